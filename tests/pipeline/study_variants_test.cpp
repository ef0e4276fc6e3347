// Studies of variants: each variant is the study's runs with its scene overrides; a
// variant that changes only the tests shares the preparation; hashes follow the overrides; a
// may_fail run that stops with a message is an outcome, recorded and reused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "config/scene_config.hpp"
#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "generate/grading.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"
#include "run/run_scene.hpp"

namespace fs = std::filesystem;

namespace {

const std::string dem_binary = std::string(DEM_BINARY_DIR) + "/bin/dem";

// 8 spheres (lattice 2 from the profile), 100 steps per run: the whole study takes a fraction of a second.
void write_scenes(const fs::path& dir) { pipeline::test::write_tiny_scenes(dir, "1.0e-4", "1.0e-4"); }

const std::string study_head =
    "name: v\noutput: out\npreparation: prep.yaml\n"
    "densities: [{name: loose, friction: 0.5}]\n"
    "tests: [{name: test1, scene: test.yaml}]\n"
    "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n";

std::vector<pipeline::PlannedRun> plan(const fs::path& dir, const std::string& variants) {
  std::ofstream(dir / "study.yaml") << study_head << variants;
  const pipeline::Study study = pipeline::load_study((dir / "study.yaml").string());
  return pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "engine-A");
}

std::map<std::string, pipeline::PlannedRun> by_name(const std::vector<pipeline::PlannedRun>& runs) {
  std::map<std::string, pipeline::PlannedRun> m;
  for (const auto& r : runs) m[r.name] = r;
  return m;
}

const std::string four_variants =
    "variants:\n"
    "  - name: reference\n"
    "  - {name: dt2, set: {numerics.time_step: 2.0e-6}}\n"
    "  - {name: slow, test: {\"stages[0].duration\": 2.0e-4}}\n"
    "  - {name: big, prepare: {particles.lattice.n: [3, 3, 3]}}\n";

}  // namespace

TEST_CASE("variants expand into runs with their overrides, and test-only variants share the preparation", "[pipeline][variants]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_plan";
  fs::remove_all(dir);
  write_scenes(dir);
  const auto runs = plan(dir, four_variants);
  const auto r = by_name(runs);
  // reference, dt2, big: a preparation and a test each; slow: its test only, from the reference's sample.
  REQUIRE(runs.size() == 7);
  for (const char* name : {"reference_loose_prepare", "reference_loose_test1", "dt2_loose_prepare", "dt2_loose_test1",
                           "slow_loose_test1", "big_loose_prepare", "big_loose_test1"})
    CHECK(r.count(name) == 1);
  const auto scene = [&](const std::string& name) { return dem::scene_from_text(r.at(name).scene_text, r.at(name).scene_file); };
  CHECK(scene("reference_loose_prepare").time_step_s == 1e-6);
  CHECK(scene("dt2_loose_prepare").time_step_s == 2e-6);  // `set` goes into the preparation ...
  CHECK(scene("dt2_loose_test1").time_step_s == 2e-6);    // ... and the test
  CHECK(scene("slow_loose_test1").stages[0].duration_s == 2e-4);
  CHECK(scene("reference_loose_test1").stages[0].duration_s == 1e-4);
  CHECK(scene("big_loose_prepare").particles.lattice.n[0] == 3);        // after the profile's lattice 2
  CHECK(scene("reference_loose_prepare").particles.lattice.n[0] == 2);
  // Each test starts from its own variant's sample, except slow, which shares the reference's.
  const auto from = [&](const std::string& name) { return runs[static_cast<std::size_t>(r.at(name).depends_on)].name; };
  CHECK(from("slow_loose_test1") == "reference_loose_prepare");
  CHECK(from("dt2_loose_test1") == "dt2_loose_prepare");
  CHECK(from("big_loose_test1") == "big_loose_prepare");
  CHECK(r.at("reference_loose_prepare").variants == std::vector<std::string>{"reference", "slow"});
  CHECK(scene("slow_loose_test1").particles.path == fs::absolute(r.at("reference_loose_prepare").result).string());
}

TEST_CASE("input hashes follow a variant's overrides and nothing else", "[pipeline][variants]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_hash";
  fs::remove_all(dir);
  write_scenes(dir);
  const auto a = by_name(plan(dir, four_variants));
  std::string changed = four_variants;
  changed.replace(changed.find("2.0e-4"), 6, "3.0e-4");  // slow's test override
  const auto b = by_name(plan(dir, changed));
  CHECK(a.at("slow_loose_test1").hash != b.at("slow_loose_test1").hash);
  for (const char* same : {"reference_loose_prepare", "reference_loose_test1", "dt2_loose_prepare", "big_loose_test1"})
    CHECK(a.at(same).hash == b.at(same).hash);
  std::string dt = four_variants;
  dt.replace(dt.find("2.0e-6"), 6, "1.5e-6");  // dt2's time step: its preparation, and so its test
  const auto c = by_name(plan(dir, dt));
  CHECK(a.at("dt2_loose_prepare").hash != c.at("dt2_loose_prepare").hash);
  CHECK(a.at("dt2_loose_test1").hash != c.at("dt2_loose_test1").hash);
  CHECK(a.at("reference_loose_test1").hash == c.at("reference_loose_test1").hash);
}

TEST_CASE("time_step_fraction sets the time step from the sample's critical step", "[pipeline][variants]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_fraction";
  fs::remove_all(dir);
  write_scenes(dir);
  const auto r = by_name(plan(dir, "variants:\n  - {name: f02, time_step_fraction: 0.2, set: {material.kn: 1.0e7, material.ks: 1.0e7}}\n"));
  const dem::SceneConfig prep = dem::scene_from_text(r.at("f02_loose_prepare").scene_text, "prep");
  // Independent expectation: the lightest of the 8 spheres sets 2 sqrt(m_min/kn).
  dem::Particles p;
  dem::PeriodicCell cell;
  dem::make_lattice(prep.particles.lattice, dem::GradingCurve(prep.particles.grading_diameters_m, prep.particles.grading_percent_finer,
                                                              prep.particles.grading_basis),
                    prep.material.density_kg_per_m3, p, cell);
  const double m_min = *std::min_element(p.mass.begin(), p.mass.end());
  const double critical = 2 * std::sqrt(m_min / 1e7);
  CHECK(prep.time_step_s == Approx(0.2 * critical).epsilon(1e-12));
  // Exactly at the default limit 0.2: the engine must accept it (the step is written to 17 digits).
  CHECK_NOTHROW(dem::build_simulation(prep));
  const dem::SceneConfig test = dem::scene_from_text(r.at("f02_loose_test1").scene_text, "test");
  CHECK(test.time_step_s == prep.time_step_s);
}

TEST_CASE("a variant's override of an unknown scene key is refused naming the study, the variant and the key", "[pipeline][variants][input]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_badkey";
  fs::remove_all(dir);
  write_scenes(dir);
  try {
    plan(dir, "variants:\n  - name: ok\n  - {name: typo, set: {numerics.time_stp: 2.0e-6}}\n");
    FAIL("accepted an unknown scene key");
  } catch (const dem::ConfigError& e) {
    const std::string msg = e.what();
    INFO(msg);
    CHECK(msg.find((dir / "study.yaml").string()) != std::string::npos);
    CHECK(msg.find("variants[1] (typo)") != std::string::npos);
    CHECK(msg.find("time_stp") != std::string::npos);
    CHECK(msg.find("did you mean 'time_step'") != std::string::npos);
  }
}

TEST_CASE("a test's override of an unknown scene key is refused naming the study and the test", "[pipeline][variants][input]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_badtestkey";
  fs::remove_all(dir);
  write_scenes(dir);
  std::ofstream(dir / "study.yaml") << "name: v\noutput: out\npreparation: prep.yaml\n"
                                       "densities: [{name: loose, friction: 0.5}]\n"
                                       "tests: [{name: test1, scene: test.yaml, set: {\"stages[0].durration\": 1.0e-4}}]\n"
                                       "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n";
  const pipeline::Study study = pipeline::load_study((dir / "study.yaml").string());
  CHECK_THROWS_WITH(pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "engine-A"),
                    Catch::Matchers::Contains((dir / "study.yaml").string() + ": tests[0] (test1)") &&
                        Catch::Matchers::Contains("durration") && Catch::Matchers::Contains("did you mean 'duration'"));
}

TEST_CASE("pipeline: a may_fail run that stops is recorded, not a failure, and reused while unchanged", "[pipeline][variants][scheduler]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "variants_may_fail";
  fs::remove_all(dir);
  write_scenes(dir);
  // refused: a time step of 0.5 x critical without raising the limit (dem exits 2 before any step);
  // squeezed: the cell is squeezed below twice the contact range (dem stops the run, exit 1).
  const std::string variants =
      "variants:\n"
      "  - name: ok\n"
      "  - {name: refused, may_fail: true, time_step_fraction: 0.5}\n"
      "  - {name: squeezed, may_fail: true, prepare: {\"stages[0].strain_rate\": [0, 0, 100], \"stages[0].duration\": 0.01}}\n";
  auto runs = plan(dir, variants);
  pipeline::write_scenes(runs);
  pipeline::Outcome o = pipeline::execute(runs, dem_binary, 2);
  CHECK(o.ran == 2);      // ok's preparation and test
  CHECK(o.stopped == 2);  // both preparations that stop
  CHECK(o.skipped == 2);  // their tests
  CHECK(o.failed == 0);
  CHECK(o.blocked == 0);
  const auto r = by_name(runs);
  const auto refused = pipeline::read_stop(r.at("refused_loose_prepare").result);
  REQUIRE(refused);
  CHECK(refused->exit_code == 2);
  CHECK(refused->input_hash == r.at("refused_loose_prepare").hash);
  CHECK_THAT(refused->message, Catch::Matchers::Contains("time_step") && Catch::Matchers::Contains("max_time_step_fraction"));
  const auto squeezed = pipeline::read_stop(r.at("squeezed_loose_prepare").result);
  REQUIRE(squeezed);
  CHECK(squeezed->exit_code == 1);
  CHECK_FALSE(squeezed->message.empty());
  // A second run does nothing: results and recorded stops are reused.
  o = pipeline::execute(runs, dem_binary, 2);
  CHECK(o.ran == 0);
  CHECK(o.stopped == 0);
  CHECK(o.reused == 4);
  CHECK(o.skipped == 2);
  // A changed input runs again: a stop recorded for other inputs is not reused.
  std::string changed = variants;
  changed.replace(changed.find("0.5}"), 3, "0.6");
  runs = plan(dir, changed);
  pipeline::write_scenes(runs);
  o = pipeline::execute(runs, dem_binary, 2);
  CHECK(o.stopped == 1);
  CHECK(o.reused == 3);
}
