#include "study/settings.hpp"

#include <algorithm>
#include <filesystem>
#include <type_traits>
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

RunSettings run_settings(const std::string& results, const std::string& prefix, const std::string& run) {
  const auto dirs = validation::sample_dirs(results);
  const std::string dir = dirs.front().second;
  RunSettings s;
  bool any = false;
  // One named run (--run NAME: DIR/NAME.h5) is read as the preparation of a study of one density.
  for (const std::string& d : run.empty() ? paper_densities() : std::vector<std::string>{"run"}) {
    const auto prep = scene_of((fs::path(dir) / (run.empty() ? prefix + d + "_prepare.h5" : run + ".h5")).string());
    if (prep) {
      s.max_energy_error = prep->max_energy_error;
      s.max_time_step_fraction = prep->max_time_step_fraction;
      any = true;
      s.friction_prepare.emplace_back(d, dem::friction_coefficient(prep->material.law));
      s.time_step_prepare_s = prep->time_step_s;
      s.grading_basis = prep->particles.grading_basis == dem::GradingCurve::Basis::Mass ? "mass" : "count";
      s.damping_form = prep->damping.form == dem::Damping::Form::Viscous ? "viscous" : "local";
      s.damping_translational = prep->damping.translational;
      s.damping_rotational = prep->damping.rotational;
      std::visit(
          [&](const auto& law) {  // the linear law's stiffnesses (other laws name their own constants)
            using Law = std::decay_t<decltype(law)>;
            if constexpr (std::is_base_of_v<dem::LinearNormal, typename Law::NormalLaw>) {  // with or without dashpots
              s.kn_N_per_m = law.normal.kn;
              if constexpr (Law::has_tangential) s.ks_N_per_m = law.tangential.ks;
            }
          },
          prep->material.law);
      if (prep->particles.kind == dem::ParticleSource::Kind::Lattice) {
        const dem::LatticeLayout& l = prep->particles.lattice;
        s.lattice = std::to_string(l.n[0]) + "×" + std::to_string(l.n[1]) + "×" + std::to_string(l.n[2]);
        s.particles = static_cast<long>(l.n[0]) * l.n[1] * l.n[2];
        s.lattice_spacing_mm = 1e3 * l.spacing_m;
      }
      if (const dem::StageConfig* st = stage_of_type(*prep, dem::StageConfig::Type::Stress)) {
        s.target_pressure_kPa = st->target_Pa.mean() / 1e3;
        s.compression_rate_Pa_per_s = st->stress_rate_Pa_per_s;
        s.max_strain_rate_per_s = st->max_strain_rate_per_s;
        s.hold_stress_tolerance = st->hold.stress_tolerance;
        s.hold_unbalanced_force_ratio = st->hold.unbalanced_force_ratio;
      }
    }
    for (int t = 1; t <= 5; ++t) {
      const auto test = scene_of((fs::path(dir) / (prefix + d + "_test" + std::to_string(t) + ".h5")).string());
      if (!test) continue;
      any = true;
      if (std::none_of(s.friction_shear.begin(), s.friction_shear.end(), [&](const auto& f) { return f.first == d; }))
        s.friction_shear.emplace_back(d, dem::friction_coefficient(test->material.law));
      s.time_step_test_s = test->time_step_s;
      if (const dem::StageConfig* st = stage_of_type(*test, dem::StageConfig::Type::StressPath)) {
        s.mean_stress_Pa = st->mean_stress_Pa;
        s.stress_ratio = st->stress_ratio;
        s.stress_rate_Pa_per_s = st->stress_rate_Pa_per_s;
        RunSettings::TestPath path{one_line(st->path_text), 0, {}};
        for (const dem::PathLeg& leg : dem::expand_path(st->path, dem::named_state("A", st->mean_stress_Pa, st->stress_ratio),
                                                        st->stress_rate_Pa_per_s))
          path.cycles += leg.ends_cycle, path.visits.push_back(leg.to_label);
        s.tests[t] = std::move(path);
      }
    }
  }
  return any ? s : RunSettings{};
}

std::map<std::string, std::string> setting_texts(const RunSettings& s) {
  std::map<std::string, std::string> kv;
  const auto put = [&](const char* key, const auto& value) {
    if (!value) return;
    if constexpr (std::is_same_v<std::decay_t<decltype(*value)>, std::string>) kv[key] = *value;
    else if constexpr (std::is_same_v<std::decay_t<decltype(*value)>, long>) kv[key] = std::to_string(*value);
    else kv[key] = num(*value);
  };
  put("grading_basis", s.grading_basis);
  put("damping_form", s.damping_form);
  put("damping_translational", s.damping_translational);
  put("damping_rotational", s.damping_rotational);
  put("kn_N_per_m", s.kn_N_per_m);
  put("ks_N_per_m", s.ks_N_per_m);
  put("lattice", s.lattice);
  put("particles", s.particles);
  put("lattice_spacing_mm", s.lattice_spacing_mm);
  put("target_pressure_kPa", s.target_pressure_kPa);
  put("compression_rate_Pa_per_s", s.compression_rate_Pa_per_s);
  put("max_strain_rate_per_s", s.max_strain_rate_per_s);
  put("hold_stress_tolerance", s.hold_stress_tolerance);
  put("hold_unbalanced_force_ratio", s.hold_unbalanced_force_ratio);
  put("max_energy_error", s.max_energy_error);
  put("max_time_step_fraction", s.max_time_step_fraction);
  put("time_step_prepare_s", s.time_step_prepare_s);
  put("time_step_test_s", s.time_step_test_s);
  put("mean_stress_Pa", s.mean_stress_Pa);
  put("stress_ratio", s.stress_ratio);
  put("stress_rate_Pa_per_s", s.stress_rate_Pa_per_s);
  const auto list = [](const std::vector<std::pair<std::string, double>>& by_density) {
    std::vector<std::string> v;
    for (const auto& [d, x] : by_density) v.push_back(num(x));
    return joined(v, " / ");
  };
  if (!s.friction_prepare.empty()) kv["friction_prepare"] = list(s.friction_prepare);
  if (!s.friction_shear.empty()) kv["friction_shear"] = list(s.friction_shear);
  for (const auto& [d, mu] : s.friction_shear) kv["friction_shear_" + d] = num(mu);
  for (const auto& [t, path] : s.tests) {
    kv["test" + std::to_string(t) + "_path"] = path.path;
    kv["test" + std::to_string(t) + "_cycles"] = std::to_string(path.cycles);
  }
  return kv;
}

}  // namespace validation
