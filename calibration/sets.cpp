#include "sets.hpp"

#include <algorithm>
#include <tuple>

namespace calibration {

pipeline::Variant variant_of(const Calibration& c, const ParameterSet& s) {
  pipeline::Variant v;
  v.name = s.name;
  // A run the engine stops with a message (a guard, a refused value) is an outcome of the set: its
  // stop is recorded and not run again in every iteration; the set is scored without that sample.
  v.may_fail = true;
  // A scene its values make that the engine refuses is named by the calibration file, the set and
  // its parameters' values (not as a variant of the study, which has none).
  v.origin = c.file + ": set " + s.name + " (";
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    v.origin += (j ? ", " : "") + c.parameters[j].name + " = " + c.parameters[j].value_text(s.u(static_cast<Eigen::Index>(j)));
  v.origin += ")";
  for (std::size_t j = 0; j < c.parameters.size(); ++j) {
    const Parameter& p = c.parameters[j];
    const auto overrides = p.overrides(s.u(static_cast<Eigen::Index>(j)));
    if (!p.densities.empty()) {  // some densities' tests only
      for (const std::string& density : p.densities) {
        auto into = std::find_if(v.per_density.begin(), v.per_density.end(), [&](const auto& e) { return e.first == density; });
        if (into == v.per_density.end()) into = v.per_density.insert(v.per_density.end(), {density, {}});
        into->second.insert(into->second.end(), overrides.begin(), overrides.end());
      }
      continue;
    }
    pipeline::Overrides& into = p.applies_to == "test" ? v.test : p.applies_to == "prepare" ? v.prepare : v.set;
    into.insert(into.end(), overrides.begin(), overrides.end());
  }
  return v;
}

std::map<std::string, std::vector<validation::Sample>> samples_of_sets(const std::vector<pipeline::PlannedRun>& runs) {
  using Key = std::tuple<std::string, std::int64_t, std::string>;  // variant, seed, density
  std::map<Key, std::string> preparation;
  for (const pipeline::PlannedRun& r : runs)
    if (r.test.empty())
      for (const std::string& v : r.variants) preparation[{v, r.seed.value_or(0), r.density}] = r.result;
  std::map<std::string, std::map<std::int64_t, validation::Sample>> by_set;
  for (const pipeline::PlannedRun& r : runs) {
    if (r.test.empty()) continue;
    for (const std::string& v : r.variants) {
      validation::Sample& s = by_set[v][r.seed.value_or(0)];
      s.name = r.seed ? "seed" + std::to_string(*r.seed) : "";
      validation::DensityResults& d = s.densities[r.density];
      if (!d.prepared) {
        const auto p = preparation.find({v, r.seed.value_or(0), r.density});
        try {
          if (p != preparation.end()) validation::load_preparation(p->second, d);
        } catch (const std::exception&) {
          d.missing_runs.push_back("prepare");
        }
      }
      try {
        d.tests.push_back(validation::load_test(r.result, r.test));
      } catch (const std::exception&) {
        d.missing_runs.push_back(r.test);
      }
    }
  }
  std::map<std::string, std::vector<validation::Sample>> out;
  for (auto& [v, seeds] : by_set)
    for (auto& [seed, sample] : seeds) out[v].push_back(std::move(sample));
  return out;
}

}  // namespace calibration
