// The `dem` command (engine/cli/dem_main.cpp). Its usage text promises: "Exit status: 0 success,
// 1 run failed, 2 bad input", and errors go to stderr.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "run/checkpoint.hpp"
#include "run/output_path.hpp"
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
    CHECK_THAT(r.out, Catch::Matchers::Contains("Usage:"));
    CHECK_THAT(r.out, Catch::Matchers::Contains("run "));  // the sub-commands are listed
  }
  SECTION("unknown command") {
    const auto r = dem_stderr("frobnicate");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("frobnicate"));
  }
  SECTION("run without --out") {
    const auto r = dem_stderr("run scene.yaml");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("--out is required"));
  }
  SECTION("an unknown option and a bad --threads name the option") {
    auto r = dem_stderr("run scene.yaml --out r.h5 --frobnicate");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("--frobnicate"));
    r = dem_stderr("run scene.yaml --out r.h5 --threads 0");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("--threads"));
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
  // The commit is the one the program was built from (written at every build): that of the source
  // tree now, as this test is built with it. It was once the commit CMake was configured at.
  const auto head = dem::test::run_command(std::string("git -C '") + DEM_SOURCE_DIR + "' rev-parse --short=12 HEAD 2>/dev/null");
  if (head.exit_code == 0 && head.out.size() > 12) {
    INFO("HEAD is " << head.out.substr(0, 12) << ": a commit made after the last build fails this until the next build");
    CHECK_THAT(version.out, Catch::Matchers::Contains("+" + head.out.substr(0, 12)));
  }
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
  CHECK(t.out.rfind("# step [1]\tp [Pa]\n0\t", 0) == 0);  // a header with units, then the first row (step 0)
  CHECK(std::count(t.out.begin(), t.out.end(), '\n') == 1 + 6);  // rows at steps 0, 100, ..., 500
  // summary: one line per result under a header with the same units as table's.
  const auto sum = dem_stdout("summary '" + dir + "/r.h5'");
  CHECK(sum.exit_code == 0);
  CHECK(sum.out.rfind("# file\twall_time [s]\tstep [1]\ttime [s]\t", 0) == 0);
  CHECK_THAT(sum.out, Catch::Matchers::Contains("\tp [Pa]\t"));
  CHECK(std::count(sum.out.begin(), sum.out.end(), '\n') == 2);
  const auto bad_column = dem_stderr("table '" + dir + "/r.h5' pressure");
  CHECK(bad_column.exit_code == 2);
  CHECK_THAT(bad_column.out, Catch::Matchers::Contains("has no column 'pressure'"));
}

// Progress where stderr is not a terminal (here a pipe): a line of its own per interval. The run
// reports every 256 steps of a stage from its first; 500 steps give reports after steps 1 and 257.
TEST_CASE("dem run: progress lines when stderr is not a terminal", "[run][cli][progress]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_progress");
  const std::string scene = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene/scene.yaml";
  const auto lines_of = [](const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("[csv_scene ", 0) == 0) lines.push_back(line);
    return lines;
  };
  SECTION("interval 0: a line at every report, with the rate since the line before and the stage's ETA") {
    const auto r = dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5' --no-resume --force --progress-interval 0");
    INFO(r.out);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find('\r') == std::string::npos);  // no terminal redraw
    const auto lines = lines_of(r.out);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0].rfind("[csv_scene 1/1 'squeeze'] step 1, t = 1e-06 s", 0) == 0);
    CHECK_THAT(lines[0], !Catch::Matchers::Contains("steps/s"));  // nothing to take a rate over yet
    CHECK(lines[1].rfind("[csv_scene 1/1 'squeeze'] step 257, t = 0.000257 s, ", 0) == 0);
    CHECK_THAT(lines[1], Catch::Matchers::Contains(" steps/s, 51 % of stage, ETA "));  // 256 of 500 steps done
  }
  SECTION("the default interval (30 s): none in a run of a fraction of a second") {
    const auto r = dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5' --no-resume --force");
    CHECK(r.exit_code == 0);
    CHECK(lines_of(r.out).empty());
  }
  SECTION("--quiet: none; a negative interval is refused with the option's name") {
    CHECK(lines_of(dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5' --no-resume --force --quiet --progress-interval 0").out).empty());
    const auto bad = dem_stderr("run '" + scene + "' --out '" + dir + "/r.h5' --progress-interval -1");
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.out, Catch::Matchers::Contains("--progress-interval"));
  }
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

// ---------------------------------------------------------------------------------------------
// Result integrity: nothing lost, nothing stale. Each case below is written to catch
// the next case of its class: every point at which a disk can fill up, every file a run keeps
// beside its result, every file key of a scene, every kind of non-regular file.

namespace {

// Runs `dem args` from a bash script that first runs `limits` (e.g. "ulimit -f 40"); returns the
// exit status of dem (a crash shows as 128 + signal) and its stderr.
dem::test::CommandResult dem_limited(const std::string& dir, const std::string& limits, const std::string& args) {
  dem::test::write_text(dir + "/limited.sh", limits + "\nexec '" + dem_exe + "' " + args + " 2>&1 >/dev/null\n");
  return dem::test::run_command("bash '" + dir + "/limited.sh'");
}

std::vector<double> series(const std::string& file, const std::string& column) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  std::size_t cols = 0;
  return dem::h5::read<double>(dem::h5::open_group(f, "timeseries"), column, cols);
}

// The names of the files in a folder.
std::set<std::string> listing(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// 27 spheres, 2,000 steps, a row every step, a checkpoint every 500: a result that grows in every
// way a result grows (rows, frames, checkpoints), to 1.3 MB, by ~300 KB between checkpoints.
std::string growing_scene() {
  return dem::test::tiny_scene("  - {name: squeeze, type: strain_rate, strain_rate: [2, 2, 2], duration: 2.0e-3}\n",
                               "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}",
                               "output: {interval: 1, flush_rows: 5, checkpoint_interval: 500, checkpoint_wall_time: 0}\n");
}

}  // namespace

TEST_CASE("dem run: a disk that fills up at any moment of a run loses nothing and never crashes", "[run][cli][disk]") {
  // A file size limit (ulimit -f, SIGXFSZ ignored) makes every write past it fail with EFBIG, as
  // a full disk makes it fail with ENOSPC, without root. The limit is swept from 1 KiB to above
  // the result's size, so that writes fail in the first attribute, in rows, in frames, in each
  // checkpoint, at the final flush and close, and the run finally succeeds. (The same with a real
  // full disk, a 200 KiB tmpfs, is tests/integrity/full_disk_test.sh, which needs root.)
  if (!have_dem() || !dem::test::have_program("bash")) return;
  const std::string dir = dem::test::scratch_dir("cli_full_disk");
  dem::test::write_text(dir + "/s.yaml", growing_scene());
  REQUIRE(dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/reference.h5' --quiet").exit_code == 0);
  const auto reference = series(dir + "/reference.h5", "p");
  const std::uintmax_t kib = fs::file_size(dir + "/reference.h5") / 1024;
  const std::uintmax_t stride = std::max<std::uintmax_t>(1, kib / 40);
  int failed = 0, failed_status = 0, kept_checkpoint = 0, completed = 0;
  std::string resumable;  // a folder whose run failed on a checkpoint and kept the previous one
  for (std::uintmax_t limit = 1; limit <= 2 * kib && completed == 0; limit += stride) {
    const std::string sub = dir + "/limit" + std::to_string(limit), out = sub + "/r.h5";
    fs::create_directories(sub);
    const auto r = dem_limited(sub, "trap '' XFSZ\nulimit -f " + std::to_string(limit),
                               "run '" + dir + "/s.yaml' --out '" + out + "' --quiet");
    INFO("limit " << limit << " KiB: exit " << r.exit_code << "\n" << r.out);
    REQUIRE((r.exit_code == 0 || r.exit_code == 1));  // never a crash (it was 139 at the close)
    CHECK_FALSE(fs::exists(out + ".checkpoint.tmp"));
    if (fs::exists(out + ".checkpoint")) CHECK_NOTHROW(dem::read_checkpoint(out + ".checkpoint"));  // whole, or absent
    if (r.exit_code == 0) {
      ++completed;
      CHECK(dem::test::h5_status(out) == "complete");
      CHECK_FALSE(fs::exists(out + ".partial"));
      CHECK(series(out, "p") == reference);
      continue;
    }
    ++failed;
    CHECK_FALSE(fs::exists(out));  // never renamed: only a complete, flushed, closed file is
    CHECK(fs::exists(out + ".partial"));
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: ") && Catch::Matchers::Contains("File too large") &&
                          Catch::Matchers::Contains("(partial result kept in " + out + ".partial"));
    const std::string status = dem::test::h5_status(out + ".partial");
    CHECK(status != "complete");
    if (status.rfind("failed: ", 0) == 0) {
      ++failed_status;
      CHECK_THAT(status, Catch::Matchers::Contains("File too large"));
      CHECK_THAT(r.out, Catch::Matchers::Contains("(partial result kept in " + out + ".partial)"));
    } else {  // the status is what the file still says, and stderr says it could not be set
      CHECK_THAT(r.out, Catch::Matchers::Contains(out + ".partial; its status could not be set to the reason above: it is "));
    }
    if (r.out.find(out + ".checkpoint keeps the previous one") != std::string::npos) {
      ++kept_checkpoint;
      REQUIRE(fs::exists(out + ".checkpoint"));
      if (resumable.empty()) resumable = sub;
    }
  }
  CHECK(failed >= 10);
  CHECK(failed_status > 0);    // the status took the reason whenever the file could still take it
  CHECK(kept_checkpoint > 0);  // a failed checkpoint did not replace the good one
  CHECK(completed == 1);
  // Nothing lost: with the space back, the run resumes from the checkpoint it kept and ends with
  // the reference's time series, bit for bit.
  REQUIRE_FALSE(resumable.empty());
  const auto again = dem_stderr("run '" + dir + "/s.yaml' --out '" + resumable + "/r.h5' --quiet");
  INFO(again.out);
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.out, Catch::Matchers::Contains("resuming from " + resumable + "/r.h5.checkpoint"));
  CHECK(series(resumable + "/r.h5", "p") == reference);
}

TEST_CASE("dem run: a run out of memory says so, in its exit status, on stderr and in its partial result", "[run][cli][memory]") {
  // An address-space limit (ulimit -v) makes allocations fail, in the engine (std::bad_alloc) or in
  // HDF5. 27,000 spheres with a Verlet skin of 7 cm have ~1.8e8 neighbour pairs: the first list
  // build needs more than 1 GiB. Swept from 32 MiB, the limit stops the run while the particles
  // are made, while the result file is created, in the first frame and in the list build.
  // Out of memory is a failed run (exit 1), never bad input (exit 2), and the partial result's
  // status gives the reason, never "interrupted".
  if (!have_dem() || !dem::test::have_program("bash")) return;
  const std::string dir = dem::test::scratch_dir("cli_memory");
  dem::test::write_text(dir + "/small.yaml", dem::test::tiny_scene(tiny_stage));
  std::string big = dem::test::tiny_scene("  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-5}\n");
  big.replace(big.find("n: [3, 3, 3]"), 12, "n: [30, 30, 30]");
  big.replace(big.find("time_step: 1.0e-6}"), 18, "time_step: 1.0e-6, verlet_skin: 0.07}");
  dem::test::write_text(dir + "/big.yaml", big);
  // A build whose address space cannot be limited this way (e.g. with AddressSanitizer) is skipped.
  if (dem_limited(dir, "ulimit -v 1048576", "run '" + dir + "/small.yaml' --out '" + dir + "/small.h5' --quiet").exit_code != 0) {
    WARN("dem does not run under ulimit -v 1 GiB: skipped");
    return;
  }
  int out_of_memory_status = 0, clean_exits = 0, limits = 0;
  for (const int mib : {32, 34, 36, 40, 48, 64, 128, 256, 1024}) {
    const std::string sub = dir + "/mib" + std::to_string(mib), out = sub + "/r.h5";
    fs::create_directories(sub);
    const auto r = dem_limited(sub, "ulimit -v " + std::to_string(mib * 1024), "run '" + dir + "/big.yaml' --out '" + out + "' --quiet");
    INFO(mib << " MiB: exit " << r.exit_code << "\n" << r.out);
    if (r.exit_code == 127) continue;  // too little even to load the shared libraries
    ++limits;
    // Where the limit falls inside HDF5 (Debian's 1.10), HDF5 itself does not survive a failed
    // malloc: gdb showed a segfault in H5AC_create under H5Fcreate (32 MiB), and a corrupted heap
    // found by H5Fflush after an H5Dwrite that ran out (34 MiB). Such a run dies by a signal and
    // leaves no finished result, which is all it can do; it is reported, not counted as clean.
    if (r.exit_code > 128) {
      WARN(mib << " MiB: died by signal " << r.exit_code - 128 << " (out of memory inside HDF5)");
      CHECK_FALSE(fs::exists(out));
      continue;
    }
    ++clean_exits;
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Matchers::Contains("out of memory"));
    CHECK_FALSE(fs::exists(out));
    if (!fs::exists(out + ".partial")) continue;  // stopped before the result file existed
    const std::string status = dem::test::h5_status(out + ".partial");
    // Out of memory, HDF5 may not manage to write the failed status either (34 MiB in some build
    // folders, after a bad_alloc or an HDF5 failure while the file was created). The partial result
    // then says "running", or nothing, or cannot be read (never "complete": it is never taken for a
    // finished one); the reason is on stderr (checked above), and so is what the status is.
    if (status.empty() || status == "running") {
      WARN(mib << " MiB: out of memory, the partial result's status could not be set: '" << status << "'");
      CHECK_THAT(r.out, Catch::Matchers::Contains("; its status could not be set to the reason above: it is "));
      continue;
    }
    CHECK_THAT(status, Catch::Matchers::StartsWith("failed: ") && Catch::Matchers::Contains("out of memory") &&
                           !Catch::Matchers::Contains("interrupted"));
    if (status == "failed: out of memory (std::bad_alloc)") ++out_of_memory_status;
  }
  CHECK(out_of_memory_status > 0);
  CHECK(2 * clean_exits > limits);  // most limits fall in the engine's own allocations
}

TEST_CASE("dem run refuses a step count of 0 or above 1e12, with the keys, before anything is written", "[run][cli][input]") {
  // numerics.time_step = 1e-21 with a 0.01 s stage overflowed the step count: 0 steps and a
  // "complete" result with exit 0. (Every stage type and key: bad_scenes_test.cpp.)
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_step_count");
  dem::test::write_text(dir + "/s.yaml",
                        dem::test::tiny_scene("  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 0.01}\n"));
  for (const auto& [set, expected] : std::vector<std::pair<std::string, std::string>>{
           {"numerics.time_step=1e-21", "stages[0].duration: 0.01 s at numerics.time_step = 1e-21 s is 1e+19 steps, more than the 1e+12"},
           {"stages[0].duration=1e-7", "stages[0].duration: 1e-07 s is less than half of numerics.time_step = 1e-06 s: the stage would get 0 steps"}}) {
    const auto r = dem_stderr("run '" + dir + "/s.yaml' --set " + set + " --out '" + dir + "/r.h5'");
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: " + dir + "/s.yaml: " + expected));
    CHECK(listing(dir) == std::set<std::string>{"s.yaml"});  // nothing written, not even the lock
  }
}

TEST_CASE("dem run refuses an --out that names a file kept beside a result, even while that result is written",
          "[run][cli][input]") {
  // The lock is per --out name: `--out X.h5.partial` while a run writes X.h5 replaced that run's
  // result by another scene's, both exiting 0. Refused: every name a run keeps beside a result,
  // taken both from the engine's own list (result_family) and from the files real runs leave
  // (a failed run with checkpoints, a complete run with frames), so a new kind of file is caught.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_reserved");
  dem::test::write_text(dir + "/s.yaml", growing_scene());
  dem::test::write_text(dir + "/stops.yaml",
                        dem::test::tiny_scene("  - {name: hold, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e9,"
                                              " hold: {max_duration: 2.0e-4}}\n",
                                              "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "output: {checkpoint_interval: 50}\n"));
  REQUIRE(dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/r.h5' --quiet").exit_code == 0);
  REQUIRE(dem_stderr("run '" + dir + "/stops.yaml' --out '" + dir + "/f.h5' --quiet").exit_code == 1);
  std::set<std::string> kept;  // what the runs left beside their results, as names beside r.h5
  for (const std::string& name : listing(dir)) {
    if (name == "s.yaml" || name == "stops.yaml" || name == "r.h5" || name == "f.h5") continue;
    kept.insert(name.rfind("f.h5", 0) == 0 ? "r.h5" + name.substr(4) : name.rfind("f.", 0) == 0 ? "r." + name.substr(2) : name);
  }
  CHECK(kept.count("r.h5.partial"));  // the runs did leave files beside their results
  CHECK(kept.count("r.h5.checkpoint"));
  CHECK(kept.count("r.xdmf"));
  for (const dem::FamilyFile& f : dem::result_family(dir + "/r.h5"))
    if (f.path != dir + "/r.h5") kept.insert(fs::path(f.path).filename().string());
  for (const std::string& suffix : dem::reserved_suffixes()) kept.insert("r.h5" + suffix);
  const std::set<std::string> before = listing(dir);
  for (const std::string& name : kept) {
    INFO(name);
    const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/" + name + "' --quiet");
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: --out " + dir + "/" + name + " ends in '") &&
                          Catch::Matchers::Contains("nothing was run"));
    CHECK(listing(dir) == before);
  }
  // While another run writes r.h5 (it holds r.h5.lock): its partial result is not touched.
  dem::test::write_text(dir + "/r.h5.partial", "another run's partial result\n");
  const int fd = open((dir + "/r.h5.lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(flock(fd, LOCK_EX | LOCK_NB) == 0);
  const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/r.h5.partial' --force");
  close(fd);
  CHECK(r.exit_code == 2);
  CHECK(dem::test::read_bytes(dir + "/r.h5.partial") == "another run's partial result\n");
}

TEST_CASE("dem run refuses an --out that is, or whose companion files are, a file the run reads", "[run][cli][input]") {
  // `--out` equal to the scene's own state file silently overwrote the sample. Every file key of a
  // scene is covered (the test fails if `dem keys` lists one it does not know), and the scene file
  // itself; each by other spellings of the path (./, .., a linked folder, a hard link), and for every
  // file a run keeps beside its result (an XDMF view named like the CSV would replace it).
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_out_is_input");
  std::set<std::string> file_keys;
  std::istringstream keys(dem_stdout("keys").out);
  for (std::string line; std::getline(keys, line);)
    if (line.find(std::string("; ") + dem::Section::file_path_allowed + ";") != std::string::npos)
      file_keys.insert(line.substr(2, line.find(';') - 2));
  CHECK(file_keys == std::set<std::string>{"particles.csv", "particles.state"});  // a new file key needs its case below

  const std::string csv_folder = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene";
  fs::copy_file(csv_folder + "/particles.csv", dir + "/particles.csv");
  dem::test::write_text(dir + "/csv.yaml", dem::test::read_bytes(csv_folder + "/scene.yaml"));
  REQUIRE(dem_stderr("run '" + dir + "/csv.yaml' --out '" + dir + "/sample.h5' --quiet").exit_code == 0);
  dem::test::write_text(dir + "/state.yaml", "name: s\nparticles: {state: sample.h5}\nmaterial: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                             "numerics: {time_step: 1.0e-6}\nstages:\n" + tiny_stage);
  fs::create_directory_symlink(dir, dir + "/linked");
  fs::create_hard_link(dir + "/sample.h5", dir + "/hard.h5");
  const auto refused = [&](const std::string& scene, const std::string& out, const std::string& expected_if_h5) {
    INFO("scene " << scene << ", --out " << out);
    // An --out that is not .h5 (the CSV, the scene file) is refused for its name before the inputs
    // are compared; refused all the same, nothing run, every input intact.
    const bool h5 = out.size() > 3 && out.compare(out.size() - 3, 3, ".h5") == 0;
    const std::string expected = h5 ? expected_if_h5 : "must end in .h5 or .hdf5";
    const std::string input = dem::test::read_bytes(dir + "/particles.csv") + dem::test::read_bytes(dir + "/sample.h5") +
                              dem::test::read_bytes(dir + "/" + scene);
    for (const char* force : {"", " --force"}) {
      const auto r = dem_stderr("run '" + dir + "/" + scene + "' --out '" + out + "'" + force);
      INFO(r.out);
      CHECK(r.exit_code == 2);
      CHECK_THAT(r.out, Catch::Matchers::Contains("error: --out " + out) && Catch::Matchers::Contains(expected) &&
                            Catch::Matchers::Contains("nothing was run"));
    }
    CHECK(dem::test::read_bytes(dir + "/particles.csv") + dem::test::read_bytes(dir + "/sample.h5") +
              dem::test::read_bytes(dir + "/" + scene) == input);
  };
  for (const std::string& out : {dir + "/particles.csv", dir + "/./particles.csv", dir + "/linked/particles.csv"})
    refused("csv.yaml", out, "is particles.csv, a file this run reads");
  fs::create_directory(dir + "/sub");
  for (const std::string& out : {dir + "/sample.h5", dir + "/sub/../sample.h5", dir + "/linked/sample.h5", dir + "/hard.h5"})
    refused("state.yaml", out, "is particles.state, a file this run reads");
  refused("state.yaml", dir + "/state.yaml", "is the scene file");
  refused("csv.yaml", dir + "/linked/csv.yaml", "is the scene file");
  // Every file of --out's family (its partial result, checkpoint, lock, XDMF view, ...) named like
  // the CSV the scene reads.
  for (const dem::FamilyFile& f : dem::result_family(dir + "/x.h5")) {
    if (f.path == dir + "/x.h5") continue;
    const std::string name = fs::path(f.path).filename().string();
    fs::copy_file(dir + "/particles.csv", f.path);
    std::string text = dem::test::read_bytes(dir + "/csv.yaml");
    text.replace(text.find("csv: particles.csv"), 18, "csv: " + name);
    dem::test::write_text(dir + "/family.yaml", text);
    refused("family.yaml", dir + "/x.h5", f.path + " (" + f.role + ") would replace particles.csv");
    fs::remove(f.path);
  }
}

TEST_CASE("dem run refuses an --out that is not a regular file, or whose companion files are not", "[run][cli][input]") {
  // `--out /dev/null` replaced the device node with an HDF5 file (as root). Every kind of
  // non-regular file is refused, for --out and for every file a run writes beside it (a FIFO
  // blocks, a symbolic link would be written through).
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_out_kind");
  dem::test::write_text(dir + "/s.yaml", dem::test::tiny_scene(tiny_stage));
  dem::test::write_text(dir + "/victim.txt", "not to be touched\n");
  fs::create_directory(dir + "/folder.h5");
  REQUIRE(mkfifo((dir + "/fifo.h5").c_str(), 0644) == 0);
  fs::create_symlink(dir + "/victim.txt", dir + "/link.h5");
  fs::create_symlink(dir + "/nothing.txt", dir + "/dangling.h5");
  const auto refused = [&](const std::string& out, const std::string& expected) {
    const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "' --force");
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: --out " + out) && Catch::Matchers::Contains(expected) &&
                          Catch::Matchers::Contains("nothing was run"));
  };
  refused("/dev/null", "is a character device, not a regular file");
  CHECK(fs::is_character_file("/dev/null"));
  refused(dir + "/folder.h5", "is a directory, not a file name");
  refused(dir + "/fifo.h5", "is a FIFO (named pipe), not a regular file");
  refused(dir + "/link.h5", "is a symbolic link, not a regular file");
  refused(dir + "/dangling.h5", "is a symbolic link, not a regular file");
  CHECK_FALSE(fs::exists(dir + "/nothing.txt"));
  for (const dem::FamilyFile& f : dem::result_family(dir + "/r.h5")) {
    if (f.path == dir + "/r.h5") continue;
    INFO(f.path);
    REQUIRE(mkfifo(f.path.c_str(), 0644) == 0);
    refused(dir + "/r.h5", f.path + " (" + f.role + ") is a FIFO (named pipe), not a regular file");
    fs::remove(f.path);
    fs::create_symlink(dir + "/victim.txt", f.path);
    refused(dir + "/r.h5", f.path + " (" + f.role + ") is a symbolic link, not a regular file");
    fs::remove(f.path);
  }
  CHECK(dem::test::read_bytes(dir + "/victim.txt") == "not to be touched\n");
  CHECK_FALSE(fs::exists(dir + "/r.h5"));
}

TEST_CASE("dem run replaces an existing result of another scene, or any other file, only with --force", "[run][cli][input]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_force");
  dem::test::write_text(dir + "/s.yaml", dem::test::tiny_scene(tiny_stage));
  const std::string out = dir + "/r.h5";
  const auto run = [&](const std::string& args) { return dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "' --quiet " + args); };
  REQUIRE(run("").exit_code == 0);
  CHECK(run("").exit_code == 0);  // the same scene again: no --force needed
  const auto needs_force = [&](const std::string& args, const std::string& holds) {
    const std::string before = dem::test::read_bytes(out);
    const auto r = run(args);
    INFO(args << "\n" << r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("error: --out " + out + " holds " + holds) &&
                          Catch::Matchers::Contains("give --force to replace it"));
    CHECK(dem::test::read_bytes(out) == before);
    CHECK_FALSE(fs::exists(out + ".lock"));
    CHECK(run(args + " --force").exit_code == 0);
  };
  needs_force("--set particles.lattice.seed=2", "the complete result of another scene (of " + dir + "/s.yaml, its resolved scene differs");
  needs_force("", "the complete result of another scene");  // back from seed 2 to seed 1
  needs_force("--input-hash abc", "the complete result of another scene (of " + dir + "/s.yaml, its input hash '' differs from this run's 'abc')");
  CHECK(run("--input-hash abc").exit_code == 0);
  dem::test::write_text(out, "my notes\n");
  needs_force("", "a file that is not a dem result");
  // A result at the final name that is not complete (a copy of a partial result, say).
  REQUIRE(dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/other.h5' --quiet").exit_code == 0);
  {
    dem::h5::Handle f = dem::h5::open_file_write(dir + "/other.h5");
    dem::h5::set_attribute(f, "status", std::string("failed: a test"));
  }
  fs::copy_file(dir + "/other.h5", out, fs::copy_options::overwrite_existing);
  needs_force("", "a result with status 'failed: a test'");
}

TEST_CASE("dem: every sub-command answers --help with exit 0", "[run][cli]") {
  if (!have_dem()) return;
  for (const std::string cmd : {"", "run ", "keys ", "table ", "state ", "summary "}) {
    const auto r = dem_stdout(cmd + "--help");
    INFO("dem " << cmd << "--help");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Matchers::Contains("Usage:"));
  }
  CHECK_THAT(dem_stdout("run --help").out, Catch::Matchers::Contains("--set"));
  CHECK_THAT(dem_stdout("table --help").out, Catch::Matchers::Contains("--csv"));
}

TEST_CASE("dem run: an --out that is not .h5 or .hdf5 is refused, and no refused run leaves a file", "[run][cli]") {
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_extension");
  dem::test::write_text(dir + "/s.yaml", dem::test::tiny_scene(tiny_stage));
  for (const std::string name : {"out.csv", "out", "out.h5x"}) {
    const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/" + name + "' --quiet");
    INFO(name << ": " << r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("must end in .h5 or .hdf5"));
  }
  // A scene refused when the run starts (the time step, found once the particles exist), after
  // the lock was taken: nothing is left, the lock file neither.
  std::string text = dem::test::tiny_scene(tiny_stage);
  text.replace(text.find("time_step: 1.0e-6"), 17, "time_step: 1.0e-4");
  dem::test::write_text(dir + "/dt.yaml", text);
  const auto r = dem_stderr("run '" + dir + "/dt.yaml' --out '" + dir + "/r.h5' --quiet");
  CHECK(r.exit_code == 2);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != "s.yaml" && e.path().filename() != "dt.yaml") left.push_back(e.path().filename().string());
  CHECK(left.empty());
  for (const auto& f : left) WARN("left behind: " << f);
  // Both extensions run.
  for (const std::string name : {"a.h5", "b.hdf5"}) {
    const auto ok = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/" + name + "' --quiet");
    INFO(name << ": " << ok.out);
    CHECK(ok.exit_code == 0);
    CHECK(dem::test::h5_status(dir + "/" + name) == "complete");
  }
}

TEST_CASE("dem run: paths typed on the command line are relative to the current folder, paths in a scene to the scene",
          "[run][cli]") {
  if (!have_dem()) return;
  // scenes/ holds the scene (which names its particle file sample.csv, beside it) and another
  // sample.csv; work/ is where the command is typed and holds a third sample.csv, with a different
  // number of spheres each, so the result's sphere count tells which file was read.
  const std::string dir = dem::test::scratch_dir("cli_paths");
  fs::create_directories(dir + "/scenes");
  fs::create_directories(dir + "/work");
  const auto spheres = [](int n) {
    std::string csv = "x,y,z,radius\n";
    for (int i = 0; i < n; ++i) csv += std::to_string(0.004 + 0.008 * i) + ",0.01,0.01,0.002\n";
    return csv;
  };
  dem::test::write_text(dir + "/scenes/sample.csv", spheres(2));
  dem::test::write_text(dir + "/work/sample.csv", spheres(3));
  std::string scene = dem::test::tiny_scene(tiny_stage);
  const auto start = scene.find("particles:");
  const auto end = scene.find("\nmaterial");
  REQUIRE(start != std::string::npos);
  REQUIRE(end != std::string::npos);
  scene.replace(start, end - start, "particles: {csv: sample.csv, cell: [0.04, 0.04, 0.04]}");
  dem::test::write_text(dir + "/scenes/s.yaml", scene);
  const auto count = [&](const std::string& result) {
    const auto st = dem_stdout("state '" + result + "'");
    return std::count(st.out.begin(), st.out.end(), '\n') - 1;  // a header, then a line per sphere
  };
  // Typed in work/: --out and --set are relative to work/; the scene's own path to scenes/.
  const auto in_work = [&](const std::string& args) {
    return dem::test::run_command("cd '" + dir + "/work' && '" + dem_exe + "' run ../scenes/s.yaml --quiet " + args + " 2>&1");
  };
  auto r = in_work("--out from_scene.h5");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir + "/work/from_scene.h5"));
  CHECK(count(dir + "/work/from_scene.h5") == 2);
  r = in_work("--out from_cli.h5 --set particles.csv=sample.csv");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(count(dir + "/work/from_cli.h5") == 3);
  r = in_work("--out from_cli_map.h5 --set 'particles={csv: sample.csv, cell: [0.04, 0.04, 0.04]}'");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(count(dir + "/work/from_cli_map.h5") == 3);
}

TEST_CASE("dem run reads each particle file once: a FIFO as the CSV runs, a FIFO as the state is refused", "[run][cli][input][fifo]") {
  // Found in review: dem opened particles.csv twice (to parse it, then to hash it into the
  // checkpoint identity), so a FIFO fed once by `cat` hung forever in the second open. The run
  // reads it once now; a saved state (HDF5, read by seeking) must be a regular file. Each source
  // that is a file is swept: csv runs to the same result as from the regular file, state is
  // refused with exit 2 before any output exists.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_fifo");
  const std::string csv_folder = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene";
  REQUIRE(mkfifo((dir + "/p.csv").c_str(), 0644) == 0);
  dem::test::write_text(dir + "/scene.yaml", "name: csv_scene\nparticles: {csv: p.csv, cell: [0.02, 0.02, 0.02]}\n"
                                             "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\nnumerics: {time_step: 1.0e-6}\n"
                                             "output: {interval: 100}\nstages:\n"
                                             "  - {name: squeeze, type: strain_rate, strain_rate: [1.0, 1.0, 1.0], duration: 5.0e-4}\n");
  // The writer feeds the FIFO once; `timeout` turns a hang into exit 124 instead of a stuck test.
  const auto r = dem::test::run_command("cat '" + csv_folder + "/particles.csv' > '" + dir + "/p.csv' & timeout 60 '" + dem_exe +
                                        "' run '" + dir + "/scene.yaml' --out '" + dir + "/fifo.h5' --quiet 2>&1 >/dev/null; "
                                        "s=$?; wait; exit $s");
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK(dem::test::h5_status(dir + "/fifo.h5") == "complete");
  // The same run from the regular file: the same time series.
  const auto regular = dem_stderr("run '" + csv_folder + "/scene.yaml' --out '" + dir + "/regular.h5' --quiet");
  REQUIRE(regular.exit_code == 0);
  for (const char* column : {"p", "void_ratio", "kinetic_energy_centred"}) CHECK(series(dir + "/fifo.h5", column) == series(dir + "/regular.h5", column));

  REQUIRE(mkfifo((dir + "/state.h5").c_str(), 0644) == 0);
  dem::test::write_text(dir + "/s.yaml", "name: s\nparticles: {state: state.h5}\nmaterial: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                         "numerics: {time_step: 1.0e-6}\nstages:\n" + tiny_stage);
  const auto s = dem::test::run_command("timeout 60 '" + dem_exe + "' run '" + dir + "/s.yaml' --out '" + dir + "/s.h5' 2>&1 >/dev/null");
  INFO(s.out);
  CHECK(s.exit_code == 2);
  CHECK_THAT(s.out, Catch::Matchers::Contains("particles.state: " + dir + "/state.h5: not a regular file"));
  CHECK_FALSE(fs::exists(dir + "/s.h5.partial"));
}

TEST_CASE("dem run keeps a resolved scene and warnings of any size: neither is an attribute", "[run][cli][integrity][text]") {
  // Found in review: the resolved scene and the warnings were root attributes, whose object
  // header holds 64 KiB: 603 warnings stopped a valid run at step 217,720 ("object header message
  // is too large", exit 1, the result lost), and a scene over 64 KiB failed before its first step.
  // Both are datasets now. The class swept: every text a run records that grows with its input
  // (the scene) or its length (the warnings), each taken past 64 KiB: a long scene with many
  // warnings, and many warnings from a short scene.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_text");
  // 64 spheres of 4.0-4.5 mm at 100 kPa (the stress-path tests' sample).
  dem::test::write_text(dir + "/sample.yaml",
                        "name: sample\nparticles:\n  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
                        "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                        "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\nnumerics: {time_step: 2.0e-6}\n"
                        "output: {interval: 5000}\nstages:\n"
                        "  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e7, max_strain_rate: 5.0,\n"
                        "     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0e-2, max_duration: 2.0}}\n");
  REQUIRE(dem_stderr("run '" + dir + "/sample.yaml' --out '" + dir + "/sample.h5' --quiet").exit_code == 0);
  // A stress path whose every leg is one step at a rate no servo follows: the cell moves at its
  // cap of 5/s, I ~ 5 x 4.25 mm x sqrt(2650 / 1e5) ~ 3.5e-3 > 1e-3, and such a leg warns.
  const auto path_scene = [&](const std::string& path) {
    return "name: jolt\nparticles: {state: sample.h5}\nmaterial: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
           "numerics: {time_step: 2.0e-6}\noutput: {interval: 1000000}\nstages:\n"
           "  - {name: jolt, type: stress_path, rate: 1.0e12, max_strain_rate: 5, path: " + path + "}\n";
  };
  std::string explicit_states = "[";
  for (int i = 0; i < 4000; ++i) explicit_states += i % 2 ? "[1.0e5, 1.0e5, 1.0e5], " : "[1.2e5, 0.9e5, 0.9e5], ";
  explicit_states += "A]";
  struct Case {
    std::string what, path;
    bool big_scene;
  };
  for (const Case& c : {Case{"a resolved scene over 64 KiB, 4,000 legs", explicit_states, true},
                        Case{"1,001 legs of a small scene", "[TC1, {repeat: 500, path: [TC2, TC1]}]", false}}) {
    INFO(c.what);
    dem::test::write_text(dir + "/s.yaml", path_scene(c.path));
    const std::string out = dir + "/r.h5";
    const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "' --quiet --force");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, !Catch::Matchers::Contains("too large") && !Catch::Matchers::Contains("out of memory"));
    REQUIRE(dem::test::h5_status(out) == "complete");
    dem::h5::Handle f = dem::h5::open_file_read(out);
    const std::string yaml = dem::h5::read_text(f, "scene_yaml");
    CHECK(yaml == dem::load_scene(dir + "/s.yaml").resolved_yaml);
    if (c.big_scene) CHECK(yaml.size() > 65536);
    // One warning per leg above 1e-3, as /legs records them, in order.
    std::size_t cols = 0;
    const std::vector<double> leg_max = dem::h5::read<double>(dem::h5::open_group(f, "legs"), "max_inertial_number", cols);
    std::size_t fast = 0;
    for (const double i : leg_max) fast += i > 1e-3 ? 1 : 0;
    // A -> 4,000 states -> A: the last state is A itself, a leg of length 0 that is not run.
    CHECK(leg_max.size() == (c.big_scene ? 4000u : 1001u));
    const std::vector<std::string> warnings = dem::h5::read_texts(f, "warnings");
    CHECK(warnings.size() == fast);
    CHECK(fast > 600);  // more warnings than stopped the run before
    std::size_t bytes = 0;
    for (const std::string& w : warnings) bytes += w.size();
    CHECK(bytes > 65536);
    CHECK_THAT(warnings.back(), Catch::Matchers::EndsWith("the loading is not quasi-static"));
    CHECK_FALSE(dem::h5::has_attribute(f, "warnings"));
    CHECK_FALSE(dem::h5::has_attribute(f, "scene_yaml"));
  }
}

TEST_CASE("dem run leaves no lock file, however it ends after taking the lock", "[run][cli][integrity][lock]") {
  // a run refused after it took OUT.lock (bad input found when the particles are made,
  // --resume without a checkpoint) left an empty OUT.lock behind. The class swept: every end of a
  // run that took the lock, refused (exit 2: a result of another scene without --force, a time
  // step above the critical step, --resume with nothing to resume), failed (exit 1) or complete
  // (exit 0). None leaves OUT.lock; a lock held by another process is left alone.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_lock");
  std::string too_fast = dem::test::tiny_scene(tiny_stage);
  too_fast.replace(too_fast.find("time_step: 1.0e-6"), 17, "time_step: 1.0e-4");
  dem::test::write_text(dir + "/dt.yaml", too_fast);
  dem::test::write_text(dir + "/ok.yaml", dem::test::tiny_scene(tiny_stage));
  dem::test::write_text(dir + "/other.yaml", dem::test::tiny_scene(tiny_stage, "{kn: 2.0e6, ks: 2.0e6, friction: 0.5}"));
  dem::test::write_text(dir + "/fails.yaml",
                        dem::test::tiny_scene("  - {name: consolidate, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6,"
                                              " hold: {max_duration: 1.0e-5}}\n"));
  struct End {
    std::string what, scene, args;
    int exit_code;
  };
  const std::string out = dir + "/r.h5";
  REQUIRE(dem_stderr("run '" + dir + "/ok.yaml' --out '" + out + "' --quiet").exit_code == 0);
  const std::vector<End> ends = {
      {"complete", "ok.yaml", "", 0},
      {"refused: another scene's result without --force", "other.yaml", "", 2},
      {"refused: the time step above the critical step", "dt.yaml", "--force", 2},
      {"refused: --resume without a checkpoint", "ok.yaml", "--resume --force", 2},
      {"failed: a hold that never settles", "fails.yaml", "--force", 1},
  };
  for (const End& e : ends) {
    INFO(e.what);
    const auto r = dem_stderr("run '" + dir + "/" + e.scene + "' --out '" + out + "' --quiet " + e.args);
    INFO(r.out);
    CHECK(r.exit_code == e.exit_code);
    CHECK_FALSE(fs::exists(out + ".lock"));
  }
  // Held by another process: refused, and its lock file stays where it is.
  const int fd = open((out + ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(flock(fd, LOCK_EX | LOCK_NB) == 0);
  const auto busy = dem_stderr("run '" + dir + "/ok.yaml' --out '" + out + "' --quiet --force");
  CHECK(busy.exit_code == 2);
  CHECK_THAT(busy.out, Catch::Matchers::Contains("another dem run is writing this result"));
  CHECK(fs::exists(out + ".lock"));
  close(fd);
}

TEST_CASE("dem run: a hold that fails gives the stresses it reached, measured at the end", "[run][cli][hold]") {
  // the message said "stress error 0 %, unbalanced force ratio 1" (the values before the
  // hold's first check) while p was far from the target. The 27 spheres of the tiny lattice do not
  // touch (5 mm apart, at most 4.5 mm wide): in 10 steps of a ramp that needs 0.1 s the stress
  // stays 0, so every axis is 100 % off its target of 100 kPa.
  if (!have_dem()) return;
  const std::string dir = dem::test::scratch_dir("cli_hold_message");
  dem::test::write_text(dir + "/s.yaml",
                        dem::test::tiny_scene("  - {name: consolidate, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6,"
                                              " hold: {max_duration: 1.0e-5}}\n"));
  const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/r.h5' --quiet");
  INFO(r.out);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Matchers::Contains("stresses 0, 0, 0 Pa against targets 100000, 100000, 100000 Pa, largest stress error 100 %"));
  CHECK_THAT(r.out, Catch::Matchers::Contains("the ramp itself needs 0.1 s at rate = 1e+06 Pa/s"));
}
