#include "config/study_config.hpp"

#include <filesystem>
#include <set>

#include "config/yaml_section.hpp"

namespace pipeline {

namespace {

std::string resolve(const std::string& study_file, const std::string& p) {
  namespace fs = std::filesystem;
  const fs::path path(p);
  return (path.is_absolute() ? path : fs::absolute(fs::path(study_file).parent_path() / path)).lexically_normal().string();
}

void require_file(const dem::Section& s, const std::string& key, const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) s.fail(key, "no such file: " + path);
}

}  // namespace

const Profile& Study::profile(const std::string& wanted) const {
  std::string known;
  for (const Profile& p : profiles) {
    if (p.name == wanted) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw dem::ConfigError(file + ": profiles: no profile '" + wanted + "' (known: " + known + ")");
}

Study load_study(const std::string& file) {
  dem::Section root = dem::Section::load_file(file);
  Study st;
  st.file = file;
  st.name = root.text("name", std::nullopt, "study name");
  st.output = resolve(file, root.text("output", std::nullopt, "results folder, relative to the study file"));
  st.preparation = resolve(file, root.text("preparation", std::nullopt, "preparation scene template (SPEC section 2)"));
  require_file(root, "preparation", st.preparation);
  std::set<std::string> names;
  for (dem::Section& d : root.list("densities", "the samples: name and friction during preparation")) {
    Density den;
    den.name = d.text("name", std::nullopt, "sample name (loose, medium, dense)");
    den.friction = d.number("friction", "", {0, 10}, std::nullopt, "mu during isotropic compression");
    d.finish();
    if (!names.insert(den.name).second) d.fail("name", "duplicate name '" + den.name + "'");
    st.densities.push_back(den);
  }
  for (dem::Section& t : root.list("tests", "the cyclic tests: name and scene file")) {
    TestCase tc;
    tc.name = t.text("name", std::nullopt, "test name");
    tc.scene = resolve(file, t.text("scene", std::nullopt, "scene file of the test, relative to the study file"));
    require_file(t, "scene", tc.scene);
    t.finish();
    if (!names.insert(tc.name).second) t.fail("name", "duplicate name '" + tc.name + "'");
    st.tests.push_back(tc);
  }
  dem::Section profiles = root.child("profiles", "named sizes of the study (paper, quick)");
  for (const char* name : {"paper", "quick"}) {
    if (!profiles.has(name)) profiles.fail(name, "missing (every study defines the paper and quick profiles)");
    dem::Section p = profiles.child(name, "a profile");
    Profile pr;
    pr.name = name;
    pr.lattice = static_cast<int>(p.integer("lattice", 2, 100, 20, "lattice sites per axis of the preparation"));
    pr.max_repeat = static_cast<int>(p.integer("max_repeat", 0, 1000000, 0, "cap on each repeat block's cycles (0: none)"));
    p.finish();
    st.profiles.push_back(pr);
  }
  profiles.finish();
  root.finish();
  return st;
}

}  // namespace pipeline
