// calibrate with the largest size in parts, end to end on 64- and 125-sphere samples of two
// densities: each part runs its densities' tests only, is scored on their curves only, and has its
// own ledger and discrepancy from the first size; and a wrong parts key refused, naming it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "tiny_calibration.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

// Two densities, a curve each, the tests' friction calibrated.
void write_inputs(const fs::path& dir, const std::string& sizes) {
  dem::test::TinyCalibration{{{"dense", 0.0}, {"loose", 0.5}}, "test", 6, sizes}.write(dir);
}

// Two parts; the dense part runs 3 sets, then what `then` asks ("confirm: 1", "probe: 1"). A
// dense e0 row every packing agrees with (e0 lies in [0.3, 1.5]): a set chosen for it agrees. The
// parameter is the tests', so every set shares its e0 at a size: the surface and the discrepancy
// are exact, a sample's sd is the row's resolution (0.01, one sample a set at the small size; 2 at
// the large, so that validate judges the row there), and e0 (about 0.6) lies more than 10 of it
// from either bound: the predicted probability exceeds 0.99 anywhere. Three iterations.
dem::test::TinyCalibration one_wide_row(const std::string& then) {
  return {{{"dense", 0.0}, {"loose", 0.5}}, "test", 6,
          "sizes: [{profile: small}, {profile: large, densities: [dense], sets: 3, per_iteration: 2, " + then + "},\n"
          "        {profile: large, densities: [loose], sets: 3, per_iteration: 2}]\n",
          "[{name: wide, quantity: void_ratio_after_preparation, density: dense, reference: 0.9, check: within, "
          "tolerance: 0.6, resolution: 0.01, reason: wide, source: typed}]",
          3, 2};
}

// A fresh folder test_tmp/<name> holding `tiny`'s files, and the command line that calibrates there.
std::pair<fs::path, std::string> fresh(const std::string& name, const dem::test::TinyCalibration& tiny) {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  tiny.write(dir);
  return {dir, "cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1"};
}

// Runs `command`, which must succeed (its output shown when it does not); its output.
std::string succeeded(const std::string& command) {
  const auto r = dem::test::run_command(command + " 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  return r.out;
}

nlohmann::json posterior_in(const fs::path& dir) {
  return nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
}

}  // namespace

TEST_CASE("calibrate with the largest size in parts: each part runs and is scored on its densities only", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_parts";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_inputs(dir, "sizes: [{profile: small}, {profile: large, densities: [dense], sets: 3, per_iteration: 2},\n"
                    "        {profile: large, densities: [loose], sets: 3, per_iteration: 2}]\n");
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1";
  const auto plan = dem::test::run_command(cmd + " --plan 2>&1");
  INFO(plan.out);
  REQUIRE(plan.exit_code == 0);
  // Per set of a part: its density's test; the preparation (the parameter is the test's) shared.
  CHECK_THAT(plan.out, Catch::Contains("size large (dense) (lattice 5, 1 sample(s) a set): first iteration: 3 runs"));
  CHECK_THAT(plan.out, Catch::Contains("size large (loose) (lattice 5, 1 sample(s) a set): first iteration: 3 runs"));

  const auto run = dem::test::run_command(cmd + " 2>&1");
  INFO(run.out);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json p = posterior_in(dir);
  REQUIRE(p["sizes"].size() == 3);
  for (int k : {1, 2}) {
    const std::string density = k == 1 ? "dense" : "loose", other = k == 1 ? "loose" : "dense";
    INFO(density);
    CHECK(p["sizes"][k]["densities"] == nlohmann::json::array({density}));
    CHECK(p["sizes"][k]["sets"] == 3);
    CHECK(p["sizes"][k]["discrepancy"]["pairs"] == 3);
    // Its discrepancy covers its density's curve only.
    CHECK(p["sizes"][k]["discrepancy"]["at_posterior_mean"].contains(density + " qp"));
    CHECK_FALSE(p["sizes"][k]["discrepancy"]["at_posterior_mean"].contains(other + " qp"));
    // Its runs: its density's only, in its own folder; its own ledger.
    const fs::path results = dir / "results" / "calibration_tiny" / ("large-" + density) / "seed1";
    bool own = false, foreign = false;
    for (const auto& f : fs::directory_iterator(results)) {
      const std::string name = f.path().filename().string();
      own |= name.find("_" + density + "_triaxial.h5") != std::string::npos;
      foreign |= name.find("_" + other + "_") != std::string::npos;
    }
    CHECK(own);
    CHECK_FALSE(foreign);
    CHECK(fs::exists(dir / "report" / ("scored_sets.large-" + density + ".json")));
    // Its best set, judged on its own curve.
    CHECK(p["largest_size_parts"][k - 1]["densities"] == nlohmann::json::array({density}));
    CHECK(p["largest_size_parts"][k - 1].contains("best_set"));
  }
  CHECK_FALSE(p.contains("largest_size"));
  // With a discrepancy in every part, the posterior is the large size's.
  CHECK(p["parameters"][0].contains("first_size_only"));
  const std::string section = dem::test::read_bytes((dir / "report" / "section.md").string());
  CHECK_THAT(section, Catch::Contains("| large (dense) |") && Catch::Contains("at large (loose)"));
}

TEST_CASE("calibrate refuses a wrong parts key, naming it", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_parts_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto refusal = [&](const std::string& sizes) {
    write_inputs(dir, sizes);
    return dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml --plan 2>&1");
  };
  const auto first = refusal("sizes: [{profile: small, densities: [dense]}, {profile: large, sets: 3}]\n");
  CHECK(first.exit_code == 2);
  CHECK_THAT(first.out, Catch::Contains("sizes[0].densities") && Catch::Contains("the first size"));
  const auto twice = refusal("sizes: [{profile: small}, {profile: large, densities: [dense], sets: 3}, "
                             "{profile: large, densities: [dense, loose], sets: 3}]\n");
  CHECK_THAT(twice.out, Catch::Contains("sizes[2].densities") && Catch::Contains("'dense' is in two parts"));
  const auto mixed = refusal("sizes: [{profile: small}, {profile: large, densities: [dense], sets: 3}, {profile: large, sets: 3}]\n");
  CHECK_THAT(mixed.out, Catch::Contains("sizes[2]") && Catch::Contains("all parts of one size"));
  const auto profiles = refusal("sizes: [{profile: small}, {profile: large, densities: [dense], sets: 3}, "
                                "{profile: small, densities: [loose], sets: 3}]\n");
  CHECK_THAT(profiles.out, Catch::Contains("sizes[2].profile") && Catch::Contains("share its profile"));
  const auto unknown = refusal("sizes: [{profile: small}, {profile: large, densities: [medium], sets: 3}]\n");
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.out, Catch::Contains("densities: 'medium' is not a density of the study"));
}

TEST_CASE("calibrate confirms a part's best prediction with one more set, and says what it predicted and what the set gave", "[calibration][cli]") {
  const dem::test::TinyCalibration tiny = one_wide_row("confirm: 1");
  const auto [dir, cmd] = fresh("calibrate_parts_confirm", tiny);
  const std::string plan = succeeded(cmd + " --plan");
  CHECK_THAT(plan, Catch::Contains("size large (dense) (lattice 5, 2 sample(s) a set): all 3 iterations at most (4 sets still to score)"));
  const std::string run = succeeded(cmd);
  CHECK_THAT(run, Catch::Contains("to confirm the posterior there"));
  const nlohmann::json p = posterior_in(dir);
  const nlohmann::json& dense = p["sizes"][1];
  CHECK(dense["sets"] == 4);
  CHECK(dense["sets_at_most"] == 4);
  REQUIRE(dense["confirmed"].size() == 1);
  const nlohmann::json& c = dense["confirmed"][0];
  const double predicted = c["predicted_probability"];
  CHECK(predicted > 0.99);
  CHECK(predicted <= 1);
  REQUIRE(c["rows"].size() == 1);
  CHECK(c["rows"][0]["name"] == "wide");
  CHECK(c["rows"][0]["consistent"] == true);
  CHECK_FALSE(p["sizes"][2].contains("confirmed"));
  const std::string section = dem::test::read_bytes((dir / "report" / "section.md").string());
  CHECK_THAT(section, Catch::Contains("To confirm the posterior at large (dense): set " + c["set"].get<std::string>()) &&
                          Catch::Contains("its samples agree with 1 of the 1 rows"));
  // A part without rows has nothing to confirm: refused, naming the key.
  dem::test::TinyCalibration curves_only = tiny;
  curves_only.rows.clear();
  curves_only.write(dir);
  const auto refused = dem::test::run_command(cmd + " --plan 2>&1");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.out, Catch::Contains("sizes[1].confirm") && Catch::Contains("no scalar row"));
}

TEST_CASE("calibrate probes a part at the reach's maximum: a new set run at both sizes, its pair in the discrepancy, replayed from the ledgers",
          "[calibration][cli]") {
  // Iterations 1 and 2 run the dense part's 3 sets; iteration 3 its probe.
  const dem::test::TinyCalibration tiny = one_wide_row("probe: 1");
  const auto [dir, cmd] = fresh("calibrate_parts_probe", tiny);
  const std::string run = succeeded(cmd);
  CHECK_THAT(run, Catch::Contains("runs the new set i3p1 at the reach's maximum"));
  const nlohmann::json p = posterior_in(dir);
  // The first size ran it too (its 3 batches of 6, and the probe), and it is the dense part's fourth pair.
  CHECK(p["sizes"][0]["sets"] == 3 * 6 + 1);
  const nlohmann::json& dense = p["sizes"][1];
  CHECK(dense["sets"] == 4);
  CHECK(dense["discrepancy"]["pairs"] == 4);
  REQUIRE(dense["confirmed"].size() == 1);
  const nlohmann::json& c = dense["confirmed"][0];
  CHECK(c["set"] == "i3p1");
  CHECK(c["chosen"] == "probe");
  CHECK(c["predicted_probability"].get<double>() > 0.99);
  CHECK(c["rows"][0]["consistent"] == true);
  const nlohmann::json small_ledger = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "scored_sets.json").string()));
  bool in_small_ledger = false;
  for (const nlohmann::json& s : small_ledger["sets"]) in_small_ledger |= s["name"] == "i3p1";
  CHECK(in_small_ledger);
  const std::string section = dem::test::read_bytes((dir / "report" / "section.md").string());
  CHECK_THAT(section, Catch::Contains("set i3p1, a new set where the posterior's prediction is best (run at the first size too)"));
  // The probe is chosen again, at the same point, from the same scores: a replay runs nothing.
  fs::remove_all(dir / "results");
  const std::string replay = succeeded(cmd + " --ledger-only");
  const nlohmann::json again = posterior_in(dir);
  CHECK(again["sizes"][1]["confirmed"] == dense["confirmed"]);
  // A part without rows has no reach to probe: refused, naming the key.
  dem::test::TinyCalibration curves_only = tiny;
  curves_only.rows.clear();
  curves_only.write(dir);
  const auto refused = dem::test::run_command(cmd + " --plan 2>&1");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.out, Catch::Contains("sizes[1].probe") && Catch::Contains("no scalar row"));
}

TEST_CASE("calibrate runs the sets named for a part once the iterations end: in its discrepancy, planned alone, replayed from the ledgers",
          "[calibration][cli]") {
  // The dense part chooses its 3 sets in iterations 1 and 2, among the sets scored by then: a set
  // of iteration 3 is not among them, so the part runs it after the iterations.
  const dem::test::TinyCalibration tiny = one_wide_row("named: [i3s004]");
  const auto [dir, cmd] = fresh("calibrate_parts_named", tiny);
  const std::string run = succeeded(cmd);
  CHECK_THAT(run, Catch::Contains("after the iterations: size large (dense) runs i3s004, named in the calibration file"));
  CHECK_THAT(run, Catch::Contains("iteration 3 with the named sets"));
  const nlohmann::json p = posterior_in(dir);
  const nlohmann::json& dense = p["sizes"][1];
  CHECK(p["sizes"][0]["sets"] == 3 * 6);  // no new set at the first size
  CHECK(dense["sets"] == 4);
  CHECK(dense["discrepancy"]["pairs"] == 4);
  REQUIRE(dense["confirmed"].size() == 1);
  CHECK(dense["confirmed"][0]["set"] == "i3s004");
  CHECK(dense["confirmed"][0]["chosen"] == "named");
  CHECK(dense["confirmed"][0]["rows"][0]["consistent"] == true);
  // What its 2 samples gave: e0 of the dense packing, inside the row's region [0.3, 1.5].
  CHECK(dense["confirmed"][0]["rows"][0]["samples"] == 2);
  CHECK(dense["confirmed"][0]["rows"][0]["mean"].get<double>() > 0.3);
  CHECK(dense["confirmed"][0]["rows"][0]["mean"].get<double>() < 1.5);
  const std::string section = dem::test::read_bytes((dir / "report" / "section.md").string());
  CHECK_THAT(section, Catch::Contains("set i3s004, a set of the first size the calibration file names"));
  // Another name added later: the plan replays every iteration and the first named set, and prices the new one alone.
  dem::test::TinyCalibration more = one_wide_row("named: [i3s004, i3s005]");
  more.write(dir);
  const std::string plan = succeeded(cmd + " --plan");
  CHECK_THAT(plan, Catch::Contains("every iteration replays from the ledgers and the finished runs; then the sets named for a size run"));
  CHECK_THAT(plan, Catch::Contains("size large (dense) (lattice 5, 2 sample(s) a set): the named sets: "));
  CHECK_THAT(plan, Catch::Contains("(1 sets still to score)"));
  // The first name replays from the ledgers: the same prediction, the same verdict, nothing run.
  tiny.write(dir);
  fs::remove_all(dir / "results");
  const std::string replay = succeeded(cmd + " --ledger-only");
  const nlohmann::json again = posterior_in(dir);
  CHECK(again["sizes"][1]["confirmed"] == dense["confirmed"]);
  // The first size's own posterior is the one without the named set, which has no effect there.
  one_wide_row("confirm: 0").write(dir);
  const std::string without = succeeded(cmd + " --ledger-only");
  const nlohmann::json alone = posterior_in(dir);
  CHECK(alone["parameters"][0]["first_size_only"] == again["parameters"][0]["first_size_only"]);
  CHECK(alone["sizes"][1]["sets"] == 3);
  // A name the calibration cannot draw is refused before anything runs, naming the key; a set
  // drawn but not scored (an engine stop in one of its runs), once the iterations end.
  one_wide_row("named: [i4s001]").write(dir);
  const auto refused = dem::test::run_command(cmd + " --plan 2>&1");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.out, Catch::Contains("sizes[1].named: 'i4s001' is not a set this calibration can draw"));
  one_wide_row("named: [i3s4]").write(dir);  // the set is i3s004
  CHECK_THAT(dem::test::run_command(cmd + " --plan 2>&1").out, Catch::Contains("sizes[1].named: 'i3s4' is not a set this calibration can draw"));
  one_wide_row("named: [i3s006]").write(dir);
  const auto unscored = dem::test::run_command(cmd + " --ledger-only 2>&1");
  CHECK(unscored.exit_code == 2);
  CHECK_THAT(unscored.out, Catch::Contains("sizes[1].named: 'i3s006' is not a set small scored in the 3 iterations"));
}
