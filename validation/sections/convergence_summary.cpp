#include "sections/convergence_summary.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/hdf5.hpp"
#include "sections/variants.hpp"
#include "study/json_file.hpp"
#include "study/manifest.hpp"
#include "study/baseline.hpp"
#include "study/paths.hpp"
#include "study/results.hpp"
#include "study/stamp.hpp"
#include "study/utc_day.hpp"

namespace validation {
namespace {

using json = nlohmann::ordered_json;

std::string string_attribute(const std::string& file, const std::string& name) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(file);
    return dem::h5::has_attribute(f, name) ? dem::h5::get_string_attribute(f, name) : "";
  } catch (const std::exception&) {
    return "";
  }
}

// A number as JSON, to 10 significant digits (null when not finite).
json number(double x) {
  if (!std::isfinite(x)) return nullptr;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return std::stod(buf);
}

// "E" for one engine, "E1 (n1 runs), E2 (n2 runs)" for several.
std::string engines_of(const std::vector<ConvergenceRun>& runs) {
  std::map<std::string, int> count;
  for (const ConvergenceRun& r : runs)
    if (!r.engine.empty()) ++count[r.engine];
  std::string s;
  for (const auto& [e, n] : count) s += (s.empty() ? "" : ", ") + e + (count.size() > 1 ? " (" + std::to_string(n) + " runs)" : "");
  return s;
}

// The reference's size (its first complete run's spheres) and samples (its complete runs' seeds),
// for the report's stamp: the settings are the study's first variant's.
void set_size(ConvergenceSummary& s) {
  if (s.runs.empty()) return;
  const std::string reference = s.runs.front().variant;
  std::set<int> seeds;
  s.spheres = 0;
  for (const ConvergenceRun& r : s.runs)
    if (r.variant == reference && r.status.empty()) {
      if (s.spheres == 0) s.spheres = r.spheres;
      seeds.insert(r.seed);
    }
  s.samples = static_cast<long>(seeds.size());
}

}  // namespace

ConvergenceSummary summarise_convergence(const sections::Manifest& manifest, const std::string& results, int threads) {
  ConvergenceSummary s;
  s.results = shown_path(results);
  s.date = utc_day();
  s.threads = threads;
  // The runs by (variant, density, seed): the preparation and the test of each.
  for (const std::string& variant : manifest.variants) {
    std::map<std::pair<std::string, std::string>, std::vector<ManifestLine>> by_sample;
    for (const ManifestLine& l : manifest.by_variant.at(variant)) by_sample[{l.density, l.seed}].push_back(l);
    for (const auto& [key, lines] : by_sample) {
      ConvergenceRun r;
      r.variant = variant;
      r.density = key.first;
      r.seed = key.second == "-" ? 1 : std::stoi(key.second);
      std::map<std::string, double> sample;
      std::vector<std::pair<std::string, TestResult>> tests;
      double wall = 0;
      for (const ManifestLine& l : lines) {
        const std::string file = result_under(results, l);
        if (!is_complete(file)) {
          validation::CaseRun stop;
          sections::read_stop(file, stop);
          if (r.status.empty()) r.status = l.run + (stop.exit_code ? ": " + stop.message : " not complete");
          continue;
        }
        const double w = sections::wall_time(file);
        wall += w;
        if (l.test == "-") r.preparation_core_s = w * threads;
        r.engine = string_attribute(file, "software_version");
        const sections::RunFile run = sections::read_run(file);
        if (l.test == "-") {
          DensityResults d;
          load_preparation(file, d);
          sample = d.sample;
          if (run.scene) r.preparation_time_step_s = run.scene->time_step_s;
          if (variant == manifest.variants.front() && s.baseline.empty()) s.baseline = baseline_of_result(file);
        } else {
          tests.push_back({l.test, load_test(file, l.test)});
          if (run.scene) {
            r.time_step_s = run.scene->time_step_s;
            if (!run.scene->stages.empty()) r.rate_Pa_s = run.scene->stages.front().stress_rate_Pa_per_s;
          }
        }
      }
      if (sample.count("particles")) r.spheres = std::lround(sample.at("particles"));
      r.core_s = wall * threads;
      if (r.status.empty()) r.quantities = convergence_quantities(sample, tests);
      s.runs.push_back(r);
    }
  }
  s.engine = engines_of(s.runs);
  const Stamp checked = stamp_of_results(results);
  s.engine_source = checked.engine_source, s.other_engine_results = checked.other_engine_results;
  set_size(s);
  return s;
}

ConvergenceSummary merge_summaries(ConvergenceSummary now, const ConvergenceSummary& before) {
  const auto key = [](const ConvergenceRun& r) { return r.variant + "/" + r.density + "/" + std::to_string(r.seed); };
  std::map<std::string, std::size_t> at;
  for (std::size_t k = 0; k < now.runs.size(); ++k) at[key(now.runs[k])] = k;
  for (const ConvergenceRun& r : before.runs) {
    if (!r.status.empty()) continue;
    const auto it = at.find(key(r));
    if (it == at.end()) now.runs.push_back(r);
    else if (!now.runs[it->second].status.empty()) now.runs[it->second] = r;
    else continue;
    // A run kept from `before` was checked against before's engine, if at all.
    if (before.engine_source != now.engine_source) now.engine_source.clear();
  }
  now.engine = engines_of(now.runs);
  if (now.baseline.empty()) now.baseline = before.baseline;
  set_size(now);
  return now;
}

std::string summary_json(const ConvergenceSummary& s) {
  json j;
  j["schema"] = s.schema;
  j["what"] = "the convergence study's runs: settings, cost (core-seconds: preparation + test) and headline quantities";
  j["results"] = s.results;
  j["engine"] = s.engine;
  j["engine_source"] = s.engine_source.empty() ? not_recorded : s.engine_source;
  if (s.other_engine_results > 0) j["other_engine_results"] = s.other_engine_results;
  j["baseline"] = s.baseline;
  j["date"] = s.date;
  j["spheres"] = s.spheres;
  j["samples"] = s.samples;
  j["threads_per_run"] = s.threads;
  json runs = json::array();
  for (const ConvergenceRun& r : s.runs) {
    json q = json::object();
    for (const auto& [name, v] : r.quantities) q[name] = number(v);
    runs.push_back({{"variant", r.variant}, {"density", r.density}, {"seed", r.seed}, {"time_step_s", number(r.time_step_s)},
                    {"preparation_time_step_s", number(r.preparation_time_step_s)}, {"rate_Pa_s", number(r.rate_Pa_s)}, {"spheres", r.spheres}, {"core_s", number(r.core_s)}, {"preparation_core_s", number(r.preparation_core_s)},
                    {"status", r.status}, {"engine", r.engine}, {"quantities", q}});
  }
  j["runs"] = runs;
  return j.dump(1) + "\n";
}

ConvergenceSummary read_convergence_summary(const std::string& file) {
  const nlohmann::json j = read_json_file(file);
  const auto need = [&](const nlohmann::json& node, const char* key, const std::string& where) -> const nlohmann::json& {
    if (!node.is_object() || !node.contains(key))
      throw std::runtime_error(file + ": not a convergence summary (" + where + " has no '" + key + "')");
    return node.at(key);
  };
  ConvergenceSummary s;
  try {
    s.schema = need(j, "schema", "the file").get<int>();
    if (s.schema != 1 && s.schema != 2)
      throw std::runtime_error(file + ": convergence summary schema " + std::to_string(s.schema) + ", this tool reads 1 and 2");
    const int read_schema = s.schema;
    s.schema = ConvergenceSummary{}.schema;  // written back in this tool's schema
    s.results = need(j, "results", "the file").get<std::string>();
    s.engine = need(j, "engine", "the file").get<std::string>();
    s.baseline = need(j, "baseline", "the file").get<std::string>();
    s.engine_source = j.value("engine_source", std::string());  // summaries from before it was recorded: not checked
    if (s.engine_source == not_recorded) s.engine_source.clear();
    s.other_engine_results = j.value("other_engine_results", 0L);
    s.date = need(j, "date", "the file").get<std::string>();
    s.spheres = j.value("spheres", 0L);  // the reference's size (the report's stamp)
    s.samples = j.value("samples", 0L);
    s.threads = need(j, "threads_per_run", "the file").get<int>();
    std::size_t k = 0;
    for (const nlohmann::json& e : need(j, "runs", "the file")) {
      const std::string where = "runs[" + std::to_string(k++) + "]";
      ConvergenceRun r;
      r.variant = need(e, "variant", where).get<std::string>();
      r.density = need(e, "density", where).get<std::string>();
      r.seed = need(e, "seed", where).get<int>();
      r.time_step_s = need(e, "time_step_s", where).get<double>();
      // Schema 1's variants set one time step for the preparation and the test.
      r.preparation_time_step_s = read_schema == 1 ? r.time_step_s : need(e, "preparation_time_step_s", where).get<double>();
      r.rate_Pa_s = need(e, "rate_Pa_s", where).get<double>();
      r.spheres = need(e, "spheres", where).get<long>();
      r.core_s = need(e, "core_s", where).get<double>();
      if (e.contains("preparation_core_s") && !e.at("preparation_core_s").is_null())  // absent or null: not recorded
        r.preparation_core_s = e.at("preparation_core_s").get<double>();
      r.status = need(e, "status", where).get<std::string>();
      r.engine = need(e, "engine", where).get<std::string>();
      for (const auto& [name, v] : need(e, "quantities", where).items())
        r.quantities[name] = v.is_null() ? std::nan("") : v.get<double>();
      s.runs.push_back(r);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file + ": not a convergence summary (" + e.what() + ")");
  }
  return s;
}

}  // namespace validation
