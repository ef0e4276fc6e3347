// Time-step stability: critical_time_step and the leapfrog limit dt < 2/omega of a harmonic mode.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "engine/test_support.hpp"

using namespace dem;

TEST_CASE("critical_time_step = 2 sqrt(m_min / kn)", "[dynamics][stability]") {
  Particles p;
  p.add(Vec3(0.1, 0.1, 0.1), 1e-3, 2650);
  p.add(Vec3(0.5, 0.5, 0.5), 0.5e-3, 2650);  // the lightest
  p.add(Vec3(0.8, 0.2, 0.3), 2e-3, 2650);
  const double kn = 3e5;
  const double m_min = 2650 * 4.0 / 3.0 * test::pi * 0.5e-3 * 0.5e-3 * 0.5e-3;
  // m_min is recomputed independently from rho 4/3 pi r^3: a few roundings, relative 1e-15.
  REQUIRE(critical_time_step(linear_law(kn, 0, 0), p, 2650) == Approx(2 * std::sqrt(m_min / kn)).epsilon(1e-14));
}

namespace {

// A periodic chain of 4 equal spheres along x, pre-compressed (spacing a < d), every contact closed.
// In the alternating mode (spheres 0, 2 displaced by +u, spheres 1, 3 by -u) each sphere's two
// contacts change their overlaps by +-2u, so m u'' = -4 kn u: a mass m on a spring 4 kn, a
// two-sublattice oscillator of frequency omega = 2 sqrt(kn/m) whose leapfrog limit is
// dt_c = 2/omega = 2 sqrt(m/(4 kn)) = critical_time_step(p, 4 kn). Returns max_n |u_n| / u0 over the run.
double alternating_mode_amplitude(double dt_over_limit, int steps, double* bound = nullptr) {
  const double r = 1e-3, d = 2 * r, a = 0.99 * d, kn = 1e5, u0 = 1e-7;  // static overlap 20 um >> 2 u
  const PeriodicCell cell(Vec3(4 * a, 0.01, 0.01));
  Particles p;
  for (int k = 0; k < 4; ++k) {
    const double u = (k % 2 == 0) ? u0 : -u0;
    p.add(test::fractional(cell, Vec3((k + 0.5) * a + u, 0.005, 0.005)), r, 2650);
  }
  const double dt = dt_over_limit * critical_time_step(linear_law(4 * kn, 0, 0), p, 2650);
  const double w = 2 * dt_over_limit;  // omega dt
  if (bound) *bound = 1 / std::sqrt(1 - w * w / 4);
  Simulation sim(p, cell, test::material(kn), test::no_damping(), dt, 1e-4);
  const Vec3 s_site = test::fractional(cell, Vec3(0.5 * a, 0.005, 0.005));
  double worst = 0;
  for (int n = 0; n < steps; ++n) {
    sim.step(test::fixed_cell(), ServoSettings{});
    worst = std::max(worst, std::abs(sim.cell().branch(s_site, sim.particles().s[0]).x()) / u0);
  }
  return worst;
}

}  // namespace

TEST_CASE("leapfrog: an oscillator mode is bounded below dt = 2/omega and grows above it", "[dynamics][stability]") {
  // Starting from rest at displacement u0 (v_{-1/2} = 0), leapfrog gives exactly
  //   u_n = A cos(omega' (n + 1/2) dt),  sin(omega' dt / 2) = omega dt / 2,  A = u0 / sqrt(1 - (omega dt / 2)^2),
  // so below the limit max |u_n| <= A (reached to within a percent over 2000 steps), while above
  // it the amplification per step is |lambda| = 1.49 at omega dt = 2.04 and u0 grows a hundredfold
  // within a few tens of steps (the contacts then open and the chain flies apart).
  double bound = 0;
  const double stable = alternating_mode_amplitude(0.98, 2000, &bound);  // bound A/u0 = 5.03
  INFO("stable: max |u|/u0 = " << stable << ", leapfrog bound " << bound);
  // Tolerance: positions are O(1e-2) m, so u (1e-7 m) carries ~1e-18 m of round-off per step: 1e-9 relative.
  REQUIRE(stable <= bound * (1 + 1e-9));
  REQUIRE(stable >= 0.99 * bound);
  const double half = alternating_mode_amplitude(0.5, 2000, &bound);
  REQUIRE(half <= bound * (1 + 1e-9));
  // Above the limit: 1.49^12 ~ 100, so within 60 steps u exceeds 100 u0 = delta_0 / 2, where the
  // contacts open; a stable scheme would stay within u0 / sqrt(1 - 0.98^2) ~ 5 u0 at any dt below the limit.
  REQUIRE(alternating_mode_amplitude(1.02, 60) > 100);
}
