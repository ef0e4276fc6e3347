#include "compare_runs/study_folder.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "io/hdf5.hpp"

namespace fs = std::filesystem;

namespace compare_runs {

Manifest read_manifest(const std::string& dir) {
  const fs::path file = fs::path(dir) / "runs.tsv";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": no manifest (run the study with build/bin/pipeline first)");
  Manifest m;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, '\t')) f.push_back(field);
    if (f.size() < 8) throw std::runtime_error(file.string() + ": a line with " + std::to_string(f.size()) + " fields, 8 expected");
    m.lines.push_back({f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[6] == "1", f.size() > 8 ? f[8] : "-"});
  }
  for (const ManifestLine& l : m.lines) {
    if (!m.by_variant.count(l.variant)) m.variants.push_back(l.variant);
    m.by_variant[l.variant].push_back(l);
  }
  return m;
}

double wall_time(const std::string& result) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    return dem::h5::has_attribute(f, "wall_time_s") ? dem::h5::get_double_attribute(f, "wall_time_s") : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

void read_stop(const std::string& result, validation::CaseRun& run) {
  try {
    const YAML::Node n = YAML::LoadFile(result + ".outcome");
    run.exit_code = n["exit_code"].as<int>();
    run.message = n["message"].as<std::string>();
  } catch (const std::exception&) {
  }
}

RunFile read_run(const std::string& result) {
  RunFile f;
  f.series = validation::read_columns(result, "timeseries");
  dem::h5::Handle h = dem::h5::open_file_read(result);
  if (dem::h5::has_text(h, "scene_yaml")) {  // a dataset (schema 3) or an attribute (before)
    f.scene = dem::scene_from_text(dem::h5::read_text(h, "scene_yaml"), result);
    for (const dem::StageConfig& st : f.scene->stages)
      if (dem::h5::has_attribute(h, "stage_end_" + st.name)) f.stage_end[st.name] = dem::h5::get_string_attribute(h, "stage_end_" + st.name);
  }
  return f;
}

std::string relative_paths(std::string s, const std::string& results) {
  std::vector<std::string> roots = {fs::current_path().string() + "/"};
  std::error_code ec;  // the real folder: a results/ that is a link to another checkout's names that one
  const std::string abs = fs::weakly_canonical(fs::absolute(results), ec).string();
  if (const auto at = abs.rfind("/results/"); !results.empty() && at != std::string::npos) roots.push_back(abs.substr(0, at + 1));
  for (const std::string& root : roots)
    for (std::size_t at; (at = s.find(root)) != std::string::npos;) s.erase(at, root.size());
  return s;
}

}  // namespace compare_runs
