// The stress servo on a real packing: it brings a gas to a target pressure and then tracks a
// moving target (a ramp on one axis at the paper's shearing rate) closely and without overshoot.
#include <catch2/catch.hpp>

#include <cmath>

#include "config/scene_config.hpp"
#include "run/run_scene.hpp"

namespace {

const char* scene_text = R"(
name: servo
particles:
  lattice: {n: [6, 6, 6], spacing: 5.0e-3, seed: 3}
  grading: {diameters: [3.0e-3, 3.7e-3, 4.5e-3], percent_finer: [0, 50, 100]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}
numerics: {time_step: 1.0e-6}
output: {interval: 50}
stages:
  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e7, max_strain_rate: 5.0,
     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0e-2, max_duration: 2.0}}
  - {name: ramp, type: stress, target: [1.05e5, 1.0e5, 1.0e5], rate: 2.0e6,
     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0, max_duration: 0.1}}
)";

}  // namespace

TEST_CASE("servo: compresses a gas to the target and tracks a stress ramp without overshoot", "[servo]") {
  const dem::SceneConfig scene = dem::scene_from_text(scene_text, "servo.yaml");
  dem::Simulation sim = dem::build_simulation(scene);

  // Stage 0 ends only when every principal stress is within 0.5 % of 100 kPa (the hold criterion).
  dem::run_stage(sim, scene, 0, {});
  const dem::Mat3 s0 = sim.sums().stress_Pa;
  for (int k = 0; k < 3; ++k) CHECK(std::abs(s0(k, k) - 1e5) <= 0.005 * 1e5);

  // Stage 1: sigma_11 ramps 100 -> 105 kPa at the paper's shearing rate 2 MPa/s (2.5 ms), the other
  // axes hold 100 kPa. A small step keeps this 216-sphere packing elastic: a larger deviator makes
  // it rearrange, and its stress then jumps by more than 1 % of p whatever the servo does.
  // Record the error against the same linear target the stage uses.
  const double start = s0(0, 0);
  double sum_sq = 0, worst_overshoot = 0, worst_other = 0;
  long n = 0;
  dem::StageHooks hooks;
  const double t0 = sim.time();
  hooks.row = [&](const dem::Simulation& s, const dem::RowContext&) {  // every 50 steps
    const double t = s.time() - t0;
    const double target = std::min(1.05e5, start + 2e6 * t);
    const dem::Mat3& st = s.sums().stress_Pa;
    // The servo learns the packing's stiffness over its first windows (250 steps each); judge
    // the tracking after the first 1.25 ms (5 windows) of the 2.5 ms ramp.
    // (During the learning windows this small packing's stresses sag by up to 2.3 % of p as it
    // relaxes after the hold, measured; that transient is not judged here.)
    if (t > 1.25e-3) {
      sum_sq += (st(0, 0) - target) * (st(0, 0) - target);
      ++n;
      worst_other = std::max({worst_other, std::abs(st(1, 1) - 1e5), std::abs(st(2, 2) - 1e5)});
    }
    worst_overshoot = std::max(worst_overshoot, st(0, 0) - 1.05e5);
  };
  dem::run_stage(sim, scene, 1, hooks);
  REQUIRE(n >= 25);  // the second half of the 2.5 ms ramp alone gives 25 rows
  const double rms = std::sqrt(sum_sq / static_cast<double>(n));
  // The stress stage uses the adaptive servo, which learns the ratio kappa of the packing's
  // stiffness to the affine one and so removes the ramp lag e = r dt (1 - kappa)/(gain kappa) of a
  // fixed-stiffness servo (measured on this packing before the servo learnt kappa: 1.4 % of p).
  // docs/method.md#damping asks each principal stress to track its target within 1 % of p (RMS over a
  // leg); once kappa is learnt this small loose packing (216 spheres) must meet it.
  CHECK(rms <= 0.01 * 1e5);
  // Axes whose target does not move stay within the 1 % band.
  CHECK(worst_other <= 0.01 * 1e5);
  // No overshoot beyond the tracking band when the ramp stops.
  CHECK(worst_overshoot <= 0.01 * 1e5);
}
