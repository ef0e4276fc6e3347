// calibrate across two sizes end to end on 64- and 125-sphere samples: every set at the small size,
// the chosen few at the large one, a discrepancy between them; replayed from its two ledgers with
// nothing run; its ledgers taken, stamped, when another engine scored them on the same scenes; and
// its sizes: key refused where it is wrong, naming the key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "tiny_calibration.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

}  // namespace

TEST_CASE("calibrate across two sizes: the chosen sets run at the large size, a discrepancy joins them, a replay runs nothing",
          "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_sizes";
  fs::remove_all(dir);
  fs::create_directories(dir);
  dem::test::TinyCalibration{{{"dense", 0.0}}, "", 8, "sizes: [{profile: small}, {profile: large, sets: 4, per_iteration: 2}]\n"}.write(dir);
  // An engine that calls itself another (its --source-hash), so that its ledgers are another engine's.
  std::ofstream(dir / "other_dem") << "#!/bin/sh\nif [ \"$1\" = --source-hash ]; then echo 'feedfacefeedface schema 4'; exit 0; fi\n"
                                   << "exec '" << bin << "dem' \"$@\"\n";
  fs::permissions(dir / "other_dem", fs::perms::owner_all);
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1";

  const auto plan = dem::test::run_command(cmd + " --plan 2>&1");
  INFO(plan.out);
  REQUIRE(plan.exit_code == 0);
  CHECK_THAT(plan.out, Catch::Contains("size small (lattice 4, 1 sample(s) a set): first iteration: 9 runs"));
  CHECK_THAT(plan.out, Catch::Contains("size large (lattice 5, 1 sample(s) a set): first iteration: 3 runs"));
  CHECK_THAT(plan.out, Catch::Contains("(4 sets still to score)"));

  const auto first = dem::test::run_command(cmd + " --dem ./other_dem 2>&1");
  INFO(first.out);
  REQUIRE(first.exit_code == 0);
  const nlohmann::json p = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
  REQUIRE(p["sizes"].size() == 2);
  CHECK(p["sizes"][0]["sets"] == 16);
  CHECK(p["sizes"][1]["sets"] == 4);  // 2 per iteration, 4 at most
  CHECK(p["sizes"][0]["stamp"]["spheres"] == 64);
  CHECK(p["sizes"][1]["stamp"]["spheres"] == 125);
  // Four pairs of one parameter: a linear discrepancy (1 + 3 pairs), and the posterior is the large size's.
  CHECK(p["sizes"][1]["discrepancy"]["pairs"] == 4);
  CHECK(p["sizes"][1]["discrepancy"]["form"] == "linear");
  CHECK(p["sizes"][1]["discrepancy"]["at_posterior_mean"]["qp"]["shift"].size() == 2);
  CHECK(p["parameters"][0].contains("first_size_only"));
  // The large size's sets are sets the small size scored, by name.
  std::set<std::string> small;
  for (const auto& s : p["sets"]) small.insert(s["name"].get<std::string>());
  REQUIRE(p["largest_size"]["sets"].size() == 4);
  for (const auto& s : p["largest_size"]["sets"]) CHECK(small.count(s["name"].get<std::string>()) == 1);
  CHECK(fs::exists(dir / "report" / "scored_sets.json"));
  CHECK(fs::exists(dir / "report" / "scored_sets.large.json"));
  const std::string section = dem::test::read_bytes((dir / "report" / "section.md").string());
  CHECK_THAT(section, Catch::Contains("What the larger size changed") && Catch::Contains("80 % of the 20 sets run were run at small"));

  // Without the small size's ledger but with every run finished: --ledger-only scores the sets on
  // their runs and runs nothing (the ledger put back after).
  fs::rename(dir / "report" / "scored_sets.json", dir / "scored_sets.kept");
  const auto from_runs = dem::test::run_command(cmd + " --dem ./other_dem --ledger-only 2>&1");
  fs::rename(dir / "scored_sets.kept", dir / "report" / "scored_sets.json");
  {
    INFO(from_runs.out);
    CHECK(from_runs.exit_code == 0);
    CHECK(from_runs.out.find("] started ") == std::string::npos);
  }

  // Without the runs' results, with this engine: the ledgers were scored by another engine, so
  // --ledger-only alone finds no score and refuses to run; with --ledger-engine it replays every set
  // (the scenes are the same), runs nothing, gives the same posterior, and says which engine scored it.
  fs::remove_all(dir / "results");
  const auto refused = dem::test::run_command(cmd + " --ledger-only 2>&1");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.out, Catch::Contains("--ledger-only") && Catch::Contains("scored_sets.json holds no score of set i1s001"));
  const auto replay = dem::test::run_command(cmd + " --ledger-only --ledger-engine 2>&1");
  INFO(replay.out);
  REQUIRE(replay.exit_code == 0);
  CHECK(replay.out.find("] started ") == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "results" / "calibration_tiny" / "small" / "runs.tsv"));
  nlohmann::json again = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
  CHECK(again["sizes"][0]["sets_scored_by_another_engine"]["sets"] == 16);
  CHECK(again["sizes"][0]["sets_scored_by_another_engine"]["engine"] == "feedfacefeedface schema 4");
  CHECK(again["sizes"][1]["sets_scored_by_another_engine"]["sets"] == 4);
  CHECK_THAT(dem::test::read_bytes((dir / "report" / "section.md").string()), Catch::Contains("scored by engine feedfacefeedface schema 4"));
  CHECK(again["parameters"] == p["parameters"]);
  CHECK(again["sets"] == p["sets"]);
  CHECK(again["largest_size"] == p["largest_size"]);
  CHECK(again["core_seconds"].get<double>() == Approx(p["core_seconds"].get<double>()).epsilon(1e-9));
}

TEST_CASE("calibrate refuses a wrong sizes: key, naming it", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_sizes_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto refusal = [&](const std::string& sizes, const std::string& extra = "") {
    dem::test::TinyCalibration{{{"dense", 0.0}}, "", 8, sizes}.write(dir);
    return dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml --plan" + extra + " 2>&1");
  };
  const auto one = refusal("sizes: [{profile: small}]\n");
  CHECK(one.exit_code == 2);
  CHECK_THAT(one.out, Catch::Contains("sizes") && Catch::Contains("at least 2"));
  const auto first_sets = refusal("sizes: [{profile: small, sets: 3}, {profile: large, sets: 3}]\n");
  CHECK_THAT(first_sets.out, Catch::Contains("sizes[0].sets") && Catch::Contains("every set runs"));
  const auto few = refusal("sizes: [{profile: small}, {profile: large, sets: 2}]\n");
  CHECK_THAT(few.out, Catch::Contains("sizes[1].sets") && Catch::Contains("3"));
  const auto twice = refusal("sizes: [{profile: small}, {profile: small, sets: 3}]\n");
  CHECK_THAT(twice.out, Catch::Contains("sizes[1].profile") && Catch::Contains("names two sizes"));
  const auto unknown = refusal("sizes: [{profile: small}, {profile: huge, sets: 3}]\n");
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.out, Catch::Contains("sizes[1].profile") && Catch::Contains("huge"));
  const auto both = refusal("sizes: [{profile: small}, {profile: large, sets: 3}]\n", " --profile small");
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.out, Catch::Contains("--profile small is given"));
}
