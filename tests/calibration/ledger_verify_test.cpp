// calibrate --ledger-verify and calibrate rekey end to end on 64-sphere samples: a ledger whose runs hash otherwise
// (as after a change of the scenes' text) is taken once its verification sets, run again, score
// bit for bit as it has them, and is written back so that the next call finds it by hash; a ledger
// scored on other physics (another preparation friction) is refused, naming the set, and kept. A
// ledger keyed on its reference files' bytes (schema 1) is rekeyed when the files it was scored
// against parse as today's, and refused when they are not those files or parse otherwise.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "core/content_hash.hpp"
#include "engine/io/io_test_support.hpp"
#include "tiny_calibration.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

// One density prepared at `friction`, the tests' friction calibrated, 4 sets an iteration.
void write_inputs(const fs::path& dir, double friction) {
  dem::test::TinyCalibration{{{"dense", friction}}, "test", 4, ""}.write(dir);
}

int started_runs(const std::string& out) {
  const std::regex started(R"(\] started )");
  return static_cast<int>(std::distance(std::sregex_iterator(out.begin(), out.end(), started), std::sregex_iterator()));
}

}  // namespace

TEST_CASE("calibrate --ledger-verify takes a ledger whose runs hash otherwise once its spot checks score bit for bit",
          "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "ledger_verify";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_inputs(dir, 0.0);
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1";
  const auto first = dem::test::run_command(cmd + " 2>&1");
  INFO(first.out);
  REQUIRE(first.exit_code == 0);
  const nlohmann::json p = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
  const fs::path ledger_file = dir / "report" / "scored_sets.json";

  // Every entry's runs made to hash otherwise, as after a change of the scenes' text; no results kept.
  nlohmann::json ledger = nlohmann::json::parse(dem::test::read_bytes(ledger_file.string()));
  REQUIRE(ledger["sets"].size() == 8);
  for (auto& s : ledger["sets"]) s["run_hashes"] = {"0000000000000000"};
  std::ofstream(ledger_file) << ledger.dump(1);
  const std::string tampered = dem::test::read_bytes(ledger_file.string());
  fs::remove_all(dir / "results");

  SECTION("the same physics: two sets run again, six taken, written back with this plan's hashes") {
    const auto verified = dem::test::run_command(cmd + " --ledger-verify 2 2>&1");
    INFO(verified.out);
    REQUIRE(verified.exit_code == 0);
    CHECK_THAT(verified.out, Catch::Contains("8 of the 8 sets of report/scored_sets.json hash otherwise here") &&
                                 Catch::Contains("2 of them run again first (i1s001, i2s001)"));
    // Only the two sets' runs: one preparation (the parameter is the test's) and a test each.
    CHECK(started_runs(verified.out) == 3);
    const nlohmann::json q = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
    CHECK(q["sets_taken_after_verification"]["sets"] == 6);
    CHECK_THAT(q["sets_taken_after_verification"]["verified_by"].get<std::string>(),
               Catch::Contains("2 of the ledger's 8 such sets (i1s001, i2s001)"));
    CHECK(q["sets"] == p["sets"]);
    CHECK(q["parameters"] == p["parameters"]);
    CHECK_THAT(dem::test::read_bytes((dir / "report" / "section.md").string()), Catch::Contains("6 of them were scored by engine"));
    // The tampered ledger is kept aside; the new one is found by hash: a replay runs nothing.
    CHECK(dem::test::read_bytes((dir / "report" / "scored_sets.kept-1.json").string()) == tampered);
    fs::remove_all(dir / "results");
    const auto replay = dem::test::run_command(cmd + " --ledger-only 2>&1");
    INFO(replay.out);
    REQUIRE(replay.exit_code == 0);
    CHECK(started_runs(replay.out) == 0);
    const nlohmann::json r = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
    CHECK(r["sets"] == p["sets"]);
    CHECK(r["sets_taken_after_verification"]["sets"] == 6);
  }

  SECTION("other physics (the preparation's friction 0.05): refused, naming the set, the ledger kept as it was") {
    write_inputs(dir, 0.05);
    const auto refused = dem::test::run_command(cmd + " --ledger-verify 1 2>&1");
    INFO(refused.out);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Contains("--ledger-verify: set i1s001 of report/scored_sets.json, run again here, does not score "
                                            "as the ledger has it (qp at point 1: "));
    CHECK(dem::test::read_bytes(ledger_file.string()) == tampered);
  }

  SECTION("with --ledger-only: refused, it would run sets") {
    const auto refused = dem::test::run_command(cmd + " --ledger-verify 1 --ledger-only 2>&1");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Contains("--ledger-verify runs sets, --ledger-only runs none"));
  }
}

TEST_CASE("calibrate rekey: a ledger keyed on its reference files' bytes is taken again after a comment, not after a change",
          "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "ledger_rekey";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_inputs(dir, 0.0);
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "calibrate' ";
  const auto first = dem::test::run_command(cmd + "cal.yaml -j 2 --threads 1 2>&1");
  INFO(first.out);
  REQUIRE(first.exit_code == 0);
  const nlohmann::json p = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
  // The references it was scored against, kept in then/; today's gain a comment; a third copy
  // differs in one point's sd.
  fs::create_directories(dir / "then");
  fs::create_directories(dir / "other");
  for (const char* f : {"refs.yaml", "curve.csv"}) fs::copy_file(dir / f, dir / "then" / f), fs::copy_file(dir / f, dir / "other" / f);
  std::ofstream(dir / "other" / "curve.csv") << "strain_3,q_over_p,sd\n0.002,0.8,0.2\n0.008,0.9,0.1\n";
  const std::string refs = dem::test::read_bytes((dir / "refs.yaml").string());
  std::ofstream(dir / "refs.yaml") << "# a comment\n" << refs;
  // The ledger as one written before keys: schema 1, the hash of the files' bytes.
  const auto bytes_hash = [&](const char* folder) {
    return dem::content_hash(dem::test::read_bytes((dir / folder / "refs.yaml").string()) + dem::test::read_bytes((dir / folder / "curve.csv").string()));
  };
  const fs::path ledger_file = dir / "report" / "scored_sets.json";
  nlohmann::json ledger = nlohmann::json::parse(dem::test::read_bytes(ledger_file.string()));
  ledger["schema"] = 1;
  ledger.erase("references_key");
  const auto write_schema_1 = [&](const char* folder) {
    ledger["references_hash"] = bytes_hash(folder);
    std::ofstream(ledger_file) << ledger.dump(1);
  };
  write_schema_1("then");
  fs::remove_all(dir / "results");
  const auto unkeyed = dem::test::run_command(cmd + "cal.yaml --ledger-only 2>&1");
  CHECK(unkeyed.exit_code == 2);  // the comment changed the bytes: no set is taken

  SECTION("the files it was scored against, parsing as today's: rekeyed, and a replay runs nothing") {
    const auto rekeyed = dem::test::run_command(cmd + "rekey cal.yaml --references-then then/refs.yaml 2>&1");
    INFO(rekeyed.out);
    REQUIRE(rekeyed.exit_code == 0);
    CHECK_THAT(rekeyed.out, Catch::Contains("8 sets rekeyed"));
    const auto replay = dem::test::run_command(cmd + "cal.yaml --ledger-only 2>&1");
    INFO(replay.out);
    REQUIRE(replay.exit_code == 0);
    CHECK(started_runs(replay.out) == 0);
    CHECK(nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()))["sets"] == p["sets"]);
  }
  SECTION("files that are not those it was scored against: refused") {
    const auto refused = dem::test::run_command(cmd + "rekey cal.yaml --references-then refs.yaml 2>&1");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Contains("give the reference files it was scored against"));
  }
  SECTION("the files it was scored against, parsing otherwise (one sd): refused, the ledger kept") {
    write_schema_1("other");
    const std::string before = dem::test::read_bytes(ledger_file.string());
    const auto refused = dem::test::run_command(cmd + "rekey cal.yaml --references-then other/refs.yaml 2>&1");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Contains("do not parse the same"));
    CHECK(dem::test::read_bytes(ledger_file.string()) == before);
  }
}
