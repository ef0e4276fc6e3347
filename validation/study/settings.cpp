#include "study/settings.hpp"

#include <filesystem>
#include <sstream>

#include "control/stress_path.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "io/hdf5.hpp"
#include "study/results.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

std::string num(double x) { return number(x); }

}  // namespace

// The resolved scene a result ran (its `scene_yaml`), if the result can be read.
std::optional<dem::SceneConfig> scene_of(const std::string& result) {
  std::error_code ec;
  if (std::filesystem::symlink_status(result, ec).type() == std::filesystem::file_type::not_found) return std::nullopt;  // not run
  std::string text;
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    if (!dem::h5::has_text(f, "scene_yaml")) return std::nullopt;  // a dataset (schema 3) or an attribute (before)
    text = dem::h5::read_text(f, "scene_yaml");
  } catch (const std::exception& e) {  // there, but lost: never left out in silence
    throw std::runtime_error(result + ": cannot be read as a result (" + e.what() + ")");
  }
  try {
    return dem::scene_from_text(text, result);
  } catch (const std::exception&) {
    return std::nullopt;  // a scene this engine no longer reads (an older result): its settings are not known
  }
}

const dem::StageConfig* stage_of_type(const dem::SceneConfig& s, dem::StageConfig::Type type) {
  for (const dem::StageConfig& st : s.stages)
    if (st.type == type) return &st;
  return nullptr;
}

std::string joined(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}


// A path as written in a scene ("- TC1\n- {repeat: 5, ...}" or a flow list) on one line: "[TC1, {repeat: 5, ...}]".
std::string one_line(const std::string& yaml) {
  std::stringstream in(yaml);
  std::vector<std::string> items;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    line = line.substr(first);
    if (line.rfind("- ", 0) == 0) items.push_back(line.substr(2));
    else if (items.empty()) items.push_back(line);
    else items.back() += " " + line;
  }
  if (items.size() == 1 && !items[0].empty() && items[0][0] == '[') return items[0];
  return "[" + joined(items, ", ") + "]";
}

std::map<std::string, std::string> run_settings(const std::string& results, const std::string& prefix, const std::string& run) {
  const auto dirs = validation::sample_dirs(results);
  const std::string dir = dirs.front().second;
  std::map<std::string, std::string> kv;
  std::map<std::string, std::vector<std::string>> per_density;
  bool any = false;
  // One named run (--run NAME: DIR/NAME.h5) is read as the preparation of a study of one density.
  for (const std::string& d : run.empty() ? paper_densities() : std::vector<std::string>{"run"}) {
    const auto prep = scene_of((fs::path(dir) / (run.empty() ? prefix + d + "_prepare.h5" : run + ".h5")).string());
    if (prep) {
      kv["max_energy_error"] = num(prep->max_energy_error);
      kv["max_time_step_fraction"] = num(prep->max_time_step_fraction);
      any = true;
      per_density["friction_prepare"].push_back(num(dem::friction_coefficient(prep->material.law)));
      kv["time_step_prepare_s"] = num(prep->time_step_s);
      kv["grading_basis"] = prep->particles.grading_basis == dem::GradingCurve::Basis::Mass ? "mass" : "count";
      kv["damping_form"] = prep->damping.form == dem::Damping::Form::Viscous ? "viscous" : "local";
      kv["damping_translational"] = num(prep->damping.translational);
      kv["damping_rotational"] = num(prep->damping.rotational);
      std::visit(
          [&](const auto& law) {  // the linear law's stiffnesses (other laws name their own constants)
            using Law = std::decay_t<decltype(law)>;
            if constexpr (std::is_base_of_v<dem::LinearNormal, typename Law::NormalLaw>) {  // with or without dashpots
              kv["kn_N_per_m"] = num(law.normal.kn);
              if constexpr (Law::has_tangential) kv["ks_N_per_m"] = num(law.tangential.ks);
            }
          },
          prep->material.law);
      if (prep->particles.kind == dem::ParticleSource::Kind::Lattice) {
        const dem::LatticeLayout& l = prep->particles.lattice;
        kv["lattice"] = std::to_string(l.n[0]) + "×" + std::to_string(l.n[1]) + "×" + std::to_string(l.n[2]);
        kv["particles"] = std::to_string(static_cast<long long>(l.n[0]) * l.n[1] * l.n[2]);
        kv["lattice_spacing_mm"] = num(1e3 * l.spacing_m);
      }
      if (const dem::StageConfig* st = stage_of_type(*prep, dem::StageConfig::Type::Stress)) {
        kv["target_pressure_kPa"] = num(st->target_Pa.mean() / 1e3);
        kv["compression_rate_Pa_per_s"] = num(st->stress_rate_Pa_per_s);
        kv["max_strain_rate_per_s"] = num(st->max_strain_rate_per_s);
        kv["hold_stress_tolerance"] = num(st->hold.stress_tolerance);
        kv["hold_unbalanced_force_ratio"] = num(st->hold.unbalanced_force_ratio);
      }
    }
    for (int t = 1; t <= 5; ++t) {
      const auto test = scene_of((fs::path(dir) / (prefix + d + "_test" + std::to_string(t) + ".h5")).string());
      if (!test) continue;
      any = true;
      if (t == 1 || !kv.count("friction_shear_" + d)) kv["friction_shear_" + d] = num(dem::friction_coefficient(test->material.law));
      kv["time_step_test_s"] = num(test->time_step_s);
      if (const dem::StageConfig* st = stage_of_type(*test, dem::StageConfig::Type::StressPath)) {
        kv["mean_stress_Pa"] = num(st->mean_stress_Pa);
        kv["stress_ratio"] = num(st->stress_ratio);
        kv["stress_rate_Pa_per_s"] = num(st->stress_rate_Pa_per_s);
        kv["test" + std::to_string(t) + "_path"] = one_line(st->path_text);
        int cycles = 0;
        for (const dem::PathLeg& leg : dem::expand_path(st->path, dem::named_state("A", st->mean_stress_Pa, st->stress_ratio),
                                                        st->stress_rate_Pa_per_s))
          cycles += leg.ends_cycle;
        kv["test" + std::to_string(t) + "_cycles"] = std::to_string(cycles);
      }
    }
  }
  if (!any) return {};
  for (const auto& [k, v] : per_density) kv[k] = joined(v, " / ");
  for (const std::string& d : paper_densities())
    if (kv.count("friction_shear_" + d)) per_density["friction_shear"].push_back(kv["friction_shear_" + d]);
  if (per_density.count("friction_shear")) kv["friction_shear"] = joined(per_density["friction_shear"], " / ");
  return kv;
}


}  // namespace validation
