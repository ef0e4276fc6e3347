#include "sections/study_folder.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "io/hdf5.hpp"

namespace fs = std::filesystem;

namespace sections {

Manifest read_manifest(const std::string& dir) {
  Manifest m;
  m.lines = validation::read_manifest(dir);
  for (const ManifestLine& l : m.lines) {
    if (!m.by_variant.count(l.variant)) m.variants.push_back(l.variant);
    m.by_variant[l.variant].push_back(l);
  }
  return m;
}

bool any_outcome(const Manifest& manifest, const std::string& dir) {
  std::error_code ec;
  for (const ManifestLine& l : manifest.lines) {
    const std::string result = validation::result_under(dir, l);
    if (validation::is_complete(result) || std::filesystem::exists(result + ".outcome", ec)) return true;
  }
  return false;
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
    const YAML::Node n = dem::load_yaml(result + ".outcome");
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
  if (dem::h5::exists(h, "particles/all/radius")) {
    std::size_t cols = 0;
    f.radius_m = dem::h5::read<double>(h, "particles/all/radius", cols);
  }
  return f;
}

std::string relative_paths(std::string s, const std::string& results) {
  std::vector<std::string> roots = {fs::current_path().string() + "/"};
  std::error_code ec;  // the real folder: a results/ that is a link to another checkout's names that one
  const std::string abs = results.empty() ? "" : fs::weakly_canonical(fs::absolute(results, ec), ec).string();
  if (const auto at = abs.rfind("/results/"); !results.empty() && at != std::string::npos) roots.push_back(abs.substr(0, at + 1));
  for (const std::string& root : roots)
    for (std::size_t at; (at = s.find(root)) != std::string::npos;) s.erase(at, root.size());
  return s;
}

}  // namespace sections
