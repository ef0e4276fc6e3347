// The hold of a stress stage ends when, and only when, the equilibrium criteria hold (docs/method.md#preparation).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "run/run_scene.hpp"

namespace {

// A small frictional sample compressed to 100 kPa; rows are taken exactly at the check steps
// (output interval = check interval), so every check the stage makes is seen by the row hook,
// on the same state, through the same hold_status() the stage uses.
const char* scene_text = R"(
name: hold
particles:
  lattice: {n: [5, 5, 5], spacing: 5.0e-3, seed: 4}
  grading: {diameters: [3.0e-3, 3.7e-3, 4.5e-3], percent_finer: [0, 50, 100]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.3}
numerics: {time_step: 1.0e-6}
output: {interval: 100}
stages:
  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e7, max_strain_rate: 5.0,
     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0e-2, check_interval: 100, max_duration: 2.0}}
)";

}  // namespace

TEST_CASE("the hold ends at the first check where both equilibrium criteria hold", "[run][hold]") {
  const dem::SceneConfig scene = dem::scene_from_text(scene_text, "hold.yaml");
  dem::Simulation sim = dem::build_simulation(scene);
  const double ramp_end = 1e5 / 1e7;  // from zero stress to 100 kPa at 10 MPa/s
  std::vector<dem::HoldStatus> checks;  // every check after the ramp, in order
  dem::StageHooks hooks;
  hooks.row = [&](const dem::Simulation& s, const dem::RowContext&) {
    if (s.step_count() > 0 && s.time() >= ramp_end - 1e-12) checks.push_back(dem::hold_status(s, scene.stages[0]));
  };
  dem::run_stage(sim, scene, 0, hooks);
  // The stage ends on a check step, which is also an output step, so the last row is the last
  // check (the stage-end row is not repeated on an output step).
  REQUIRE(sim.step_count() % 100 == 0);
  REQUIRE(checks.size() >= 2);
  // "When": at the end both criteria hold ...
  const dem::HoldStatus last = checks.back();
  CHECK(last.met);
  CHECK(last.stress_error <= 0.5);
  CHECK(last.unbalanced_force_ratio <= 1e-2);
  // ... "and only when": no earlier check after the ramp met them (else the stage would have ended there).
  std::size_t earlier_met = 0;
  for (std::size_t i = 0; i + 1 < checks.size(); ++i) earlier_met += checks[i].met;
  CHECK(earlier_met == 0);
  // The check can fail: the criteria were not met at the first check after the ramp (the gas
  // jams late, so the stress lags its ramp).
  CHECK_FALSE(checks.front().met);
}

TEST_CASE("a hold with a creep criterion ends at the first check where the packing is also at rest", "[run][hold]") {
  // The same compression with hold.creep_rate: the stage measures |ln(V_end / V_start)| / window
  // over consecutive windows of 1,000 steps from the end of the ramp (step 10,000), and may end
  // only at a check where the force criteria hold and the last whole window crept at most
  // creep_rate. Window ends and checks are multiples of 100 steps, so the rows see them all.
  std::string text = scene_text;
  const std::string hold = "check_interval: 100, max_duration: 2.0}";
  text.replace(text.find(hold), hold.size(), "check_interval: 100, max_duration: 2.0, creep_rate: 0.05, creep_window: 1.0e-3}");
  const dem::SceneConfig scene = dem::scene_from_text(text, "creep.yaml");
  dem::Simulation sim = dem::build_simulation(scene);
  struct Row {
    std::int64_t step;
    double volume;
    bool met;  // the force criteria
  };
  std::vector<Row> rows;
  dem::StageHooks hooks;
  hooks.row = [&](const dem::Simulation& s, const dem::RowContext&) {
    rows.push_back({s.step_count(), s.cell().volume(), dem::hold_status(s, scene.stages[0]).met});
  };
  dem::run_stage(sim, scene, 0, hooks);
  const auto row_at = [&](std::int64_t step) {
    const auto r = std::find_if(rows.begin(), rows.end(), [&](const Row& x) { return x.step == step; });
    REQUIRE(r != rows.end());
    return *r;
  };
  // The creep of the last whole window before `step` (-1: none yet).
  const auto creep_before = [&](std::int64_t step) {
    const std::int64_t window_end = 10000 + (step - 10000) / 1000 * 1000;
    if (window_end < 11000) return -1.0;
    return std::abs(std::log(row_at(window_end).volume / row_at(window_end - 1000).volume)) / 1e-3;
  };
  const std::int64_t end = sim.step_count();
  INFO("the stage ended at step " << end << ", creep of its last window " << creep_before(end) << " 1/s");
  CHECK(row_at(end).met);
  CHECK(creep_before(end) >= 0);
  CHECK(creep_before(end) <= 0.05);
  // Only then: at every earlier check where the force criteria held, the packing still crept.
  int delayed = 0;
  for (std::int64_t c = 10000; c < end; c += 100) {
    if (!row_at(c).met) continue;
    const double creep = creep_before(c);
    CHECK((creep < 0 || creep > 0.05));
    ++delayed;
  }
  // The criterion is not idle on this packing: without it the stage would have ended earlier.
  CHECK(delayed >= 1);
}
