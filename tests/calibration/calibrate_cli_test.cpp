// The calibrate tool end to end on 64-sphere samples: it plans, runs two iterations, writes its
// posterior, and, started again, replays itself: every run reused and the same posterior.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("calibrate runs, writes its posterior, and replays itself from its runs", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string src = DEM_SOURCE_DIR;
  std::ofstream(dir / "study.yaml") << "name: tiny\noutput: results\npreparation: " << src << "/scenes/prepare_dense.yaml\n"
                                    << "densities: [{name: dense, friction: 0.0}]\n"
                                    << "tests: [{name: triaxial, scene: " << src << "/scenes/tests/triaxial_drained.yaml, "
                                    << "set: {\"stages[1].until.strain\": 0.01}}]\n"
                                    << "profiles: {quick: {lattice: 4, seeds: 1}}\n";
  // A typed curve (q/p of 64 spheres is whatever it is: the test checks the mechanism, not a value).
  std::ofstream(dir / "curve.csv") << "strain_3,q_over_p,sd\n0.002,0.8,0.1\n0.008,0.9,0.1\n";
  std::ofstream(dir / "refs.yaml") << "source: typed\ncurves: [{name: qp, file: curve.csv, x: strain_3, y: q_over_p, "
                                   << "density: dense, test: triaxial}]\n";
  std::ofstream(dir / "cal.yaml") << "name: tiny\nstudy: study.yaml\nreferences: refs.yaml\nreport: report\n"
                                  << "parameters: [{name: friction, keys: material.friction, uniform: [0.1, 0.9]}]\n"
                                  << "batch: 3\nmin_iterations: 2\nmax_iterations: 2\n";
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1";
  const auto plan = dem::test::run_command(cmd + " --plan 2>&1");
  INFO(plan.out);
  REQUIRE(plan.exit_code == 0);
  CHECK_THAT(plan.out, Catch::Contains("first iteration: 4 runs (1 shared by every set, 3 for its sets still to run)"));
  CHECK_THAT(plan.out, Catch::Contains("all 2 iterations at most (6 sets still to score)"));
  const auto particle_steps = [](const std::string& out, const std::string& line) {  // the figure after `line`
    const std::size_t at = out.find(line);
    return at == std::string::npos ? std::string("(no line)") : out.substr(at + line.size(), out.find(" particle-steps", at) - at - line.size());
  };
  // With nothing run, the first iteration costs the shared run and 3 sets' own runs, all 2
  // iterations the shared run and 6 sets' own runs.
  const std::string first_iteration = particle_steps(plan.out, "for its sets still to run), ");
  CHECK(std::stod(particle_steps(plan.out, "(6 sets still to score): ")) > std::stod(first_iteration));
  CHECK_FALSE(fs::exists(dir / "report" / "posterior.json"));

  const auto first = dem::test::run_command(cmd + " 2>&1");
  INFO(first.out);
  REQUIRE(first.exit_code == 0);
  const nlohmann::json p = nlohmann::json::parse(read(dir / "report" / "posterior.json"));
  REQUIRE(p["sets"].size() == 6);
  double total = 0;
  for (const auto& s : p["sets"]) total += s["weight"].get<double>();
  CHECK(total == Approx(1));
  const auto& f = p["parameters"][0];
  CHECK(f["lower_95"].get<double>() <= f["median"].get<double>());
  CHECK(f["median"].get<double>() <= f["upper_95"].get<double>());
  CHECK(f["lower_95"].get<double>() >= 0.1);
  CHECK(f["upper_95"].get<double>() <= 0.9);
  CHECK(p["iterations"].size() == 2);
  // The report was written after the first iteration too (the posterior so far), once; the final
  // one says why it stopped.
  std::size_t so_far = 0;
  for (std::size_t at = first.out.find("the posterior so far"); at != std::string::npos; at = first.out.find("the posterior so far", at + 1)) ++so_far;
  CHECK(so_far == 1);
  CHECK_THAT(p["stop_reason"].get<std::string>(), !Catch::Contains("still iterating"));
  CHECK(fs::exists(dir / "report" / "section.md"));
  CHECK(fs::exists(dir / "report" / "curve_1.dat"));
  // The manifest lists every set's runs (what the stamp and compare-runs read).
  const std::string manifest = read(dir / "results" / "calibration_tiny" / "quick" / "runs.tsv");
  CHECK_THAT(manifest, Catch::Contains("i1s001\tdense\ttriaxial") && Catch::Contains("i2s003\tdense\ttriaxial"));
  CHECK(p["stamp"]["spheres"] == 64);

  // Again: the same draws, every run reused (no "started"), the same posterior.
  const std::string before = read(dir / "report" / "posterior.json");
  const auto again = dem::test::run_command(cmd + " 2>&1");
  INFO(again.out);
  REQUIRE(again.exit_code == 0);
  CHECK(again.out.find("] started ") == std::string::npos);
  CHECK(read(dir / "report" / "posterior.json") == before);
  // An iteration that ran nothing new leaves the finished report as it is until the end.
  CHECK(again.out.find("the posterior so far") == std::string::npos);

  // On a machine without the runs' results (another session): every set's score comes from the
  // ledger beside the report, nothing runs, and the posterior is the same but for the recorded
  // cost, which is summed set by set (the same to rounding) and the count of sets from the ledger.
  fs::remove_all(dir / "results");
  const auto plan_again = dem::test::run_command(cmd + " --plan 2>&1");
  INFO(plan_again.out);
  CHECK_THAT(plan_again.out, Catch::Contains("every iteration replays from the ledgers and the finished runs: nothing to run"));
  CHECK_THAT(plan_again.out, Catch::Contains("holds 6 set(s); 6 taken so far"));
  CHECK_THAT(plan_again.out, Catch::Contains("all 2 iterations at most (0 sets still to score): 0 particle-steps"));
  // The throughput: the one the ledger's runs recorded, none of them being here.
  CHECK_THAT(plan_again.out, Catch::Contains("recorded by the runs of the ledger's scored sets"));
  {  // Without the ledger's second iteration: the first replays from the ledger; the second's 3 sets
     // are still to score, on the shared run (not here) and 3 sets' own runs: what the plan's
     // iteration 2 costs.
    nlohmann::json ledger = nlohmann::json::parse(read(dir / "report" / "scored_sets.json"));
    const std::string saved = ledger.dump();
    nlohmann::json first_only = nlohmann::json::array();
    for (const auto& s : ledger["sets"])
      if (s["name"].get<std::string>().rfind("i1", 0) == 0) first_only.push_back(s);
    REQUIRE(first_only.size() == 3);
    ledger["sets"] = first_only;
    std::ofstream(dir / "report" / "scored_sets.json") << ledger.dump();
    const auto part = dem::test::run_command(cmd + " --plan 2>&1");
    INFO(part.out);
    CHECK_THAT(part.out, Catch::Contains("iteration 1 replays from the ledgers and the finished runs"));
    CHECK_THAT(part.out, Catch::Contains("iteration 2: 4 runs (1 shared by every set, 3 for its sets still to run)"));
    // (Its sets' values differ from the first iteration's, and so may their runs' estimated cost.)
    CHECK(particle_steps(part.out, "(3 sets still to score): ") == particle_steps(part.out, "for its sets still to run), "));
    std::ofstream(dir / "report" / "scored_sets.json") << saved;
  }
  const auto resumed = dem::test::run_command(cmd + " 2>&1");
  INFO(resumed.out);
  REQUIRE(resumed.exit_code == 0);
  CHECK(resumed.out.find("] started ") == std::string::npos);
  CHECK_FALSE(fs::exists(dir / "results"));
  nlohmann::json from_ledger = nlohmann::json::parse(read(dir / "report" / "posterior.json"));
  nlohmann::json from_runs = p;
  CHECK(from_ledger["sets_from_ledger"] == 6);
  CHECK(from_runs["sets_from_ledger"] == 0);
  CHECK(from_ledger["core_seconds"].get<double>() == Approx(from_runs["core_seconds"].get<double>()).epsilon(1e-12));
  for (nlohmann::json* j : {&from_ledger, &from_runs}) j->erase("core_seconds"), j->erase("sets_from_ledger");
  CHECK(from_ledger == from_runs);
  CHECK_THAT(read(dir / "report" / "section.md"), Catch::Contains("6 of the sets were scored in earlier calls"));

  // Other references: the ledger's scores do not count, and the sets run again.
  std::ofstream(dir / "curve.csv") << "strain_3,q_over_p,sd\n0.002,0.7,0.1\n0.008,0.9,0.1\n";
  const auto other = dem::test::run_command(cmd + " 2>&1");
  INFO(other.out);
  REQUIRE(other.exit_code == 0);
  CHECK(other.out.find("] started ") != std::string::npos);
  CHECK(nlohmann::json::parse(read(dir / "report" / "posterior.json"))["sets_from_ledger"] == 0);

  // A damaged ledger is an error naming it, not a silent rerun.
  std::ofstream(dir / "report" / "scored_sets.json") << "{\"schema\": 1, \"sets\": 3}";
  const auto damaged = dem::test::run_command(cmd + " --plan 2>&1");
  CHECK(damaged.exit_code != 0);
  CHECK_THAT(damaged.out, Catch::Contains("scored_sets.json: not a ledger of scored sets"));
}

TEST_CASE("calibrate sets a density's parameter in that density's tests only, and a reading's keys together", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_cli_density";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string src = DEM_SOURCE_DIR;
  std::ofstream(dir / "study.yaml") << "name: two\noutput: results\npreparation: " << src << "/scenes/prepare_dense.yaml\n"
                                    << "densities: [{name: loose, friction: 0.5}, {name: dense, friction: 0.0}]\n"
                                    << "tests: [{name: triaxial, scene: " << src << "/scenes/tests/triaxial_drained.yaml, "
                                    << "set: {\"stages[1].until.strain\": 0.002}}]\n"
                                    << "profiles: {quick: {lattice: 4, seeds: 2}}\n";
  std::ofstream(dir / "curve.csv") << "strain_3,q_over_p,sd\n0.001,0.5,0.1\n";
  // Two scalar rows whose verdicts are known in every set: a packing's e0 lies in [0.3, 1.5], never near 5.
  std::ofstream(dir / "rows.yaml") << "source: typed\nrows:\n"
                                   << "  - {name: wide, quantity: void_ratio_after_preparation, density: dense, reference: 0.9, check: within, tolerance: 0.6, reason: wide, source: typed}\n"
                                   << "  - {name: far, quantity: void_ratio_after_preparation, density: dense, reference: 5.0, check: within, tolerance: 0.1, reason: far, source: typed}\n";
  std::ofstream(dir / "refs.yaml") << "source: typed\ncurves: [{name: qp, file: curve.csv, x: strain_3, y: q_over_p, "
                                   << "density: dense, test: triaxial}]\nrows: rows.yaml\n";
  std::ofstream(dir / "cal.yaml")
      << "name: two\nstudy: study.yaml\nreferences: refs.yaml\nreport: report\nparameters:\n"
      << "  - {name: dense_friction, keys: material.friction, densities: [dense], uniform: [0.1, 0.3]}\n"
      << "  - {name: test_damping, readings: [{name: body, set: {damping.translational: 0.05, material.contact_damping: 0.0}},\n"
      << "                                  {name: dashpots, set: {damping.translational: 0.0, material.contact_damping: 0.05}}]}\n"
      << "batch: 4\nmin_iterations: 1\nmax_iterations: 1\n";
  const auto r = dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' cal.yaml -j 2 --threads 1 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json p = nlohmann::json::parse(read(dir / "report" / "posterior.json"));
  REQUIRE(p["sets"].size() == 4);
  std::set<double> readings;
  for (const auto& set : p["sets"]) {
    const std::string name = set["name"];
    INFO(name);
    CHECK(set["scored"].get<bool>());  // its runs, dashpots or not, finished
    const fs::path scenes = dir / "results" / "calibration_two" / "quick" / "scenes" / "seed2";
    const YAML::Node dense = YAML::LoadFile((scenes / (name + "_dense_triaxial.yaml")).string());
    const YAML::Node loose = YAML::LoadFile((scenes / (name + "_loose_triaxial.yaml")).string());
    CHECK(set["judged_rows"] == 2);  // on its 2 samples, as validate judges a study
    CHECK(set["consistent_rows"] == 1);
    CHECK(dense["material"]["friction"].as<double>() == Approx(set["values"]["dense_friction"].get<double>()));
    CHECK(loose["material"]["friction"].as<double>() == 0.5);  // the test scene's, as written
    const bool dashpots = set["values"]["test_damping"].get<double>() == 1;  // a reading's value: its index
    readings.insert(set["values"]["test_damping"].get<double>());
    for (const YAML::Node& scene : {dense, loose}) {
      CHECK(scene["material"]["contact_damping"].as<double>() == (dashpots ? 0.05 : 0.0));
      CHECK(scene["damping"]["translational"].as<double>() == (dashpots ? 0.0 : 0.05));
    }
  }
  CHECK(readings == std::set<double>{0, 1});  // both readings drawn in 4 quasi-random sets
  const nlohmann::json& rows = p["rows_consistent"];
  CHECK(rows["sets_with_every_row_consistent"] == 0);
  CHECK(rows["per_row"][0]["consistent_sets"] == 4);
  CHECK(rows["per_row"][1]["consistent_sets"] == 0);
  CHECK(rows["per_row"][1]["judged_sets"] == 4);
  CHECK_THAT(read(dir / "report" / "section.md"), Catch::Contains("no set run makes all 2 consistent"));
  // The best set as a study variant: its value of the dense friction in the dense tests, its reading's keys.
  const auto best = dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' variant cal.yaml 2>warning.txt");
  INFO(best.out);
  REQUIRE(best.exit_code == 0);
  // Its one iteration of at most one ended with the posterior still moving: said, on stderr.
  CHECK_THAT(read(dir / "warning.txt"), Catch::Contains("warning:") && Catch::Contains("did not settle") &&
                                            Catch::Contains("best of the 4 scored, not of a settled posterior"));
  const YAML::Node variant = YAML::Load(best.out);
  CHECK(variant["name"].as<std::string>() == p["best_set"]["name"].get<std::string>());
  const auto& best_set = *std::find_if(p["sets"].begin(), p["sets"].end(), [&](const auto& set) { return set["name"] == p["best_set"]["name"]; });
  CHECK(variant["per_density"]["dense"]["material.friction"].as<double>() == Approx(best_set["values"]["dense_friction"].get<double>()));
  CHECK(variant["test"]["material.contact_damping"].as<double>() == (best_set["values"]["test_damping"].get<double>() == 1 ? 0.05 : 0.0));
  const auto missing = dem::test::run_command("cd '" + dir.string() + "' && '" + bin + "calibrate' variant cal.yaml --set i9s999 2>&1");
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.out, Catch::Contains("no set named 'i9s999'"));
}

TEST_CASE("calibrate refuses bad input with the file and key", "[calibration][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibrate_cli_bad";
  fs::create_directories(dir);
  std::ofstream(dir / "cal.yaml") << "name: x\nstudy: nosuch.yaml\nreferences: r.yaml\nreport: out\n"
                                  << "parameters: [{name: a, keys: k, uniform: [1, 0]}]\n";
  const auto r = dem::test::run_command("'" + bin + "calibrate' '" + (dir / "cal.yaml").string() + "' 2>&1");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains("cal.yaml") && Catch::Contains("uniform") && Catch::Contains("low < high"));
  const auto missing = dem::test::run_command("'" + bin + "calibrate' '" + (dir / "none.yaml").string() + "' 2>&1");
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.out, Catch::Contains("none.yaml"));
}
