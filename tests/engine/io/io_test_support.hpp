#pragma once
// Helpers shared by the configuration, I/O and restart tests (not a test file itself: no _test
// suffix): a scratch folder under the build tree, small file utilities, HDF5 inspection and a
// tiny scene used by several tests.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "io/hdf5.hpp"
#include "version.hpp"

namespace dem::test {

// DEM_BINARY_DIR "/test_tmp/<name>", created empty: each test case owns its own folder, so test
// cases do not see each other's files and a rerun starts clean.
inline std::string scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs a shell command; returns its exit status (-1 if it did not exit normally) and stdout.
struct CommandResult {
  int exit_code = -1;
  std::string out;
};
inline CommandResult run_command(const std::string& cmd) {
  CommandResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline bool have_program(const std::string& name) {
  return run_command("command -v " + name + " >/dev/null 2>&1").exit_code == 0;
}

// Names of the links (datasets, groups) directly in an HDF5 group, in creation-independent order.
inline std::vector<std::string> h5_members(hid_t group) {
  std::vector<std::string> names;
  H5G_info_t info;
  if (H5Gget_info(group, &info) < 0) return names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (len < 0) continue;
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(name);
  }
  return names;
}

// Marks an open file a complete result as a run does (io/result_file.hpp: status "complete", its
// wall_time_s, this build's schema_version): what a fixture that writes a result by hand needs.
inline void mark_complete(hid_t f, double wall_time_s = 1.0) {
  h5::set_attribute(f, "status", std::string("complete"));
  h5::set_attribute(f, "wall_time_s", wall_time_s);
  h5::set_attribute(f, "schema_version", static_cast<std::int64_t>(schema_version));
}

// The file's top-level `status` attribute ("" if the file cannot be read or has none).
inline std::string h5_status(const std::string& file) {
  try {
    h5::Handle f = h5::open_file_read(file);
    return h5::has_attribute(f, "status") ? h5::get_string_attribute(f, "status") : std::string();
  } catch (const std::exception&) {
    return "";
  }
}

// A tiny valid scene: 27 spheres of 3 ... 4.5 mm on a 3x3x3 lattice of spacing 5 mm (a 15 mm
// cube), the paper's material (kn = ks = 1e6 N/m, density 2650), dt = 1 us. `stages` is the YAML
// of the `stages:` list (block style, items indented by two spaces).
inline std::string tiny_scene(const std::string& stages, const std::string& material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}",
                              const std::string& extra = "") {
  return "name: tiny\n"
         "particles:\n"
         "  lattice: {n: [3, 3, 3], spacing: 5.0e-3, seed: 1}\n"
         "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
         "material: " + material + "\n"
         "numerics: {time_step: 1.0e-6}\n" + extra + "stages:\n" + stages;
}

}  // namespace dem::test
