// The `dem` command (engine/cli/dem_main.cpp). Its usage text promises: "Exit status: 0 success,
// 1 run failed, 2 bad input", and errors go to stderr.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "engine/io/io_test_support.hpp"
#include "version.hpp"

namespace fs = std::filesystem;

namespace {

const std::string dem_exe = std::string(DEM_BINARY_DIR) + "/bin/dem";

bool have_dem() {
  if (fs::exists(dem_exe)) return true;
  WARN(dem_exe << " not built (cmake --build build --target dem): skipped");
  return false;
}

// Runs dem with `args`; returns exit code and stderr (stdout discarded).
dem::test::CommandResult dem_stderr(const std::string& args) { return dem::test::run_command("'" + dem_exe + "' " + args + " 2>&1 >/dev/null"); }
// Runs dem with `args`; returns exit code and stdout (stderr discarded).
dem::test::CommandResult dem_stdout(const std::string& args) { return dem::test::run_command("'" + dem_exe + "' " + args + " 2>/dev/null"); }

const std::string tiny_stage = "  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 2.0e-4}\n";

}  // namespace

TEST_CASE("dem: usage errors and bad scenes exit with status 2 and a message on stderr", "[run][cli]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_bad");
  SECTION("no arguments: the usage, exit 2") {
    const auto r = dem_stderr("");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("usage:"));
  }
  SECTION("unknown command") {
    const auto r = dem_stderr("frobnicate");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("dem: unknown command 'frobnicate'"));
  }
  SECTION("run without --out") {
    const auto r = dem_stderr("run scene.yaml");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("need a scene file and --out RESULT.h5"));
  }
  SECTION("a scene with a bad value: the message names file, key path and range") {
    dem::test::write_text(dir + "/bad.yaml", dem::test::tiny_scene(tiny_stage, "{kn: 1.0e6, ks: 1.0e6, friction: -0.5}"));
    const auto r = dem_stderr("run '" + dir + "/bad.yaml' --out '" + dir + "/r.h5'");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: " + dir + "/bad.yaml: material.friction: must be in [0, 10], got -0.5"));
    CHECK_FALSE(fs::exists(dir + "/r.h5.partial"));  // refused before any output exists
  }
  SECTION("a nonexistent scene") {
    const auto r = dem_stderr("run '" + dir + "/none.yaml' --out '" + dir + "/r.h5'");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains(dir + "/none.yaml: no such file"));
  }
  SECTION("a time step above the critical-step limit (found when the particles exist)") {
    std::string text = dem::test::tiny_scene(tiny_stage);
    text.replace(text.find("time_step: 1.0e-6"), 17, "time_step: 1.0e-4");
    dem::test::write_text(dir + "/dt.yaml", text);
    const auto r = dem_stderr("run '" + dir + "/dt.yaml' --out '" + dir + "/r.h5'");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("numerics.time_step = 0.0001 s is above the allowed"));
  }
}

TEST_CASE("dem keys lists every scene key and dem --version names the version", "[run][cli]") {
  if (!have_dem()) return;
  const auto keys = dem_stdout("keys");
  CHECK(keys.exit_code == 0);
  CHECK_THAT(keys.out, Catch::Matchers::Contains("  material.friction; [0, 10]; required;"));
  CHECK_THAT(keys.out, Catch::Matchers::Contains("  numerics.time_step [s]"));
  CHECK_THAT(keys.out, Catch::Matchers::Contains("  stages[].hold.max_duration [s]"));
  CHECK_THAT(keys.out, Catch::Matchers::Contains("  damping; mapping; optional (every key at its default);"));
  CHECK_THAT(keys.out, Catch::Matchers::Contains("  stages[].path; "));
  const auto version = dem_stdout("--version");
  CHECK(version.exit_code == 0);
  CHECK_THAT(version.out, Catch::Matchers::Contains(dem::software_version));
}

TEST_CASE("dem run writes a complete result and dem table prints its columns", "[run][cli]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_run");
  // tests/data/csv_scene/scene.yaml: 8 spheres from a CSV file, 500 steps, a row every 100.
  const std::string scene = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene/scene.yaml";
  const auto r = dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5' --quiet");
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("csv_scene: 500 steps"));
  CHECK(dem::test::h5_status(dir + "/r.h5") == "complete");
  CHECK_FALSE(fs::exists(dir + "/r.h5.partial"));

  const auto t = dem_stdout("table '" + dir + "/r.h5' step p");
  CHECK(t.exit_code == 0);
  CHECK(t.out.rfind("# step p\n0\t", 0) == 0);  // a header, then the first row (step 0)
  CHECK(std::count(t.out.begin(), t.out.end(), '\n') == 1 + 6);  // rows at steps 0, 100, ..., 500
  const auto bad_column = dem_stderr("table '" + dir + "/r.h5' pressure");
  CHECK(bad_column.exit_code == 2);
  CHECK_THAT(bad_column.out, Catch::Matchers::Contains("has no column 'pressure'"));
}

TEST_CASE("dem run: a stage that fails exits with status 1 and keeps the partial result", "[run][cli]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_fail");
  dem::test::write_text(dir + "/s.yaml",
                        dem::test::tiny_scene("  - {name: consolidate, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6,"
                                              " hold: {max_duration: 1.0e-5}}\n"));
  const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/r.h5' --quiet");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Matchers::Contains("stage 'consolidate' did not reach equilibrium"));
  CHECK_THAT(r.out, Catch::Matchers::Contains("(partial result kept in " + dir + "/r.h5.partial)"));
  CHECK_FALSE(fs::exists(dir + "/r.h5"));
  CHECK_THAT(dem::test::h5_status(dir + "/r.h5.partial"), Catch::Matchers::StartsWith("failed: "));
}

TEST_CASE("dem run exits 2 (bad input) for a bad grading curve, lattice, particle file or state file", "[run][cli]") {
  // These are found only when the particles are made (grading and lattice generators, CSV and
  // state readers); build_simulation rethrows them as ConfigError naming the scene file and the
  // particle source, so dem sorts them with bad input (exit 2), before any output file exists.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_bad_grading");
  const auto refused = [&](const std::string& scene, const std::string& expected) {
    INFO(scene);
    const auto r = dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5'");
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: " + scene + ": " + expected));
    CHECK_THAT(r.out, !Catch::Matchers::Contains("partial result kept"));
    CHECK_FALSE(fs::exists(dir + "/r.h5.partial"));
  };
  std::string text = dem::test::tiny_scene(tiny_stage);
  text.replace(text.find("percent_finer: [0, 100]"), 23, "percent_finer: [10, 100]");
  dem::test::write_text(dir + "/g.yaml", text);
  refused(dir + "/g.yaml", "particles.lattice/grading: grading: diameters must be positive, percent_finer must start at 0");
  text = dem::test::tiny_scene(tiny_stage);
  text.replace(text.find("spacing: 5.0e-3"), 15, "spacing: 4.0e-3");
  dem::test::write_text(dir + "/l.yaml", text);
  refused(dir + "/l.yaml", "particles.lattice/grading: lattice spacing 0.004 m is smaller than the largest diameter");
  // tests/data/csv_scene/bad_csv_scene.yaml: its CSV file has a negative radius on line 3.
  const std::string csv_folder = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene";
  refused(csv_folder + "/bad_csv_scene.yaml", "particles.csv: " + csv_folder + "/negative_radius.csv: line 3: radius must be > 0 m");
  // A state file that is not a result file.
  dem::test::write_text(dir + "/not_a_result.h5", "plain text\n");
  dem::test::write_text(dir + "/s.yaml", "name: s\nparticles: {state: not_a_result.h5}\nmaterial: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                          "numerics: {time_step: 1.0e-6}\nstages:\n" + tiny_stage);
  refused(dir + "/s.yaml", "particles.state: " + dir + "/not_a_result.h5: not a readable HDF5 file");
}
