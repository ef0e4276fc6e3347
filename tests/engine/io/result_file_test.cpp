// The result file of a run (engine/io/result_writer.hpp, layout in engine/README.md): written as
// "<out>.partial", renamed to <out> with status "complete" only when the run finishes; a failed
// run keeps the .partial with status "failed: <reason>" and never touches <out>.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include "analysis/time_series.hpp"
#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "io/result_file.hpp"
#include "io/result_writer.hpp"
#include "io/state_io.hpp"
#include "run/run_scene.hpp"
#include "version.hpp"

using namespace dem;
namespace fs = std::filesystem;

namespace {

// 500 steps of slow isotropic compression (dt = 1 us).
const std::string squeeze_stage = "  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 5.0e-4}\n";

// A denser variant of the tiny scene for the complete-run test: 4 ... 4.5 mm spheres 4.5 mm apart,
// compressed by 1 % (20/s for 500 steps), so that the Verlet list holds pairs and the frictional
// contact history exists. 13.5 mm cell, > 2 x (4.5 mm + skin).
std::string dense_tiny_scene() {
  return "name: dense_tiny\n"
         "particles:\n"
         "  lattice: {n: [3, 3, 3], spacing: 4.5e-3, seed: 1}\n"
         "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
         "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
         "numerics: {time_step: 1.0e-6}\n"
         "output: {interval: 100, flush_rows: 2}\n"
         "stages:\n"
         "  - {name: squeeze, type: strain_rate, strain_rate: [20, 20, 20], duration: 5.0e-4}\n";
}

// A stress stage that cannot finish: the ramp to 100 kPa at 1 MPa/s takes 0.1 s, but the stage may
// last only 10 us (10 steps), so it throws StageError.
const std::string hopeless_stage =
    "  - {name: consolidate, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1.0e-5}}\n";

// The documented /state datasets (engine/README.md) with their units.
const std::map<std::string, std::string> state_units = {
    {"position", "m"},          {"position_fractional", "1"},    {"velocity", "m/s"},
    {"angular_velocity", "rad/s"}, {"radius", "m"},              {"mass", "kg"},
    {"moment_of_inertia", "kg m^2"}, {"cell_lengths", "m"},      {"cell_reference_lengths", "m"},
    {"cell_strain_rate", "1/s"}, {"contact_first", "1"},          {"contact_second", "1"},
    {"contact_tangential_spring", "m"}, {"contact_sliding", "1"}};

// The `unit` attribute itself (not h5::unit_of, which also reads an older file's `units`): every
// dataset a result writes names its unit as H5MD's do.
std::string units_of(hid_t group, const std::string& name) {
  h5::Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  CHECK_FALSE(h5::has_attribute(ds, "units"));
  return h5::has_attribute(ds, "unit") ? h5::get_string_attribute(ds, "unit") : "<none>";
}

}  // namespace

TEST_CASE("a complete run writes a complete, self-describing result file", "[io][result]") {
  const std::string dir = test::scratch_dir("result_complete");
  const std::string out = dir + "/tiny.h5";
  const SceneConfig scene = scene_from_text(dense_tiny_scene(), dir + "/tiny.yaml");
  const RunSummary summary = run_scene(scene, out);
  CHECK(summary.steps == 500);  // duration / dt

  // Renamed on completion: only the final name exists.
  REQUIRE(fs::exists(out));
  CHECK_FALSE(fs::exists(out + ".partial"));

  h5::Handle f = h5::open_file_read(out);
  SECTION("root attributes") {
    CHECK(h5::get_string_attribute(f, "status") == "complete");
    CHECK(h5::get_string_attribute(f, "software_version") == software_version);
    CHECK(h5::get_int_attribute(f, "schema_version") == schema_version);
    CHECK(h5::get_string_attribute(f, "scene_file") == dir + "/tiny.yaml");
    CHECK(h5::get_string_attribute(f, "damping_form") == "viscous");
    CHECK(h5::get_double_attribute(f, "wall_time_s") > 0);
    // The recorded scene is the resolved one, and it is itself a valid scene that resolves to
    // the same text (so the run can be repeated from the result file alone).
    const std::string yaml = h5::read_text(f, "scene_yaml");  // a dataset (schema 3)
    CHECK(yaml == scene.resolved_yaml);
    CHECK(scene_from_text(yaml, "again.yaml").resolved_yaml == yaml);
  }
  SECTION("time series: every documented column, with its units, one row per 100 steps") {
    h5::Handle g = h5::open_group(f, "timeseries");
    std::set<std::string> expected, present;
    for (const SeriesColumn& c : series_columns()) expected.insert(c.name);
    for (const std::string& n : test::h5_members(g)) present.insert(n);
    CHECK(present == expected);
    // Rows at steps 0 (start), 100, ..., 500 (the stage end falls on an output step: no extra row).
    const std::vector<double> want_steps = {0, 100, 200, 300, 400, 500};
    for (const SeriesColumn& c : series_columns()) {
      INFO("column " << c.name);
      CHECK(units_of(g, c.name) == c.units);
      std::size_t cols = 0;
      const auto v = h5::read<double>(g, c.name, cols);
      CHECK(cols == 1);
      CHECK(v.size() == want_steps.size());
    }
    std::size_t cols = 0;
    CHECK(h5::read<double>(g, "step", cols) == want_steps);
    const auto stage = h5::read<double>(g, "stage", cols);
    CHECK(std::all_of(stage.begin(), stage.end(), [](double s) { return s == 0; }));
    // L(t) = L0 exp(-rate t): after 500 steps of 1 us at 20/s, L = 13.5 mm x exp(-0.01).
    const auto L1 = h5::read<double>(g, "cell_length_1", cols);
    CHECK(L1.front() == Approx(13.5e-3).epsilon(1e-12));
    CHECK(L1.back() == Approx(13.5e-3 * std::exp(-0.01)).epsilon(1e-12));
    // Outside stress paths: cycle 0, leg -1, no leg or cycle ends.
    for (const char* name : {"cycle", "leg_end", "cycle_end"}) {
      INFO(name);
      const auto v = h5::read<double>(g, name, cols);
      CHECK(std::all_of(v.begin(), v.end(), [](double x) { return x == 0; }));
    }
    const auto leg = h5::read<double>(g, "leg", cols);
    CHECK(std::all_of(leg.begin(), leg.end(), [](double x) { return x == -1; }));
  }
  SECTION("legs table: every documented column, with its units, and no rows without a stress path") {
    h5::Handle g = h5::open_group(f, "legs");
    std::set<std::string> expected, present;
    for (const SeriesColumn& c : leg_columns()) expected.insert(c.name);
    for (const std::string& n : test::h5_members(g)) present.insert(n);
    CHECK(present == expected);
    for (const SeriesColumn& c : leg_columns()) {
      INFO("column " << c.name);
      CHECK(units_of(g, c.name) == c.units);
      std::size_t cols = 0;
      CHECK(h5::read<double>(g, c.name, cols).empty());
    }
  }
  SECTION("state: every documented dataset with its units and the step attributes") {
    h5::Handle g = h5::open_group(f, "state");
    std::set<std::string> expected, present;
    for (const auto& [name, units] : state_units) expected.insert(name);
    for (const std::string& n : test::h5_members(g)) present.insert(n);
    CHECK(present == expected);  // frictional scene: springs and sliding flags included
    for (const std::string& n : test::h5_members(g)) {
      INFO("dataset " << n);
      CHECK(units_of(g, n) == state_units.at(n));
    }
    CHECK(h5::get_int_attribute(g, "step") == 500);
    CHECK(h5::get_double_attribute(g, "time_step") == 1e-6);
    CHECK(h5::get_double_attribute(g, "time") == Approx(5e-4));
    std::size_t cols = 0;
    CHECK(h5::read<double>(g, "position", cols).size() == 27 * 3);
    CHECK(cols == 3);
    CHECK(h5::read<double>(g, "radius", cols).size() == 27);
    CHECK(h5::read<double>(g, "cell_lengths", cols).size() == 3);
  }
}

TEST_CASE("a frictionless run's state has no tangential springs", "[io][result]") {
  // friction 0 runs the frictionless kernel, which keeps no contact history (engine/README.md:
  // springs and sliding flags are written for frictional runs only).
  const std::string dir = test::scratch_dir("result_frictionless");
  const SceneConfig scene = scene_from_text(test::tiny_scene(squeeze_stage, "{kn: 1.0e6, ks: 0, friction: 0}"), dir + "/s.yaml");
  run_scene(scene, dir + "/r.h5");
  h5::Handle f = h5::open_file_read(dir + "/r.h5");
  h5::Handle g = h5::open_group(f, "state");
  CHECK(h5::exists(g, "contact_first"));
  CHECK_FALSE(h5::exists(g, "contact_tangential_spring"));
  CHECK_FALSE(h5::exists(g, "contact_sliding"));
}

TEST_CASE("a frictional run without any neighbour pair still writes its (empty) contact history", "[io][result]") {
  // engine/README.md: contact_tangential_spring and contact_sliding are written for frictional
  // runs. write_state writes the history the law keeps (friction > 0: a tangential spring), so a frictional run
  // whose Verlet list is empty (the tiny scene: 5 mm spacing, spheres <= 4.5 mm, gaps > skin)
  // has the frictional layout with zero contacts, and loads back as such.
  const std::string dir = test::scratch_dir("result_friction_no_pairs");
  const SceneConfig scene = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml");
  REQUIRE(has_tangential(scene.material.law));
  run_scene(scene, dir + "/r.h5");
  {
    h5::Handle f = h5::open_file_read(dir + "/r.h5");
    h5::Handle g = h5::open_group(f, "state");
    CHECK(h5::exists(g, "contact_tangential_spring"));
    CHECK(h5::exists(g, "contact_sliding"));
    std::size_t cols = 0;
    CHECK(h5::read<double>(g, "contact_tangential_spring", cols).empty());
    CHECK(h5::read<std::uint32_t>(g, "contact_first", cols).empty());
  }
  const SavedState st = read_state(dir + "/r.h5");
  CHECK(st.contacts.size() == 0);
  CHECK(st.particles.size() == 27);
}

TEST_CASE("h5ls lists the time series and the state of a result file", "[io][result]") {
  // An independent reader (the HDF5 command-line tools) must see the documented layout.
  if (!test::have_program("h5ls")) {
    WARN("h5ls not installed (package hdf5-tools): skipped");
    return;
  }
  const std::string dir = test::scratch_dir("result_h5ls");
  const SceneConfig scene = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml");
  run_scene(scene, dir + "/r.h5");
  const test::CommandResult r = test::run_command("h5ls -r '" + dir + "/r.h5' 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  // h5ls -r prints one object per line: its path, padding, then its kind ("Dataset {...}").
  std::set<std::string> datasets;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string path, kind;
    words >> path >> kind;
    if (kind == "Dataset") datasets.insert(path);
  }
  CHECK(datasets.count("/timeseries/p") == 1);
  CHECK(datasets.count("/timeseries/step") == 1);
  CHECK(datasets.count("/state/position") == 1);
  CHECK(datasets.count("/state/contact_first") == 1);
}

TEST_CASE("a failed run keeps only the .partial file, marked failed, and leaves the result path alone", "[io][result]") {
  const std::string dir = test::scratch_dir("result_failed");
  const std::string out = dir + "/r.h5";
  const SceneConfig bad = scene_from_text(test::tiny_scene(hopeless_stage), dir + "/bad.yaml");

  SECTION("no earlier result") {
    CHECK_THROWS_AS(run_scene(bad, out), StageError);
    CHECK_FALSE(fs::exists(out));  // a failed run never gets the final name
    REQUIRE(fs::exists(out + ".partial"));
    const std::string status = test::h5_status(out + ".partial");
    CHECK_THAT(status, Catch::Matchers::StartsWith("failed: stage 'consolidate' did not reach equilibrium within "
                                                   "hold.max_duration = 1e-05 s"));
    {
      // The rows measured before the failure are kept (the initial row at least) ...
      h5::Handle f = h5::open_file_read(out + ".partial");
      std::size_t cols = 0;
      CHECK(h5::read<double>(h5::open_group(f, "timeseries"), "step", cols).size() >= 1);
      // ... but there is no final state, and a failed result cannot be used as a starting state.
      CHECK_FALSE(h5::exists(f, "state"));
    }  // closed: the run below recreates this file
    CHECK_THROWS_WITH(read_state(out + ".partial"),
                      Catch::Matchers::StartsWith(out + ".partial: not a complete result (status 'failed: stage 'consolidate'"));

    // A later successful run to the same path replaces the stale .partial.
    const SceneConfig good = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/good.yaml");
    run_scene(good, out);
    CHECK(test::h5_status(out) == "complete");
    CHECK_FALSE(fs::exists(out + ".partial"));
  }
  SECTION("an existing complete result at the out path is left untouched") {
    // Write something at the out path first (any bytes will do: the run must not open it).
    const std::string earlier = "an earlier, complete result\n";
    test::write_text(out, earlier);
    CHECK_THROWS_AS(run_scene(bad, out), StageError);
    CHECK(test::read_bytes(out) == earlier);
    CHECK_THAT(test::h5_status(out + ".partial"), Catch::Matchers::StartsWith("failed: "));
  }
}

TEST_CASE("input errors are raised before any output file exists", "[io][result]") {
  // run_scene builds the simulation (all input checks) before it creates the .partial file, so a
  // bad scene leaves nothing behind that could be mistaken for a run.
  const std::string dir = test::scratch_dir("result_input_error");
  std::string text = test::tiny_scene(squeeze_stage);
  text.replace(text.find("time_step: 1.0e-6"), 17, "time_step: 1.0e-4");  // 40 x the allowed step
  const SceneConfig too_big_step = scene_from_text(text, dir + "/s.yaml");
  CHECK_THROWS_AS(run_scene(too_big_step, dir + "/r.h5"), ConfigError);
  CHECK(fs::is_empty(dir));

  // An output folder that does not exist: HDF5 cannot create the file; the error names the path.
  const SceneConfig good = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml");
  CHECK_THROWS_WITH(run_scene(good, dir + "/no/such/folder/r.h5"),
                    Catch::Matchers::StartsWith(dir + "/no/such/folder/r.h5.partial: cannot create the HDF5 file"));
}

TEST_CASE("a result writer is 'running' while open and 'failed' if dropped before completion", "[io][result]") {
  // The status tells a reader whether a file is finished. A writer that is destroyed without
  // complete() (an exception escaping the run) marks the file failed, never complete.
  const std::string dir = test::scratch_dir("result_writer");
  const SceneConfig scene = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml");
  {
    ResultWriter w(dir + "/r.h5", scene);
    CHECK(w.partial_path() == dir + "/r.h5.partial");
    // Read back through a second (read-only) handle, as another program would.
    CHECK(test::h5_status(dir + "/r.h5.partial") == "running");
  }
  CHECK_FALSE(fs::exists(dir + "/r.h5"));
  CHECK(test::h5_status(dir + "/r.h5.partial") == "failed: the run was interrupted");
}

TEST_CASE("an HDF5 call that fails with nothing on HDF5's error stack and errno ENOMEM is reported as out of memory",
          "[io][result][memory]") {
  // Out of memory, HDF5 can fail before it records why (its error stack allocates too); malloc's
  // ENOMEM is then all that is left. cli_test's sweep of address-space limits meets this case only
  // where the limit happens to land (at 34 MiB in one build folder: "HDF5: attribute units failed"),
  // so here the two inputs of the rule are set directly.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t failed_id = H5Screate_simple(1, nullptr, nullptr);  // no dimensions: refused, the stack says why
  REQUIRE(failed_id < 0);
  errno = ENOMEM;
  CHECK(h5::last_error().find("out of memory") == std::string::npos);  // HDF5's own reason wins over a stale errno
  H5Eclear2(H5E_DEFAULT);
  errno = ENOMEM;
  CHECK(h5::last_error() == "out of memory (HDF5 recorded no reason; errno ENOMEM)");
  errno = 0;
  CHECK(h5::last_error().empty());
}

namespace {

// AddressSanitizer reserves terabytes of shadow address space and aborts when a mapping fails: an
// address-space limit cannot be tried under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool address_sanitizer = true;
#else
constexpr bool address_sanitizer = false;
#endif
#else
constexpr bool address_sanitizer = false;
#endif

// The process's address-space usage now, in bytes (Linux: /proc/self/statm's first field).
std::uint64_t address_space_in_use() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// Lowers the soft address-space limit for its lifetime and restores it after.
class AddressSpaceLimit {
 public:
  explicit AddressSpaceLimit(std::uint64_t bytes) {
    getrlimit(RLIMIT_AS, &saved_);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    set_ = setrlimit(RLIMIT_AS, &lowered) == 0;
  }
  ~AddressSpaceLimit() { setrlimit(RLIMIT_AS, &saved_); }
  bool set() const { return set_; }

 private:
  rlimit saved_{};
  bool set_ = false;
};

}  // namespace

TEST_CASE("an HDF5 failure whose reason HDF5 did not record, within 16 MiB of the memory limit, is reported as out of memory",
          "[io][result][memory]") {
  // A CI run at 34 MiB failed in H5Dcreate2 with only the outer call's "unable to create dataset" on
  // the stack and errno not ENOMEM. The process's headroom under its limit is what is left to tell:
  // here the limit is set 8 MiB above the usage (the rule's side), then 64 MiB above (the other).
  if (address_sanitizer) return;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (address_space_in_use() == 0) return;  // no /proc: the rule cannot apply
  const hid_t failed_id = H5Screate_simple(1, nullptr, nullptr);
  REQUIRE(failed_id < 0);
  errno = 0;
  const std::string no_limit = h5::last_error();
  CHECK(no_limit.find("out of memory") == std::string::npos);
  std::string near, far;
  {
    const AddressSpaceLimit limit(address_space_in_use() + (8u << 20));
    REQUIRE(limit.set());
    errno = 0;
    near = h5::last_error();
  }
  {
    const AddressSpaceLimit limit(address_space_in_use() + (64u << 20));
    errno = 0;
    far = h5::last_error();
  }
  CHECK_THAT(near, Catch::Matchers::StartsWith("out of memory (" + no_limit + "; ") &&
                       Catch::Matchers::EndsWith(" MiB memory limit in use)"));
  CHECK(far == no_limit);
  H5Eclear2(H5E_DEFAULT);
}

TEST_CASE("h5::unit_of reads the unit of a dataset of this version and of an older one", "[io][result]") {
  // Results written before 2026-11-27 named the attribute `units` outside the H5MD groups; today
  // every dataset has `unit`. A hand-made file with one of each, and one with neither.
  const std::string dir = test::scratch_dir("unit_of");
  {
    h5::Handle f = h5::create_file(dir + "/u.h5");
    h5::write(f, "new", std::vector<double>{1, 2}, 1, "Pa");
    h5::write(f, "old", std::vector<double>{1, 2}, 1, "m");
    h5::Handle old(H5Dopen2(f, "old", H5P_DEFAULT));
    REQUIRE(H5Adelete(old, "unit") >= 0);
    h5::set_attribute(old, "units", std::string("m"));
    h5::write(f, "none", std::vector<double>{1}, 1, "s");
    h5::Handle none(H5Dopen2(f, "none", H5P_DEFAULT));
    REQUIRE(H5Adelete(none, "unit") >= 0);
  }
  h5::Handle f = h5::open_file_read(dir + "/u.h5");
  CHECK(h5::unit_of(f, "new") == "Pa");
  CHECK(h5::unit_of(f, "old") == "m");
  CHECK(h5::unit_of(f, "none").empty());
}

namespace {

// A complete result of the tiny scene in `dir`: r.h5.
std::string complete_result(const std::string& dir) {
  const std::string out = dir + "/r.h5";
  // A row every 100 of the 500 steps: 6 rows or so.
  run_scene(scene_from_text(test::tiny_scene(squeeze_stage, "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "output: {interval: 100}\n"),
                            dir + "/s.yaml"),
            out);
  return out;
}

// Opens `file` for writing and runs `edit` on it (a forger's or a flipped bit's change).
template <class Edit>
void edit_file(const std::string& file, Edit edit) {
  h5::Handle f = h5::open_file_write(file);
  edit(f);
}

std::string problem_of(const std::string& file) { return result_problem(h5::open_file_read(file)); }

}  // namespace

TEST_CASE("a complete result is one check: status, wall time and a known schema; every reader asks it", "[io][result][complete]") {
  // Found by a hostile sweep: a killed run's .partial renamed to the result with its status set to
  // "complete" was read by validate, ensemble-cycles and report (dem summary and figure-data
  // refused it for its missing wall_time_s), and a schema_version of 99 or none was read as 4.
  const std::string dir = test::scratch_dir("result_complete_check");
  const std::string out = complete_result(dir);
  CHECK(problem_of(out).empty());
  SECTION("a failed run's .partial, its status set to complete by hand") {
    const std::string partial = dir + "/bad.h5.partial";
    CHECK_THROWS(run_scene(scene_from_text(test::tiny_scene(hopeless_stage), dir + "/bad.yaml"), dir + "/bad.h5"));
    REQUIRE(fs::exists(partial));
    CHECK(problem_of(partial).rfind("status 'failed: ", 0) == 0);
    edit_file(partial, [](hid_t f) { h5::set_attribute(f, "status", std::string("complete")); });
    fs::rename(partial, dir + "/forged.h5");
    CHECK(problem_of(dir + "/forged.h5") ==
          "status 'complete' but no wall_time_s, which a run writes as it completes: a killed run's .partial marked complete by hand?");
    CHECK_THROWS_WITH(read_state(dir + "/forged.h5"), Catch::Matchers::Contains("not a complete result (status 'complete' but no wall_time_s"));
  }
  SECTION("a schema this build does not read, or none") {
    edit_file(out, [](hid_t f) { h5::set_attribute(f, "schema_version", std::int64_t{99}); });
    CHECK(problem_of(out) == "schema_version 99: this dem reads 1 to " + std::to_string(schema_version) + " (a result of a newer dem?)");
    edit_file(out, [](hid_t f) { H5Adelete(f, "schema_version"); });
    CHECK(problem_of(out) == "no schema_version: not a result of dem");
    edit_file(out, [](hid_t f) { h5::set_attribute(f, "schema_version", std::int64_t{schema_version}); });
    CHECK(problem_of(out).empty());
  }
}

TEST_CASE("a result's tables are read whole or refused: a short column, a changed value", "[io][result][table]") {
  // Found by a hostile sweep: a time-series column shorter than `time` was read with zeros for the
  // missing rows (dem table printed 0, validate judged εv 0.0 where it was 0.603), and a flipped
  // bit in a column was read silently. read_table, which every reader uses, refuses both.
  const std::string dir = test::scratch_dir("result_table_check");
  const std::string out = complete_result(dir);
  const Table whole = read_table(h5::open_file_read(out), "timeseries", out);
  const std::size_t rows = whole.at("time").size();
  REQUIRE(rows >= 3);
  for (const auto& [name, values] : whole) CHECK(values.size() == rows);
  SECTION("every column has its checksum, and the unchanged file passes it") {
    h5::Handle f = h5::open_file_read(out);
    h5::Handle g = h5::open_group(f, "timeseries");
    for (const auto& [name, values] : whole) CHECK(h5::has_attribute(h5::Handle(H5Dopen2(g, name.c_str(), H5P_DEFAULT)), "checksum"));
    CHECK_NOTHROW(read_table(f, "legs", out));
  }
  SECTION("a column one row short") {
    edit_file(out, [&](hid_t f) {
      h5::Handle ds(H5Dopen2(f, "timeseries/p", H5P_DEFAULT));
      const hsize_t shorter = rows - 1;
      REQUIRE(H5Dset_extent(ds, &shorter) >= 0);
    });
    CHECK_THROWS_WITH(read_table(h5::open_file_read(out), "timeseries", out),
                      out + ": /timeseries/p has " + std::to_string(rows - 1) + " rows and /timeseries/time " + std::to_string(rows) +
                          ": a damaged result (every column of a table has one value per row)");
    // The tools say so: dem table (it printed 0 for the missing row) and dem summary.
    const std::string dem = std::string(DEM_BINARY_DIR) + "/bin/dem";
    for (const std::string command : {"table '" + out + "' time p", "summary '" + out + "'"}) {
      const auto r = test::run_command("'" + dem + "' " + command + " 2>&1 >/dev/null");
      INFO(command << ": " << r.out);
      CHECK(r.exit_code != 0);
      CHECK_THAT(r.out, Catch::Matchers::Contains("/timeseries/p has " + std::to_string(rows - 1) + " rows"));
    }
  }
  SECTION("one value changed by its last bit") {
    edit_file(out, [&](hid_t f) {
      h5::Handle ds(H5Dopen2(f, "timeseries/p", H5P_DEFAULT));
      std::vector<double> p = whole.at("p");
      p[1] = std::nextafter(p[1], 1e300);
      REQUIRE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0);
    });
    CHECK_THROWS_WITH(read_table(h5::open_file_read(out), "timeseries", out),
                      out + ": /timeseries/p: its values do not match its checksum (changed since the run wrote them: a damaged or edited file)");
  }
}
