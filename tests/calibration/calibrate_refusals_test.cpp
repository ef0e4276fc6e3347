// The calibrate tool against hostile input, end to end on 64-sphere samples: what it refuses
// before anything runs, what it keeps, and what it never reports as a result.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "io/file_lock.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

std::string read(const fs::path& p) { return dem::test::read_bytes(p.string()); }

// A folder with a one-density, one-test study of 64 spheres (`seeds` samples), a calibration of
// the test's friction (`extra`: more calibration keys) and the reference file `refs`.
fs::path tiny(const std::string& name, int seeds, const std::string& refs, const std::string& extra = "") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string src = DEM_SOURCE_DIR;
  std::ofstream(dir / "study.yaml") << "name: tiny\noutput: results\npreparation: " << src << "/scenes/prepare_dense.yaml\n"
                                    << "densities: [{name: dense, friction: 0.0}]\n"
                                    << "tests: [{name: triaxial, scene: " << src << "/scenes/tests/triaxial_drained.yaml, "
                                    << "set: {\"stages[1].until.strain\": 0.002}}]\n"
                                    << "profiles: {quick: {lattice: 4, seeds: " << seeds << "}}\n";
  std::ofstream(dir / "refs.yaml") << refs;
  std::ofstream(dir / "cal.yaml") << "name: tiny\nstudy: study.yaml\nreferences: refs.yaml\nreport: report\n"
                                  << "parameters: [{name: friction, keys: material.friction, uniform: [0.1, 0.9]}]\n"
                                  << "batch: 2\nmin_iterations: 1\nmax_iterations: 1\n"
                                  << extra;
  return dir;
}

dem::test::CommandResult calibrate(const fs::path& dir, const std::string& args = "") {
  return dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 1 --threads 1 " + args + " 2>&1");
}

}  // namespace

TEST_CASE("calibrate: a posterior with no finite weight is an error, never a result", "[calibration][cli]") {
  // One sample, a bound of e0 no packing reaches (e0 >= 5), no tolerance and no resolution: every
  // set's chi^2 is the distance over an sd of 0, infinite, so no set weighs anything.
  const fs::path dir = tiny("calibrate_no_weight", 1,
                            "source: typed\nrows: rows.yaml\n");
  std::ofstream(dir / "rows.yaml") << "source: typed\nrows:\n"
                                   << "  - {name: far, quantity: void_ratio_after_preparation, density: dense, reference: 5.0, "
                                      "check: at_least, reason: none, source: typed}\n";
  const auto r = calibrate(dir);
  INFO(r.out);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains("no parameter set has a finite weight") && Catch::Contains("'far' has chi^2 inf") &&
                        Catch::Contains("refs.yaml"));
  CHECK_FALSE(fs::exists(dir / "report" / "posterior.json"));
  // calibrate variant has nothing to print from.
  const auto v = dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' variant cal.yaml 2>&1");
  CHECK(v.exit_code != 0);
}

TEST_CASE("calibrate: two calibrations on one report folder at once: the second is refused before it runs anything", "[calibration][cli]") {
  const fs::path dir = tiny("calibrate_locked", 1, "source: typed\ncurves: [{name: qp, file: c.csv, x: strain_3, y: q_over_p, "
                                                   "density: dense, test: triaxial}]\n");
  std::ofstream(dir / "c.csv") << "strain_3,q_over_p,sd\n0.001,0.5,0.1\n";
  fs::create_directories(dir / "report");
  std::ofstream(dir / "report" / "posterior.json") << "{\"kept\": true}\n";
  {
    // This process stands for a calibration that holds the folder (its lock, as calibrate takes it).
    const dem::FileLock held((dir / "report" / ".calibrate.lock").string());
    REQUIRE(held.held());
    const auto r = calibrate(dir);
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("another calibrate is running in") && Catch::Contains("report") &&
                          Catch::Contains("nothing was run"));
    CHECK_FALSE(fs::exists(dir / "results"));  // no run planned, written or started
    CHECK(read(dir / "report" / "posterior.json") == "{\"kept\": true}\n");
    const auto plan = calibrate(dir, "--plan");  // --plan writes nothing: it needs no lock
    INFO(plan.out);
    CHECK(plan.exit_code == 0);
  }
  CHECK_FALSE(fs::exists(dir / "report" / ".calibrate.lock"));  // its holder removed it when it let go
}

TEST_CASE("calibrate: the ledger is keyed on the references as parsed, and a ledger of other references is kept aside", "[calibration][cli]") {
  const fs::path dir = tiny("calibrate_ledger_key", 1, "source: typed\ncurves: [{name: qp, file: c.csv, x: strain_3, y: q_over_p, "
                                                      "density: dense, test: triaxial}]\n");
  std::ofstream(dir / "c.csv") << "strain_3,q_over_p,sd\n0.001,0.5,0.1\n";
  const auto first = calibrate(dir);
  INFO(first.out);
  REQUIRE(first.exit_code == 0);
  const std::string ledger = read(dir / "report" / "scored_sets.json");
  REQUIRE(nlohmann::json::parse(ledger)["sets"].size() == 2);

  // A comment in each file, a key moved, a number written another way: the same references. With
  // the runs' results out of reach, the plan takes both sets from the ledger.
  std::ofstream(dir / "refs.yaml") << "# the lab's curve\nsource: typed\ncurves: [{file: c.csv, name: qp, x: strain_3, y: q_over_p, "
                                      "density: dense, test: triaxial}]\n";
  std::ofstream(dir / "c.csv") << "# measured on 3 May\nstrain_3,q_over_p,sd\n1e-3,0.50,0.1\n";
  fs::rename(dir / "results", dir / "results.away");
  const auto plan = calibrate(dir, "--plan");
  INFO(plan.out);
  CHECK_THAT(plan.out, Catch::Contains("holds 2 set(s); 2 taken so far"));
  CHECK_THAT(plan.out, Catch::Contains("(0 sets still to score)"));
  {  // A forged chi^2 (the set's and its row's, to agree with each other) is refused, naming the set.
    nlohmann::json forged = nlohmann::json::parse(ledger);
    forged["sets"][0]["misfit"]["chi2"] = 0.0;
    forged["sets"][0]["misfit"]["rows"][0]["chi2"] = 0.0;
    std::ofstream(dir / "report" / "scored_sets.json") << forged.dump(1);
    const auto refused = calibrate(dir, "--plan");
    INFO(refused.out);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Contains("scored_sets.json: set i1s001: its score does not follow from its values"));
    std::ofstream(dir / "report" / "scored_sets.json") << ledger;
  }
  fs::rename(dir / "results.away", dir / "results");

  // Another reference value: the ledger's scores do not hold; it is kept aside, whole, not lost.
  std::ofstream(dir / "c.csv") << "strain_3,q_over_p,sd\n0.001,0.6,0.1\n";
  const auto other_plan = calibrate(dir, "--plan");
  CHECK_THAT(other_plan.out, Catch::Contains("holds 2 set(s) scored against other references: none is taken"));
  const auto other = calibrate(dir);
  INFO(other.out);
  REQUIRE(other.exit_code == 0);
  CHECK_THAT(other.out, Catch::Contains("kept as") && Catch::Contains("scored_sets.kept-1.json"));
  CHECK(read(dir / "report" / "scored_sets.kept-1.json") == ledger);
  CHECK(read(dir / "report" / "scored_sets.json") != ledger);
  // Started again with the same references: the new ledger holds every set it scored; nothing more is kept aside.
  const auto again = calibrate(dir);
  INFO(again.out);
  REQUIRE(again.exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "report" / "scored_sets.kept-2.json"));
  // The calibration file now allows 3 iterations: its set is of an unfinished calibration, and
  // calibrate variant says what is missing.
  std::string cal = read(dir / "cal.yaml");
  cal.replace(cal.find("max_iterations: 1"), 17, "max_iterations: 3");
  std::ofstream(dir / "cal.yaml") << cal;
  const auto v = dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' variant cal.yaml 2>&1 >/dev/null");
  INFO(v.out);
  CHECK_THAT(v.out, Catch::Contains("warning:") && Catch::Contains("unfinished calibration: 1 of at most 3 iterations done, up to 2 "
                                                                   "more (4 sets) still to run"));
}

TEST_CASE("calibrate: a parameter's keys obey a study variant's rules, and a scene error names the calibration's set", "[calibration][cli]") {
  const std::string refs = "source: typed\ncurves: [{name: qp, file: c.csv, x: strain_3, y: q_over_p, density: dense, test: triaxial}]\n";
  const auto plan_with = [&](const std::string& name, int seeds, const std::string& parameter) {
    const fs::path dir = tiny(name, seeds, refs);
    std::ofstream(dir / "c.csv") << "strain_3,q_over_p,sd\n0.001,0.5,0.1\n";
    std::ofstream(dir / "cal.yaml") << "name: tiny\nstudy: study.yaml\nreferences: refs.yaml\nreport: report\n"
                                    << "parameters: [" << parameter << "]\nbatch: 2\nmin_iterations: 1\nmax_iterations: 1\n";
    return calibrate(dir, "--plan");
  };
  // `name` is the pipeline's (the runs' names), as in a study's variant.
  const auto named = plan_with("calibrate_key_name", 1, "{name: n, keys: name, values: [a, b]}");
  INFO(named.out);
  CHECK(named.exit_code == 2);
  CHECK_THAT(named.out, Catch::Contains("cal.yaml: parameters[0] (n): keys: 'name' is set by the pipeline"));
  // The seed of a 2-sample ensemble is the study's seeds' to choose.
  const auto seed = plan_with("calibrate_key_seed", 2, "{name: s, keys: particles.lattice.seed, applies_to: prepare, values: [3, 4]}");
  INFO(seed.out);
  CHECK(seed.exit_code == 2);
  CHECK_THAT(seed.out, Catch::Contains("cal.yaml: parameters[0] (s): keys: 'particles.lattice.seed'") &&
                           Catch::Contains("a variant cannot set the seed of an ensemble"));
  // A value the engine refuses (friction above 10): the error names the calibration file, the set
  // and its value, not a list of variants the user never wrote.
  const auto range = plan_with("calibrate_key_range", 1, "{name: friction, keys: material.friction, uniform: [5, 20]}");
  INFO(range.out);
  CHECK(range.exit_code == 2);
  CHECK_THAT(range.out, Catch::Contains("cal.yaml: set i1s001 (friction = 12.5)") && Catch::Contains("material.friction"));
  CHECK_THAT(range.out, !Catch::Contains("variants["));
}
