// The validation tools fail loudly on nothing: a results folder that is missing or a file exits 2
// naming it; a folder without a single result exits 1; a result file that is there but cannot be
// read (truncated) exits 1 naming it instead of being left out as "not run"; a symbolic link loop
// (a seed folder or a result file linking to itself) is named with the system's reason, never an
// abort (exit 134, an uncaught std::filesystem::filesystem_error, as it was).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

const std::string refs = std::string(DEM_SOURCE_DIR) + "/reference_data/paper.yaml";
// A complete result of a preparation (1,000 spheres) shipped with the scenes.
const std::string good_result = std::string(DEM_SOURCE_DIR) + "/scenes/samples/dense_1k.h5";

dem::test::CommandResult tool(const std::string& program, const std::string& args) {
  return dem::test::run_command("'" + std::string(DEM_BINARY_DIR) + "/bin/" + program + "' " + args + " 2>&1 < /dev/null");
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// The first `bytes` bytes of the shipped result: an HDF5 file cut short.
void truncated_copy(const fs::path& to, std::size_t bytes) {
  const std::string all = dem::test::read_bytes(good_result);
  dem::test::write_text(to.string(), all.substr(0, bytes));
}

}  // namespace

TEST_CASE("validation tools: a results folder that is missing or a file exits 2 and is named", "[tools][lost]") {
  const fs::path dir = dem::test::scratch_dir("lost_inputs_folder");
  const fs::path nosuch = dir / "nosuch", file = dir / "file";
  dem::test::write_text(file.string(), "not a folder\n");
  const struct {
    std::string program, args, said;
  } cases[] = {
      {"report", "--results " + q(nosuch) + " --references '" + refs + "' --out " + q(dir / "r1"), "does not exist"},
      {"report", "--results " + q(file) + " --references '" + refs + "' --out " + q(dir / "r2"), "is not a folder"},
      {"ensemble-cycles", q(nosuch) + " " + q(dir / "e"), "does not exist"},
      {"figure-data", "figures " + q(nosuch) + " " + q(dir / "f"), "does not exist"},
      {"figure-data", "settings " + q(file), "is not a folder"},
      {"figure-data", "samples-table " + q(nosuch) + " --references '" + refs + "'", "does not exist"},
      {"figure-data", "tests-table " + q(nosuch), "does not exist"},
  };
  for (const auto& c : cases) {
    const auto r = tool(c.program, c.args);
    INFO(c.program << " " << c.args << ":\n" << r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Contains(c.said));
    CHECK_THAT(r.out, Contains(c.said == "does not exist" ? nosuch.string() : file.string()));
  }
  CHECK_FALSE(fs::exists(dir / "r1" / "index.md"));  // no report on nothing
  // A report's folder that keeps what an earlier report took from the results (study_values.json):
  // a missing --results is then allowed (the machine has not run that study), but a file still is not.
  fs::create_directories(dir / "r3");
  dem::test::write_text((dir / "r3" / "study_values.json").string(), "{\"values\": {}}\n");
  const auto r = tool("report", "--results " + q(file) + " --references '" + refs + "' --out " + q(dir / "r3"));
  CHECK(r.exit_code == 2);
}

TEST_CASE("validation tools: a results folder without a single result exits 1", "[tools][lost]") {
  const fs::path dir = dem::test::scratch_dir("lost_inputs_empty");
  fs::create_directories(dir / "results");
  const auto cycles = tool("ensemble-cycles", q(dir / "results") + " " + q(dir / "e"));
  INFO(cycles.out);
  CHECK(cycles.exit_code == 1);
  CHECK_THAT(cycles.out, Contains("no complete test result in " + (dir / "results").string()));
  const auto figures = tool("figure-data", "figures " + q(dir / "results") + " " + q(dir / "f"));
  INFO(figures.out);
  CHECK(figures.exit_code == 1);
  CHECK_THAT(figures.out, Contains("no complete result in " + (dir / "results").string()));
  CHECK_FALSE(fs::exists(dir / "f" / "values.gp"));  // no data files holding only headers
}

TEST_CASE("compare-runs: a study planned but not run draws no section and leaves the committed one", "[tools][lost]") {
  // A runs.tsv as `pipeline --plan` writes it (runs listed, none run): every mode exits 1 naming the
  // folder, and the section's folder keeps the table that was there.
  const fs::path dir = dem::test::scratch_dir("lost_inputs_planned");
  const fs::path results = dir / "results", out = dir / "section";
  fs::create_directories(results);
  fs::create_directories(out);
  dem::test::write_text((results / "runs.tsv").string(),
                        "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n"
                        "baseline\tdense\t-\tseed1/baseline_dense_prepare\t" + (results / "seed1" / "baseline_dense_prepare.h5").string() +
                        "\t-\t0\tas written\t1\n"
                        "baseline\tdense\tcompression_mu0\tseed1/dense_compression_mu0\t" + (results / "seed1" / "dense_compression_mu0.h5").string() +
                        "\tseed1/baseline_dense_prepare\t0\tas written\t1\n");
  dem::test::write_text((out / "table.md").string(), "the committed table\n");
  for (const std::string& mode : {"decisions", "critical-state", "stability", "convergence"}) {
    const auto r = tool("compare-runs", mode + " " + q(results) + " " + q(out));
    INFO(mode << ":\n" << r.out);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Contains("no finished run in " + results.string()));
  }
  const auto l = tool("compare-runs", "liquefaction " + q(out) + " " + q(results));
  INFO(l.out);
  CHECK(l.exit_code == 1);
  CHECK(dem::test::read_bytes((out / "table.md").string()) == "the committed table\n");
}

TEST_CASE("validation tools: a result file that is there but truncated is named and fails the tool", "[tools][lost]") {
  // A sample of one complete preparation (dense) and a loose one cut to 4 KiB (its HDF5 superblock
  // and little else): the loose density must not vanish in silence.
  const fs::path dir = dem::test::scratch_dir("lost_inputs_truncated");
  const fs::path results = dir / "results";
  fs::create_directories(results);
  fs::copy_file(good_result, results / "dense_prepare.h5");
  truncated_copy(results / "loose_prepare.h5", 4096);
  truncated_copy(results / "dense_test1.h5", 4096);
  const std::string loose = (results / "loose_prepare.h5").string(), test1 = (results / "dense_test1.h5").string();
  const struct {
    std::string program, args, named;
  } cases[] = {
      {"figure-data", "figures " + q(results) + " " + q(dir / "f"), loose},
      {"figure-data", "settings " + q(results), loose},
      {"figure-data", "samples-table " + q(results) + " --references '" + refs + "'", loose},
      {"figure-data", "tests-table " + q(results), test1},
      {"ensemble-cycles", q(results) + " " + q(dir / "e"), test1},
      {"report", "--results " + q(results) + " --references '" + refs + "' --out " + q(dir / "r"), loose},
  };
  for (const auto& c : cases) {
    const auto r = tool(c.program, c.args);
    INFO(c.program << " " << c.args << ":\n" << r.out);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Contains(c.named + ": cannot be read as a"));
  }
}

TEST_CASE("validation tools: a symbolic link loop is named, never an abort", "[tools][lost]") {
  // seed1/ links to itself; in a second study a result file links to itself.
  const fs::path dir = dem::test::scratch_dir("lost_inputs_loop");
  const fs::path looped = dir / "looped", file_loop = dir / "file_loop";
  fs::create_directories(looped);
  fs::create_directory_symlink("seed1", looped / "seed1");
  fs::create_directories(file_loop / "seed1");
  fs::create_symlink("dense_prepare.h5", file_loop / "seed1" / "dense_prepare.h5");
  fs::copy_file(good_result, file_loop / "seed1" / "loose_prepare.h5");
  for (const fs::path& study : {looped, file_loop}) {
    std::ofstream runs(study / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (const std::string d : {"loose", "medium", "dense"})
      runs << "-\t" << d << "\t-\tseed1/" << d << "_prepare\t/x/seed1/" << d << "_prepare.h5\t-\t0\tas written\t1\n";
  }
  const std::string seed_loop = (looped / "seed1").string(), result_loop = (file_loop / "seed1" / "dense_prepare.h5").string();
  const struct {
    std::string program, args, named;
  } cases[] = {
      {"ensemble-cycles", q(looped) + " " + q(dir / "e1"), seed_loop + ": Too many levels of symbolic links"},
      {"figure-data", "figures " + q(looped) + " " + q(dir / "f1"), seed_loop + ": Too many levels of symbolic links"},
      {"figure-data", "samples-table " + q(looped / "seed1") + " --references '" + refs + "'", "Too many levels of symbolic links"},
      {"report", "--results " + q(looped) + " --references '" + refs + "' --out " + q(dir / "r1"), seed_loop + ": Too many levels of symbolic links"},
      {"validate", "--results " + q(looped) + " --references '" + refs + "' --out " + q(dir / "v1") + " --profile quick", "seed1"},
      {"ensemble-cycles", q(file_loop) + " " + q(dir / "e2"), result_loop + ": cannot be read as a"},
      {"figure-data", "figures " + q(file_loop) + " " + q(dir / "f2"), result_loop + ": cannot be read as a"},
      {"figure-data", "settings " + q(file_loop), result_loop + ": cannot be read as a"},
      {"report", "--results " + q(file_loop) + " --references '" + refs + "' --out " + q(dir / "r2"), result_loop + ": cannot be read as a"},
      {"validate", "--results " + q(file_loop) + " --references '" + refs + "' --out " + q(dir / "v2") + " --profile quick", "missing or not complete"},
      {"compare-runs", "stability " + q(file_loop) + " " + q(dir / "c2"), ""},
  };
  for (const auto& c : cases) {
    const auto r = tool(c.program, c.args);
    INFO(c.program << " " << c.args << ":\n" << r.out);
    CHECK((r.exit_code == 1 || r.exit_code == 2));  // an abort was 134
    CHECK_THAT(r.out, !Contains("terminate called") && Contains(c.named));
  }
}
