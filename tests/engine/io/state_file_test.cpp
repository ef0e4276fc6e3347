// Loading a saved state (engine/io/state_io.hpp): read_state "reads the /state group of a
// *complete* result file; throws naming the file otherwise". A good result is written once per
// test case, then copies of it are damaged in one way each and must be refused with a message
// that names the file and what is wrong.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <type_traits>
#include <utility>
#include <limits>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "io/state_io.hpp"
#include "run/run_scene.hpp"

using namespace dem;
namespace fs = std::filesystem;

namespace {

constexpr double a_nan = std::numeric_limits<double>::quiet_NaN();

// 64 spheres of 4 ... 4.5 mm, 4.5 mm apart, compressed by 4 %: many contacts with springs.
std::string scene_text(const std::string& particles, const std::string& material) {
  return "name: state\n" + particles + "material: " + material +
         "\n"
         "numerics: {time_step: 2.0e-6}\n"
         "stages:\n"
         "  - {name: compress, type: strain_rate, strain_rate: [20, 20, 20], duration: 2.0e-3}\n";
}
const std::string lattice =
    "particles:\n"
    "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
    "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n";
const std::string frictional = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}";
const std::string frictionless = "{kn: 1.0e6, ks: 1.0e6, friction: 0}";

// Writes a complete result of the compression into `dir`/good.h5 and returns its path.
std::string good_result(const std::string& dir, const std::string& material = frictional) {
  const std::string out = dir + "/good.h5";
  run_scene(scene_from_text(scene_text(lattice, material), dir + "/good.yaml"), out);
  return out;
}

// A copy of `good` named `name`, changed by `edit` (given the open file).
std::string damaged_copy(const std::string& good, const std::string& name, const std::function<void(hid_t)>& edit) {
  const std::string file = fs::path(good).parent_path().string() + "/" + name + ".h5";
  fs::copy_file(good, file, fs::copy_options::overwrite_existing);
  h5::Handle f = h5::open_file_write(file);
  edit(f);
  return file;
}

// Changes values of an existing dataset in place (same shape).
template <class T>
void edit_values(hid_t file, const std::string& path, const std::function<void(std::vector<T>&)>& change) {
  std::size_t cols = 0;
  const auto slash = path.rfind('/');
  h5::Handle g = h5::open_group(file, path.substr(0, slash));
  std::vector<T> v = h5::read<T>(g, path.substr(slash + 1), cols);
  change(v);
  h5::Handle ds(H5Dopen2(g, path.substr(slash + 1).c_str(), H5P_DEFAULT));
  const hid_t type = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_UINT32;
  REQUIRE(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
}

// Replaces a dataset of /state by a new one with other contents or shape.
void replace_dataset(hid_t file, const std::string& name, const std::vector<double>& data, std::size_t cols) {
  h5::Handle g = h5::open_group(file, "state");
  REQUIRE(H5Ldelete(g, name.c_str(), H5P_DEFAULT) >= 0);
  h5::write(g, name, data, cols, "m");
}

}  // namespace

TEST_CASE("a saved state loads into a new simulation exactly, with its step count reset", "[io][state]") {
  const std::string dir = test::scratch_dir("state_load");
  const std::string good = good_result(dir);
  const SavedState st = read_state(good);
  REQUIRE(st.particles.size() == 64);
  REQUIRE(st.contacts.size() > 0);
  CHECK(st.history.tangential.size() == st.contacts.size());  // frictional: history saved
  CHECK(st.step == 1000);
  CHECK(st.time_step_s == 2e-6);
  // The scene's state path is relative to the scene file (resolved against its folder).
  const Simulation sim = build_simulation(scene_from_text(scene_text("particles: {state: good.h5}\n", frictional), dir + "/next.yaml"));
  CHECK(sim.step_count() == 0);
  CHECK(sim.particles().s == st.particles.s);
  CHECK(sim.particles().v == st.particles.v);
  CHECK(sim.particles().omega == st.particles.omega);
  CHECK(sim.particles().mass == st.particles.mass);
  CHECK(sim.cell().lengths() == st.cell.lengths());
  CHECK(sim.cell().reference_lengths() == st.cell.reference_lengths());
  CHECK(sim.strain_rate() == st.rates.axial);
  CHECK(sim.pairs().first == st.contacts.first);
  CHECK(sim.history().tangential == st.history.tangential);
  CHECK(sim.history().sliding == st.history.sliding);
}

TEST_CASE("a frictionless state can start a frictional scene and vice versa", "[io][state]") {
  // The contact law is the new scene's: a frictional scene starting from a frictionless sample
  // gets zero springs on the existing contacts; a frictionless scene drops the saved springs.
  SECTION("frictionless sample, frictional scene") {
    const std::string dir = test::scratch_dir("state_cross_a");
    const SavedState st = read_state(good_result(dir, frictionless));
    REQUIRE(st.contacts.size() > 0);
    CHECK(st.history.tangential.empty());
    const Simulation sim = build_simulation(scene_from_text(scene_text("particles: {state: good.h5}\n", frictional), dir + "/n.yaml"));
    CHECK(sim.pairs().size() == st.contacts.size());
    REQUIRE(sim.history().tangential.size() == st.contacts.size());
    for (const Vec3& u : sim.history().tangential) CHECK(u == Vec3::Zero());
  }
  SECTION("frictional sample, frictionless scene") {
    const std::string dir = test::scratch_dir("state_cross_b");
    const SavedState st = read_state(good_result(dir, frictional));
    REQUIRE(!st.history.tangential.empty());
    const Simulation sim = build_simulation(scene_from_text(scene_text("particles: {state: good.h5}\n", frictionless), dir + "/n.yaml"));
    CHECK(sim.pairs().size() == st.contacts.size());
    CHECK(sim.history().tangential.empty());
    CHECK(sim.history().sliding.empty());
  }
}

TEST_CASE("damaged or unfinished state files are refused naming the file", "[io][state]") {
  const std::string dir = test::scratch_dir("state_damaged");
  const std::string good = good_result(dir);
  const SavedState st = read_state(good);
  const std::size_t n = st.particles.size(), nc = st.contacts.size();
  REQUIRE(nc >= 2);

  struct Case {
    std::string file, expected;  // expected: message after "<file>: "
  };
  const std::vector<Case> cases = {
      // Only a run that finished has a trustworthy final state.
      {damaged_copy(good, "running", [](hid_t f) { h5::set_attribute(f, "status", std::string("running")); }),
       "not a complete result (status 'running'); only a finished run's state can be loaded"},
      {damaged_copy(good, "no_status", [](hid_t f) { REQUIRE(H5Adelete(f, "status") >= 0); }),
       "not a complete result (status 'missing')"},
      // Each particle needs positive radius, mass and inertia and finite position and velocity.
      {damaged_copy(good, "negative_radius", [](hid_t f) { edit_values<double>(f, "state/radius", [](auto& v) { v[3] = -1e-3; }); }),
       "/state particle 3 has a non-finite or non-positive value"},
      {damaged_copy(good, "zero_mass", [](hid_t f) { edit_values<double>(f, "state/mass", [](auto& v) { v[7] = 0; }); }),
       "/state particle 7 has a non-finite or non-positive value"},
      {damaged_copy(good, "nan_velocity", [](hid_t f) { edit_values<double>(f, "state/velocity", [](auto& v) { v[5 * 3 + 1] = a_nan; }); }),
       "/state particle 5 has a non-finite or non-positive value"},
      // Fractional positions must lie in [0, 1) (core/particles.hpp); an infinite one does not.
      {damaged_copy(good, "inf_position",
                    [](hid_t f) { edit_values<double>(f, "state/position_fractional", [](auto& v) { v[2] = HUGE_VAL; }); }),
       "/state/position_fractional of particle 0 is outside [0, 1)"},
      {damaged_copy(good, "nan_position",
                    [](hid_t f) { edit_values<double>(f, "state/position_fractional", [](auto& v) { v[3 * 9] = a_nan; }); }),
       "/state/position_fractional of particle 9 is outside [0, 1)"},
      // Shapes: N x 3 vectors, N scalars per particle, 3 cell values.
      {damaged_copy(good, "velocity_2_columns", [n](hid_t f) { replace_dataset(f, "velocity", std::vector<double>(2 * n, 0.0), 2); }),
       "/state/velocity must have 3 columns, has 2"},
      {damaged_copy(good, "short_mass", [n](hid_t f) { replace_dataset(f, "mass", std::vector<double>(n - 1, 1e-4), 1); }),
       "/state particle datasets have different lengths"},
      {damaged_copy(good, "cell_2_values", [](hid_t f) { replace_dataset(f, "cell_lengths", {0.02, 0.02}, 1); }),
       "/state cell datasets must have 3 values"},
      // Contacts: pairs (i < j < N), sorted, as the Verlet list needs them.
      {damaged_copy(good, "contact_i_equals_j",
                    [](hid_t f) {
                      std::size_t c = 0;
                      const auto second = h5::read<std::uint32_t>(h5::open_group(f, "state"), "contact_second", c);
                      edit_values<std::uint32_t>(f, "state/contact_first", [&](auto& v) { v[0] = second[0]; });
                    }),
       "/state contact 0 names invalid particles"},
      {damaged_copy(good, "contact_out_of_range",
                    [n, nc](hid_t f) {
                      edit_values<std::uint32_t>(f, "state/contact_second", [&](auto& v) { v[nc - 1] = static_cast<std::uint32_t>(n); });
                    }),
       "/state contact " + std::to_string(nc - 1) + " names invalid particles"},
      {damaged_copy(good, "contacts_unsorted",
                    [](hid_t f) {
                      edit_values<std::uint32_t>(f, "state/contact_first", [](auto& v) { std::swap(v[0], v[1]); });
                      edit_values<std::uint32_t>(f, "state/contact_second", [](auto& v) { std::swap(v[0], v[1]); });
                    }),
       "/state contact 1 names invalid particles"},
  };
  for (const Case& c : cases) {
    INFO(c.file);
    CHECK_THROWS_WITH(read_state(c.file), Catch::Matchers::StartsWith(c.file + ": " + c.expected));
    // The same through a scene: a ConfigError (bad input) naming the scene file and key, then
    // the reader's message unchanged.
    const SceneConfig scene = scene_from_text(scene_text("particles: {state: " + c.file + "}\n", frictional), dir + "/s.yaml");
    CHECK_THROWS_MATCHES(build_simulation(scene), ConfigError,
                         Catch::Matchers::Predicate<std::exception>(
                             [&](const std::exception& e) {
                               return std::string(e.what()).rfind(dir + "/s.yaml: particles.state: " + c.file + ": " + c.expected, 0) == 0;
                             },
                             "starts with the scene file, particles.state, then " + c.file + ": " + c.expected));
  }
  // A scene naming a state file that does not exist, or a file that is not HDF5.
  CHECK_THROWS_WITH(read_state(dir + "/none.h5"), dir + "/none.h5: no such file");
  test::write_text(dir + "/text.h5", "this is not an HDF5 file\n");
  CHECK_THROWS_WITH(read_state(dir + "/text.h5"), Catch::Matchers::StartsWith(dir + "/text.h5: not a readable HDF5 file"));
}

TEST_CASE("a complete result without /state is refused naming the file", "[io][state]") {
  // read_state promises to throw "naming the file"; a missing group or dataset (h5::Error from
  // the HDF5 layer) is prefixed with it.
  const std::string dir = test::scratch_dir("state_no_group");
  const std::string good = good_result(dir);
  const std::string file = damaged_copy(good, "no_state", [](hid_t f) { REQUIRE(H5Ldelete(f, "state", H5P_DEFAULT) >= 0); });
  CHECK_THROWS_WITH(read_state(file), Catch::Matchers::StartsWith(file + ": ") && Catch::Matchers::Contains("'state'"));
  const std::string no_mass = damaged_copy(good, "no_mass", [](hid_t f) {
    h5::Handle g = h5::open_group(f, "state");
    REQUIRE(H5Ldelete(g, "mass", H5P_DEFAULT) >= 0);
  });
  CHECK_THROWS_WITH(read_state(no_mass), Catch::Matchers::StartsWith(no_mass + ": ") && Catch::Matchers::Contains("mass"));
}

TEST_CASE("a non-finite spin in a saved state is refused", "[io][state]") {
  // A NaN spin would otherwise surface only later, as a non-finite stress in the first step.
  // angular_velocity is N x 3: value 4 is particle 1, component y.
  const std::string dir = test::scratch_dir("state_nan_spin");
  const std::string good = good_result(dir);
  const std::string nan_spin = damaged_copy(good, "nan_spin", [](hid_t f) {
    edit_values<double>(f, "state/angular_velocity", [](auto& v) { v[4] = a_nan; });
  });
  CHECK_THROWS_WITH(read_state(nan_spin), nan_spin + ": /state particle 1 has a non-finite or non-positive value");
  const std::string inf_spin = damaged_copy(good, "inf_spin", [](hid_t f) {
    edit_values<double>(f, "state/angular_velocity", [](auto& v) { v[3 * 20 + 2] = -HUGE_VAL; });
  });
  CHECK_THROWS_WITH(read_state(inf_spin), inf_spin + ": /state particle 20 has a non-finite or non-positive value");
}

TEST_CASE("non-positive or non-finite cell lengths and non-finite strain rates in a saved state are refused", "[io][state]") {
  // A cell of length 0 or NaN cannot hold particles; a strain rate of NaN would poison the first step.
  const std::string dir = test::scratch_dir("state_bad_cell");
  const std::string good = good_result(dir);
  const std::string expected = ": /state cell lengths must be positive and finite, strain rates finite";
  const std::vector<std::string> bad = {
      damaged_copy(good, "zero_cell", [](hid_t f) { edit_values<double>(f, "state/cell_lengths", [](auto& v) { v[1] = 0; }); }),
      damaged_copy(good, "negative_cell", [](hid_t f) { edit_values<double>(f, "state/cell_lengths", [](auto& v) { v[2] = -0.018; }); }),
      damaged_copy(good, "inf_cell", [](hid_t f) { edit_values<double>(f, "state/cell_lengths", [](auto& v) { v[0] = HUGE_VAL; }); }),
      damaged_copy(good, "nan_reference", [](hid_t f) { edit_values<double>(f, "state/cell_reference_lengths", [](auto& v) { v[0] = a_nan; }); }),
      damaged_copy(good, "zero_reference", [](hid_t f) { edit_values<double>(f, "state/cell_reference_lengths", [](auto& v) { v[2] = 0; }); }),
      damaged_copy(good, "nan_rate", [](hid_t f) { edit_values<double>(f, "state/cell_strain_rate", [](auto& v) { v[1] = a_nan; }); }),
      damaged_copy(good, "inf_rate", [](hid_t f) { edit_values<double>(f, "state/cell_strain_rate", [](auto& v) { v[0] = HUGE_VAL; }); }),
  };
  for (const std::string& file : bad) {
    INFO(file);
    CHECK_THROWS_WITH(read_state(file), file + expected);
  }
  // Control: a negative strain rate (extension) is a valid state.
  const std::string extension =
      damaged_copy(good, "negative_rate", [](hid_t f) { edit_values<double>(f, "state/cell_strain_rate", [](auto& v) { v[0] = -5; }); });
  CHECK(read_state(extension).rates.axial[0] == -5);
}

TEST_CASE("a saved fractional position outside the unit interval is refused", "[io][state]") {
  // Particles must hold s in [0, 1) (core/particles.hpp); the minimum image and the binning rely
  // on it. 1.0 itself is outside (the interval is half-open), 0 is inside.
  const std::string dir = test::scratch_dir("state_outside");
  const std::string good = good_result(dir);
  const auto with_s0 = [&](const std::string& name, double x) {
    return damaged_copy(good, name, [x](hid_t f) { edit_values<double>(f, "state/position_fractional", [x](auto& v) { v[0] = x; }); });
  };
  for (const auto& [name, x] : std::vector<std::pair<std::string, double>>{{"s_1_5", 1.5}, {"s_1", 1.0}, {"s_minus", -1e-17}}) {
    const std::string file = with_s0(name, x);
    INFO(file);
    CHECK_THROWS_WITH(read_state(file), file + ": /state/position_fractional of particle 0 is outside [0, 1)");
  }
  const std::string zero = with_s0("s_0", 0.0);
  CHECK(read_state(zero).particles.s[0].x() == 0.0);
}
