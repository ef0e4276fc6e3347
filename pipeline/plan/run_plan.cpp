#include "plan/run_plan.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "control/stress_path.hpp"

namespace pipeline {

namespace fs = std::filesystem;

std::string content_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a 64 offset basis
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

YAML::Node load_yaml(const std::string& file) {
  try {
    return YAML::LoadFile(file);
  } catch (const YAML::Exception& e) {
    throw dem::ConfigError(file + ": not valid YAML: " + e.what());
  }
}

// Caps every repeat block of every stress-path stage at `max_repeat` repetitions.
void cap_repeats(YAML::Node scene, int max_repeat) {
  if (max_repeat <= 0 || !scene["stages"] || !scene["stages"].IsSequence()) return;
  for (YAML::Node stage : scene["stages"]) {
    if (!stage["path"] || !stage["path"].IsSequence()) continue;
    for (YAML::Node item : stage["path"])
      if (item.IsMap() && item["repeat"] && item["repeat"].as<int>() > max_repeat) item["repeat"] = max_repeat;
  }
}

std::string emit(const YAML::Node& n, const std::string& header) {
  YAML::Emitter out;
  out << n;
  return header + out.c_str() + "\n";
}

double estimated_steps(const dem::SceneConfig& scene) {
  double steps = 0;
  for (const dem::StageConfig& st : scene.stages) {
    if (st.type == dem::StageConfig::Type::StrainRate) steps += st.duration_s / scene.time_step_s;
    else if (st.type == dem::StageConfig::Type::Stress) steps += 1.0 / scene.time_step_s;  // about 1 s to hold (measured)
    else
      for (const dem::PathLeg& leg : dem::expand_path(st.path, dem::named_state("A", st.mean_stress_Pa, st.stress_ratio),
                                                      st.stress_rate_Pa_per_s))
        steps += leg.duration_s / scene.time_step_s;
  }
  return steps;
}

}  // namespace

std::vector<PlannedRun> plan_study(const Study& study, const Profile& profile, const std::string& out_dir,
                                   const std::string& engine_version) {
  std::vector<PlannedRun> runs;
  const std::string header = "# Resolved by the pipeline from " + study.file + " (profile " + profile.name +
                             "); do not edit, edit the study or its scenes.\n";
  const double particles = static_cast<double>(profile.lattice) * profile.lattice * profile.lattice;
  for (const Density& d : study.densities) {
    PlannedRun prep;
    prep.name = d.name + "_prepare";
    prep.scene_file = (fs::path(out_dir) / "scenes" / (prep.name + ".yaml")).string();
    prep.result = (fs::path(out_dir) / (prep.name + ".h5")).string();
    prep.log = (fs::path(out_dir) / "logs" / (prep.name + ".log")).string();
    YAML::Node scene = load_yaml(study.preparation);
    const std::string n = std::to_string(profile.lattice);
    dem::apply_override(scene, study.preparation, "name", prep.name);
    std::ostringstream mu;
    mu << d.friction;
    dem::apply_override(scene, study.preparation, "material.friction", mu.str());
    dem::apply_override(scene, study.preparation, "particles.lattice.n", "[" + n + ", " + n + ", " + n + "]");
    prep.scene_text = emit(scene, header);
    const dem::SceneConfig parsed = dem::scene_from_text(prep.scene_text, prep.scene_file);
    prep.hash = content_hash(engine_version + "\n" + prep.scene_text);
    prep.cost = particles * estimated_steps(parsed);
    const int prep_index = static_cast<int>(runs.size());
    runs.push_back(prep);

    for (const TestCase& t : study.tests) {
      PlannedRun run;
      run.name = d.name + "_" + t.name;
      run.scene_file = (fs::path(out_dir) / "scenes" / (run.name + ".yaml")).string();
      run.result = (fs::path(out_dir) / (run.name + ".h5")).string();
      run.log = (fs::path(out_dir) / "logs" / (run.name + ".log")).string();
      YAML::Node ts = load_yaml(t.scene);
      dem::apply_override(ts, t.scene, "name", run.name);
      dem::apply_override(ts, t.scene, "particles", "{state: " + fs::absolute(prep.result).string() + "}");
      cap_repeats(ts, profile.max_repeat);
      run.scene_text = emit(ts, header);
      const dem::SceneConfig tp = dem::scene_from_text(run.scene_text, run.scene_file);
      run.hash = content_hash(engine_version + "\n" + run.scene_text + "\nfrom " + prep.hash);
      run.depends_on = prep_index;
      run.cost = particles * estimated_steps(tp);
      runs.push_back(run);
    }
  }
  return runs;
}

void write_scenes(const std::vector<PlannedRun>& runs) {
  for (const PlannedRun& r : runs) {
    fs::create_directories(fs::path(r.scene_file).parent_path());
    fs::create_directories(fs::path(r.log).parent_path());
    std::ifstream in(r.scene_file);
    std::stringstream old;
    old << in.rdbuf();
    if (in && old.str() == r.scene_text) continue;
    std::ofstream out(r.scene_file);
    out << r.scene_text;
    if (!out) throw std::runtime_error(r.scene_file + ": cannot be written");
  }
}

}  // namespace pipeline
