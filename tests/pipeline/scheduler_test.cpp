// The pipeline's scheduler with the real engine on a tiny study: runs in dependency order, reuses
// finished results, reruns missing or corrupt ones, and reports a failure without running the
// runs that need it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config/study_config.hpp"
#include "exec/scheduler.hpp"
#include "exec/tracker.hpp"
#include "io/hdf5.hpp"
#include "plan/plan_cost.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"

namespace fs = std::filesystem;

namespace {

const std::string dem_binary = std::string(DEM_BINARY_DIR) + "/bin/dem";

// 27 spheres, 200 steps per run: the study takes well under a second.
void write_study(const fs::path& dir, const std::string& test_duration) {
  pipeline::test::write_tiny_scenes(dir, "2.0e-4", test_duration);
  std::ofstream(dir / "study.yaml") << "name: tiny\noutput: out\npreparation: prep.yaml\n"
                                       "densities: [{name: loose, friction: 0.5}, {name: dense, friction: 0}]\n"
                                       "tests: [{name: test1, scene: test.yaml}]\n"
                                       "profiles: {paper: {lattice: 3}, quick: {lattice: 3}}\n";
}

pipeline::Outcome run(const fs::path& dir) {
  const pipeline::Study study = pipeline::load_study((dir / "study.yaml").string());
  const auto runs = pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "test-engine");
  pipeline::write_scenes(runs);
  return pipeline::execute(runs, dem_binary, 2);
}

}  // namespace

TEST_CASE("pipeline: runs once, then reuses, reruns what is missing or corrupt", "[pipeline][scheduler]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_ok";
  fs::remove_all(dir);
  write_study(dir, "2.0e-4");
  pipeline::Outcome o = run(dir);
  CHECK(o.ran == 4);  // two preparations, two tests (each after its preparation)
  CHECK(o.reused == 0);
  CHECK(o.failed == 0);
  o = run(dir);  // a second run does no work
  CHECK(o.ran == 0);
  CHECK(o.reused == 4);
  CHECK(pipeline::reuse_problem((dir / "out" / "loose_prepare.h5").string(), "another hash") == "written for other inputs");
  fs::remove(dir / "out" / "dense_test1.h5");  // an interrupted study continues where it stopped
  { std::ofstream(dir / "out" / "loose_test1.h5", std::ios::trunc) << "truncated"; }  // a corrupt result
  o = run(dir);
  CHECK(o.ran == 2);
  CHECK(o.reused == 2);
}

TEST_CASE("pipeline: a changed input reruns over the earlier result, which dem replaces only with --force", "[pipeline][scheduler]") {
  // `dem run` refuses to replace a complete result of another scene without --force;
  // the pipeline's results are its own, so it passes --force: a changed test scene reruns the
  // tests in place, and a corrupt result is replaced too.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_force";
  fs::remove_all(dir);
  write_study(dir, "2.0e-4");
  REQUIRE(run(dir).ran == 4);
  write_study(dir, "3.0e-4");  // the tests' duration changes: their input hash and scene text too
  pipeline::Outcome o = run(dir);
  CHECK(o.ran == 2);
  CHECK(o.reused == 2);
  CHECK(o.failed == 0);
  { std::ofstream(dir / "out" / "dense_test1.h5", std::ios::trunc) << "not a result"; }
  o = run(dir);
  CHECK(o.ran == 1);
  CHECK(o.failed == 0);
}

TEST_CASE("pipeline: a failed run is reported and blocks only the runs that need it", "[pipeline][scheduler]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_fail";
  fs::remove_all(dir);
  write_study(dir, "2.0e-4");
  // Make the dense preparation fail at run time: a time step above the allowed fraction of the
  // critical step passes the plan (which parses scenes) but is refused by dem when it builds.
  const pipeline::Study study = pipeline::load_study((dir / "study.yaml").string());
  auto runs = pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "test-engine");
  for (auto& r : runs)
    if (r.name == "dense_prepare") {
      const auto pos = r.scene_text.find("time_step: 1.0e-6");
      REQUIRE(pos != std::string::npos);
      r.scene_text.replace(pos, 17, "time_step: 1.0e-4");
    }
  pipeline::write_scenes(runs);
  const pipeline::Outcome o = pipeline::execute(runs, dem_binary, 2);
  CHECK(o.failed == 1);   // dense_prepare
  CHECK(o.blocked == 1);  // dense_test1 needs it
  CHECK(o.ran == 2);      // the loose runs are independent and finish
  std::ifstream log(dir / "out" / "logs" / "dense_prepare.log");
  std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::Matchers::Contains("time_step"));
}

TEST_CASE("pipeline: every preparation runs before any test (longest chain first)", "[pipeline][scheduler]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_order";
  fs::remove_all(dir);
  write_study(dir, "2.0e-4");
  const pipeline::Study study = pipeline::load_study((dir / "study.yaml").string());
  const auto runs = pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "test-engine");
  pipeline::write_scenes(runs);
  REQUIRE(pipeline::execute(runs, dem_binary, 1).ran == 4);  // one at a time: the order is the start order
  // Listed order is loose_prepare, loose_test1, dense_prepare, dense_test1; the dense sample must
  // be finished before the first test (a result is renamed into place when it is complete).
  const auto finished = [&](const std::string& name) { return fs::last_write_time(dir / "out" / (name + ".h5")); };
  CHECK(finished("dense_prepare") < finished("loose_test1"));
  CHECK(finished("loose_prepare") < finished("dense_prepare"));
}

TEST_CASE("pipeline: several studies share one list of runs, each test after its own study's sample", "[pipeline][scheduler]") {
  const fs::path root = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_joined";
  fs::remove_all(root);
  std::vector<pipeline::StudyPlan> plans;
  for (const std::string name : {"first", "second"}) {
    write_study(root / name, "2.0e-4");
    const pipeline::Study study = pipeline::load_study((root / name / "study.yaml").string());
    plans.push_back({name, pipeline::plan_study(study, study.profile("quick"), (root / name / "out").string(), "test-engine")});
    pipeline::write_scenes(plans.back().runs);
  }
  SECTION("joined") {
    const auto runs = pipeline::join_studies(plans);
    REQUIRE(runs.size() == 8);
    int copies = 0;
    for (const auto& r : runs) {
      const std::string study = r.name.substr(0, r.name.find('/'));
      CHECK((study == "first" || study == "second"));
      if (r.copy_of >= 0) {  // the second study's samples are the first's (same scenes but for the header)
        ++copies;
        CHECK(r.depends_on == r.copy_of);
        CHECK(runs[static_cast<std::size_t>(r.copy_of)].name == "first/" + r.density + "_prepare");
        CHECK(r.name == "second/" + r.density + "_prepare");
        continue;
      }
      if (r.depends_on < 0) continue;  // a test: it starts from its own study's preparation of its density
      const auto& sample = runs[static_cast<std::size_t>(r.depends_on)];
      CHECK(sample.name == study + "/" + r.density + "_prepare");
      CHECK(fs::path(sample.result).parent_path() == fs::path(r.result).parent_path());
    }
    CHECK(copies == 2);
    pipeline::Outcome o = pipeline::execute(runs, dem_binary, 2);
    CHECK(o.ran == 6);
    CHECK(o.copied == 2);
    CHECK(o.failed == 0);
    CHECK(fs::exists(root / "first" / "out" / "dense_test1.h5"));
    CHECK(fs::exists(root / "second" / "out" / "dense_test1.h5"));
    for (const auto& r : runs) CHECK(pipeline::up_to_date(r.result, r.hash));  // a copy carries its own input hash
    // and the scene the engine resolved for the run it copies (defaults filled in), under its own name
    for (const auto& r : runs) {
      if (r.copy_of < 0) continue;
      const auto text = [](const std::string& file) { return dem::h5::read_text(dem::h5::open_file_read(file), "scene_yaml"); };
      const std::string copy = text(r.result), source = text(runs[static_cast<std::size_t>(r.copy_of)].result);
      CHECK(copy.substr(copy.find('\n')) == source.substr(source.find('\n')));
      CHECK(copy.rfind("name: " + YAML::Load(r.scene_text)["name"].as<std::string>() + "\n", 0) == 0);
    }
    o = pipeline::execute(runs, dem_binary, 2);  // and is reused like any result
    CHECK(o.reused == 8);
    CHECK(o.ran + o.copied == 0);
  }
  SECTION("a study given twice would write its results twice: refused") {
    plans[1] = plans[0];
    CHECK_THROWS_WITH(pipeline::join_studies(plans), Catch::Matchers::Contains("would both write"));
  }
}

namespace {
// A complete result as `dem run` leaves it, for the tracker to reuse: status, input hash, the
// final step count of /state and its spheres, and (if given) the run's wall time.
void write_result(const fs::path& file, const std::string& hash, std::int64_t steps, std::size_t spheres,
                  std::optional<double> wall_s) {
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::h5::set_attribute(f, "status", std::string("complete"));
  dem::h5::set_attribute(f, "schema_version", std::int64_t{4});
  dem::h5::set_attribute(f, "input_hash", hash);
  if (wall_s) dem::h5::set_attribute(f, "wall_time_s", *wall_s);
  {
    dem::h5::Handle state = dem::h5::create_group(f, "state");
    dem::h5::set_attribute(state, "step", steps);
    dem::h5::write(state, "radius", std::vector<double>(spheres, 1e-3), 1, "m");
  }
  dem::h5::close_file(f, file.string());
}

pipeline::PlannedRun planned(const fs::path& dir, const std::string& name, const std::string& family, double cost) {
  pipeline::PlannedRun r;
  r.name = name, r.test = "test", r.family = family, r.cost = cost;
  r.result = (dir / (name + ".h5")).string(), r.log = (dir / (name + ".log")).string();
  r.hash = "hash of " + name;
  return r;
}
}  // namespace

TEST_CASE("pipeline: the ETA learns from finished runs what their family takes against its plan", "[pipeline][scheduler]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "scheduler_eta";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Family "liquefy": planned at 2e6 particle-steps each (their duration bound), the finished one
  // stopped after 1,000 steps of 10 spheres (1e4) in 20 s: the next is expected to take 2e6 x 1e4 / 2e6.
  std::vector<pipeline::PlannedRun> runs = {planned(dir, "liquefy_a", "liquefy", 2e6), planned(dir, "liquefy_b", "liquefy", 2e6),
                                            planned(dir, "shear", "shear", 3e4), planned(dir, "unknown_wall", "other", 5e4),
                                            planned(dir, "unknown_wall_b", "other", 5e4)};
  write_result(runs[0].result, runs[0].hash, 1000, 10, 20.0);
  // A wall time of 0 (none measured): scales its family, not the rate. A complete result always has
  // the attribute (io/result_file.hpp: one without it is a .partial marked complete by hand).
  write_result(runs[3].result, runs[3].hash, 100, 10, 0.0);
  pipeline::Tracker tracker(runs);
  REQUIRE(tracker.state(0) == pipeline::RunState::Done);
  REQUIRE(tracker.state(3) == pipeline::RunState::Done);
  CHECK(tracker.expected_cost(1) == Approx(1e4));
  CHECK(tracker.expected_cost(2) == Approx(3e4));  // no finished run of its family: the plan
  CHECK(tracker.expected_cost(4) == Approx(1e3));  // 5e4 x 1e3 / 5e4
  // Throughput learnt from the tests' actual particle-steps with a wall time: 1e4 in 20 s = 500
  // per second (the planned 2e6 would claim 1e5 per second). Left: liquefy_b (1e4 / 500 = 20 s),
  // shear (3e4 / 500 = 60 s) and unknown_wall_b (1e3 / 500 = 2 s), on one worker.
  CHECK(tracker.eta_seconds() == Approx(82.0));
  tracker.set_workers(2);
  CHECK(tracker.eta_seconds() == Approx(41.0));
}

TEST_CASE("pipeline: a plan without finished runs takes what this engine's runs in other results folders recorded", "[pipeline][plan]") {
  const fs::path root = fs::path(DEM_BINARY_DIR) / "test_tmp" / "machine_throughput";
  fs::remove_all(root);
  const auto manifest = [&](const fs::path& folder, const std::string& engine, const std::vector<std::string>& results) {
    fs::create_directories(folder);
    std::ofstream f(folder / "runs.tsv");
    f << "# engine source " << engine << "\n# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\tinput_hash\n";
    for (const std::string& r : results) f << "-\tloose\t-\t" << r << "\t" << (folder / (r + ".h5")).string() << "\t-\t0\tas written\t-\th\n";
  };
  // Engine E: 1,000 steps of 10 spheres in 2 s, and 2,000 steps of 10 in 2 s (30,000 particle-steps in 4 s);
  // a run without a wall time and a run listed but never finished are left out.
  manifest(root / "a" / "paper", "E schema 4", {"one", "two", "no_wall", "not_run"});
  write_result(root / "a" / "paper" / "one.h5", "h", 1000, 10, 2.0);
  write_result(root / "a" / "paper" / "two.h5", "h", 2000, 10, 2.0);
  write_result(root / "a" / "paper" / "no_wall.h5", "h", 5000, 10, std::nullopt);
  // A calibration's folder, one level deeper: counted (1,000 x 10 in 6 s).
  manifest(root / "calibration" / "calibration_c" / "paper", "E schema 4", {"three"});
  write_result(root / "calibration" / "calibration_c" / "paper" / "three.h5", "h", 1000, 10, 6.0);
  // Another engine's runs: not counted.
  manifest(root / "b" / "paper", "F schema 4", {"fast"});
  write_result(root / "b" / "paper" / "fast.h5", "h", 1000000, 10, 1.0);
  const auto m = pipeline::recorded_throughput_under(root.string(), "E schema 4");
  REQUIRE(m);
  CHECK(m->particle_steps_per_s == Approx(40000.0 / 10.0));
  CHECK(m->runs == 3);
  CHECK(m->studies == 2);
  CHECK_FALSE(pipeline::recorded_throughput_under(root.string(), "G schema 4"));
  CHECK_FALSE(pipeline::recorded_throughput_under((root / "missing").string(), "E schema 4"));
}
