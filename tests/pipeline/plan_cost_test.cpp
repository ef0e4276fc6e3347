// What a plan costs (pipeline/plan/plan_cost.*) and profiles of any name (pipeline/config/
// study_config.*), on a tiny study whose particle-steps are counted by hand.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "plan/plan_cost.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  pipeline::test::write_tiny_scenes(dir, "0.002", "0.005");  // 2,000 and 5,000 steps at dt = 1 us
  return dir;
}

pipeline::Study load(const fs::path& dir, const std::string& text) {
  std::ofstream(dir / "study.yaml") << text;
  return pipeline::load_study((dir / "study.yaml").string());
}

// Two densities; tests `short` (1,000 steps) and `long` (5,000); variants `base` (the profile's
// 3 x 3 x 3 = 27 spheres) and `big` (4 x 4 x 4 = 64 spheres).
const std::string study_text =
    "name: cost\noutput: out\npreparation: prep.yaml\n"
    "densities: [{name: loose, friction: 0.5}, {name: dense, friction: 0.1}]\n"
    "tests: [{name: short, scene: test.yaml, set: {\"stages[0].duration\": 0.001}}, {name: long, scene: test.yaml}]\n"
    "profiles: {small: {lattice: 3}}\n"
    "variants: [{name: base}, {name: big, prepare: {particles.lattice.n: [4, 4, 4]}}]\n";

}  // namespace

TEST_CASE("plan cost: particle-steps, the critical path and the wall time on n cores, counted by hand", "[pipeline][plan]") {
  const fs::path dir = fresh("plan_cost");
  const pipeline::Study study = load(dir, study_text);
  const std::vector<pipeline::PlannedRun> runs = pipeline::plan_study(study, study.profile("small"), (dir / "out").string(), "e");
  REQUIRE(runs.size() == 12);  // 2 variants x 2 densities x (preparation + 2 tests)
  // By hand, per density: base: preparation 27 x 2,000 = 54,000, short 27 x 1,000 = 27,000, long
  // 27 x 5,000 = 135,000; big: 64 x 2,000 = 128,000, 64,000 and 320,000. In all 2 x 728,000.
  double total = 0;
  for (const auto& r : runs) total += r.cost;
  CHECK(total == Approx(1456000.0));
  const std::vector<double> cost = pipeline::run_costs(runs, std::vector<bool>(runs.size(), true));
  // The longest chain: big's preparation then its long test, 128,000 + 320,000.
  const pipeline::CriticalPath cp = pipeline::critical_path(runs, cost);
  CHECK(cp.cost == Approx(448000.0));
  REQUIRE(cp.runs.size() == 2);
  const std::string first = runs[static_cast<std::size_t>(cp.runs[0])].name, second = runs[static_cast<std::size_t>(cp.runs[1])].name;
  CHECK((first == "big_loose_prepare" || first == "big_dense_prepare"));
  CHECK(second == first.substr(0, first.size() - std::string("prepare").size()) + "long");
  // At 1e5 particle-steps/s: one core runs everything in turn (14.56 s); 64 cores are bound by the
  // critical path (4.48 s); two cores, longest chain first, by hand: both big preparations (to 1.28
  // s), both big long tests (4.48), the base preparations (5.02), base long (6.37), big short
  // (7.01), base short (7.28 s) = total / 2 with no core idle.
  CHECK(pipeline::estimated_wall_time_s(runs, cost, 1, 1e5) == Approx(14.56));
  CHECK(pipeline::estimated_wall_time_s(runs, cost, 2, 1e5) == Approx(7.28));
  CHECK(pipeline::estimated_wall_time_s(runs, cost, 64, 1e5) == Approx(4.48));
  // A reused preparation costs nothing: the chain is then the other density's.
  std::vector<bool> todo(runs.size(), true);
  for (int k : cp.runs) todo[static_cast<std::size_t>(k)] = false;
  const pipeline::CriticalPath rest = pipeline::critical_path(runs, pipeline::run_costs(runs, todo));
  CHECK(rest.cost == Approx(448000.0));
  CHECK(runs[static_cast<std::size_t>(rest.runs[0])].name != first);
}

TEST_CASE("profiles: any names; the study declares them and an unknown one is refused listing them", "[pipeline][plan]") {
  const fs::path dir = fresh("plan_profiles");
  const pipeline::Study study = load(dir, study_text);
  CHECK(study.profile("small").lattice == 3);
  CHECK(study.default_profile().name == "small");  // no paper profile: the first declared
  CHECK_THROWS_WITH(study.profile("paper"), Catch::Matchers::Contains("no profile 'paper'") &&
                                                Catch::Matchers::Contains("declares small"));
  std::string two = study_text;
  two.replace(two.find("profiles: {small: {lattice: 3}}"), 31, "profiles: {tiny: {lattice: 2}, paper: {lattice: 3}}");
  const pipeline::Study with_paper = load(dir, two);
  CHECK(with_paper.default_profile().name == "paper");  // the default when declared, as before
  CHECK_THROWS_WITH(with_paper.profile("quick"), Catch::Matchers::Contains("declares tiny, paper"));
  std::string bad = study_text;
  bad.replace(bad.find("small:"), 6, "\"a b\":");
  CHECK_THROWS_WITH(load(dir, bad), Catch::Matchers::Contains("profiles.a b") && Catch::Matchers::Contains("letters, digits"));
  bad = study_text;
  bad.replace(bad.find("profiles: {small: {lattice: 3}}"), 31, "profiles: {}");
  CHECK_THROWS_WITH(load(dir, bad), Catch::Matchers::Contains("profiles: must be a non-empty mapping"));
}
