// validate's exit status follows one rule (issue 38): 0 only when everything asked for was done and
// judged. Missing results, a sample runs.tsv lists whose folder is gone, rows not judged: 1, with
// the reason on stderr (the tables are still written). Bad arguments, a results folder that is not
// there, an --out that is not a folder: 2, with a message, never an uncaught exception.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/validate";
const std::string refs = std::string(DEM_SOURCE_DIR) + "/reference_data/paper.yaml";

dem::test::CommandResult validate(const std::string& args) { return dem::test::run_command("'" + bin + "' " + args + " 2>&1"); }

}  // namespace

TEST_CASE("validate: an --out or --results that cannot be used is a clear error, exit 2", "[validate][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_args";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  SECTION("--out /dev/null (a file, not a folder)") {
    const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("--out '/dev/null' is not a folder") != std::string::npos);
  }
  SECTION("--out under a file") {
    std::ofstream(dir / "file") << "x";
    const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / "file" / "sub").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("cannot create the folder") != std::string::npos);
  }
  SECTION("a misspelt --results folder, and --results pointing at the study file") {
    auto r = validate("--results '" + (dir / "resluts").string() + "' --references '" + refs + "' --out '" + (dir / "out").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("does not exist") != std::string::npos);
    r = validate("--results '" + std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml' --references '" + refs + "' --out '" +
                 (dir / "out").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("is not a folder") != std::string::npos);
  }
}

TEST_CASE("validate: missing results and a deleted sample make exit 1, and are listed", "[validate][cli]") {
  // A 3-seed study whose runs.tsv lists seeds 1-3; seed1/ and seed2/ are there but empty, seed3/ is gone.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_missing";
  fs::remove_all(dir);
  fs::create_directories(dir / "results" / "seed1");
  fs::create_directories(dir / "results" / "seed2");
  {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int seed = 1; seed <= 3; ++seed)
      runs << "-\tloose\t-\tseed" << seed << "/loose_prepare\t/x/seed" << seed << "/loose_prepare.h5\t-\t0\tas written\t" << seed << "\n";
  }
  const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / "out").string() +
                          "' --profile quick");
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("lists 1 sample(s) whose folder is gone: seed3") != std::string::npos);
  CHECK(r.out.find("36 result file(s) missing") != std::string::npos);  // 2 samples x 3 densities x 6 runs
  CHECK(r.out.find("row(s) not judged") != std::string::npos);
  // The tables are written all the same, and say what is missing.
  std::ifstream f(dir / "out" / "validation.json");
  const nlohmann::json j = nlohmann::json::parse(f);
  CHECK(j.at("missing_samples") == nlohmann::json::array({"seed3"}));
  CHECK(j.at("missing_results").size() == 36);
  CHECK(j.at("complete") == false);
  CHECK(j.at("samples").size() == 2);
}
