// The pipeline's integrity: no shell ever sees a path, one pipeline per results folder,
// a particle file the pipeline hashes must be a regular file.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "exec/scheduler.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin";

// For the test's own shell commands (run_command): one argument, single-quoted.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  pipeline::test::write_tiny_scenes(dir, "2.0e-4", "2.0e-4");
  std::ofstream(dir / "study.yaml") << "name: tiny\noutput: out\npreparation: prep.yaml\n"
                                       "densities: [{name: loose, friction: 0.5}]\ntests: [{name: test1, scene: test.yaml}]\n"
                                       "profiles: {paper: {lattice: 3}, quick: {lattice: 3}}\n";
  return dir;
}

}  // namespace

TEST_CASE("pipeline: no shell sees the engine's path, whatever its folder is called", "[pipeline][integrity][shell]") {
  // Found in review: `pipeline` ran popen("'DEM' --source-hash"): a folder named
  // `inj'; touch INJECTED; echo '` ran touch, and `o'brien` made the pipeline unusable. The class
  // swept: folder names holding each character a shell treats specially (quote, semicolon,
  // command substitution, backquote, glob, newline, a leading dash, spaces). The engine is found
  // and answers as from its own folder; no command in a name runs.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "shell_paths";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string dem = bin + "/dem";
  REQUIRE(fs::exists(dem));
  const std::string expected = pipeline::engine_version(dem);
  REQUIRE_FALSE(expected.empty());
  const std::vector<std::string> names = {"inj'; touch INJECTED; echo '", "o'brien", "$(touch SUBST)", "`touch BACK`", "semi;colon",
                                          "glob*?[x]", "new\nline", "-dash", "two  spaces", "dollar$HOME", "amp & touch AMP"};
  for (const std::string& name : names) {
    INFO("folder '" << name << "'");
    const fs::path folder = dir / name;
    fs::create_directories(folder);
    fs::create_symlink(dem, folder / "dem");
    const fs::path cwd = fs::current_path();
    fs::current_path(dir);  // a relative `touch` would land here
    const std::string got = pipeline::engine_version((folder / "dem").string());
    fs::current_path(cwd);
    CHECK(got == expected);
  }
  for (const char* planted : {"INJECTED", "SUBST", "BACK", "AMP"}) {
    CHECK_FALSE(fs::exists(dir / planted));
    CHECK_FALSE(fs::exists(fs::current_path() / planted));
  }
  CHECK(pipeline::engine_version((dir / "absent" / "dem").string()).empty());
  // The pipeline program itself, given such an engine (--plan: plans with the engine's hash).
  if (!fs::exists(bin + "/pipeline")) {
    WARN("pipeline not built: the program is not tried");
    return;
  }
  const fs::path study = fresh("shell_paths_study");
  const auto r = dem::test::run_command("cd " + quoted(dir.string()) + " && " + quoted(bin + "/pipeline") + " " +
                                        quoted((study / "study.yaml").string()) + " --plan --dem " +
                                        quoted((dir / names[0] / "dem").string()) + " 2>&1");
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "INJECTED"));
}

TEST_CASE("pipeline: one pipeline per results folder; the second refuses before writing anything", "[pipeline][integrity][lock]") {
  // two pipelines on one study ran the same runs; the second reported FAILED for a run
  // the first finished, and the log was garbled. The folder's lock is held while a pipeline runs
  // and removed when it ends.
  const fs::path dir = fresh("study_lock");
  const std::string out = (dir / "out").string();
  {
    const auto first = pipeline::lock_results_folder(out);
    REQUIRE(first->held());
    CHECK(fs::exists(out + "/.pipeline.lock"));
    CHECK_THROWS_MATCHES(pipeline::lock_results_folder(out), dem::ConfigError,
                         Catch::Matchers::Predicate<std::exception>([&](const std::exception& e) {
                           const std::string m = e.what();
                           return m.rfind("another pipeline is running in " + out + " (pid " + std::to_string(getpid()) + " on ", 0) == 0 &&
                                  m.find("nothing was run") != std::string::npos;
                         }, "names the folder and the holder"));
    // The program: refused with exit 2, nothing written (no runs.tsv, no scenes).
    if (fs::exists(bin + "/pipeline")) {
      const auto r = dem::test::run_command(quoted(bin + "/pipeline") + " " + quoted((dir / "study.yaml").string()) +
                                            " --profile quick --out " + quoted(out) + " --dem " + quoted(bin + "/dem") + " 2>&1");
      INFO(r.out);
      CHECK(r.exit_code == 2);
      CHECK_THAT(r.out, Catch::Matchers::Contains("error: another pipeline is running in " + out));
      CHECK_FALSE(fs::exists(out + "/runs.tsv"));
      CHECK_FALSE(fs::exists(out + "/scenes"));
    }
  }
  CHECK_FALSE(fs::exists(out + "/.pipeline.lock"));  // let go and removed
  const auto again = pipeline::lock_results_folder(out);
  CHECK(again->held());
}

TEST_CASE("pipeline: a particle file that is not a regular file is refused when planned", "[pipeline][integrity][fifo]") {
  // The pipeline reads a preparation's particle file for its input hash, and dem reads it again:
  // a FIFO would give its bytes to the pipeline and leave dem waiting.
  const fs::path dir = fresh("study_fifo");
  REQUIRE(mkfifo((dir / "p.csv").c_str(), 0644) == 0);
  std::ofstream(dir / "csv.yaml") << "name: tiny\noutput: out\npreparation: prep.yaml\n"
                                     "densities: [{name: loose, friction: 0.5}]\n"
                                     "profiles: {paper: {lattice: 3}, quick: {lattice: 3}}\n"
                                     "variants: [{name: csv, prepare: {particles: {csv: p.csv, cell: [0.02, 0.02, 0.02]}}}]\n";
  const pipeline::Study study = pipeline::load_study((dir / "csv.yaml").string());
  CHECK_THROWS_MATCHES(pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "engine"), dem::ConfigError,
                       Catch::Matchers::Predicate<std::exception>([&](const std::exception& e) {
                         return std::string(e.what()).find((dir / "p.csv").string() + " is not a regular file") != std::string::npos;
                       }, "names the file"));
}
