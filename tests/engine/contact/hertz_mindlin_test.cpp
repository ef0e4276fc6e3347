// Hertz-Mindlin (contact/hertz_mindlin.hpp): a head-on collision of two elastic spheres against
// Hertz's solution, and Mindlin's tangential stiffness with its Coulomb cap.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/contact/contact_support.hpp"
#include "engine/test_support.hpp"

using namespace dem;

namespace {
// Glass-like grains: E = 70 GPa, nu = 0.25, so E* = E / (2 (1 - nu^2)) = 3.7333e10 Pa and
// G = E / (2 (1 + nu)) = 2.8e10 Pa, G* = G / (2 (2 - nu)) = 8e9 Pa.
HertzNormal glass() { return {70e9, 0.25}; }
}  // namespace

TEST_CASE("Hertz: the moduli of one material", "[contact][hertz]") {
  CHECK(glass().effective_modulus() == Approx(70e9 / 1.875).epsilon(1e-15));
  CHECK(MindlinCoulomb::of(glass(), 0.5).shear_coefficient == Approx(8 * 8e9).epsilon(1e-15));
}

TEST_CASE("Hertz: head-on collision lasts 2.87 (m*^2 / (R* E*^2 v))^1/5 and peaks at Hertz's force", "[contact][hertz]") {
  // Two 1 mm spheres meet at relative speed v = 0.2 m/s, no damping, no friction. Hertz's solution
  // (Johnson, Contact Mechanics, 11.4): maximum overlap d = (15 m* v^2 / (16 E* sqrt(R*)))^2/5,
  // peak force 4/3 E* sqrt(R*) d^3/2, duration 2.868 d / v = 2.87 (m*^2 / (R* E*^2 v))^1/5.
  const double r = 1e-3, v = 0.2, rho = 2650;
  const HertzNormal hertz = glass();
  const double m = rho * 4.0 / 3.0 * test::pi * r * r * r, m_star = m / 2, R_star = r / 2;
  const double E_star = hertz.effective_modulus();
  const double d_max = std::pow(15 * m_star * v * v / (16 * E_star * std::sqrt(R_star)), 0.4);
  const double f_max = 4.0 / 3.0 * E_star * std::sqrt(R_star) * std::pow(d_max, 1.5);
  const double t_c = 2.87 * std::pow(m_star * m_star / (R_star * E_star * E_star * v), 0.2);
  const double dt = t_c / 4000;
  const PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(test::fractional(cell, Vec3(0.01 - r - 2 * v * dt, 0.01, 0.01)), r, rho);  // they meet after about one step
  p.add(test::fractional(cell, Vec3(0.01 + r + 2 * v * dt, 0.01, 0.01)), r, rho);
  p.v[0] = Vec3(v / 2, 0, 0);
  p.v[1] = Vec3(-v / 2, 0, 0);
  Material material;
  material.law = HertzLaw{hertz, {}, {}};
  Simulation sim(p, cell, material, test::no_damping(), dt, 1e-4);
  int steps_in_contact = 0;
  double peak = 0;
  for (int n = 0; n < 8000 && (steps_in_contact == 0 || sim.sums().contacts > 0); ++n) {
    sim.step(test::fixed_cell(), ServoSettings{});
    if (sim.sums().contacts > 0) ++steps_in_contact;
    peak = std::max(peak, sim.sums().sum_normal_force_N);
  }
  // Tolerances: 2.87 is Hertz's 2.868 rounded (0.07 %), and the contact is counted in whole steps
  // of t_c / 4000 (0.03 %): 0.2 %. The peak: the leapfrog's overlap error at the turning point is
  // O(dt^2) relative, and the sampled step is within dt of the peak, where f changes by
  // O((dt / t_c)^2): 1e-5.
  CHECK(steps_in_contact * dt == Approx(t_c).epsilon(2e-3));
  CHECK(peak == Approx(f_max).epsilon(1e-5));
  // Elastic: the spheres leave with the speed they came with, the energy balance closing.
  CHECK((sim.particles().v[1] - sim.particles().v[0]).x() == Approx(v).epsilon(1e-4));
  CHECK(sim.energy().closure_error() < 1e-4);
}

TEST_CASE("Mindlin: tangential force k_t u below mu f_n, k_t = 8 G* sqrt(R* overlap), then the Coulomb cap", "[contact][mindlin]") {
  // A contact of R* = 0.5 mm at overlap 2 um, held, sheared by 0.1 nm per step along y.
  const MindlinCoulomb law = MindlinCoulomb::of(glass(), 0.3);
  const double R_star = 5e-4, overlap = 2e-6;
  const double fn = glass().coefficient() * std::sqrt(R_star * overlap) * overlap;  // 2.36 N
  const double k_t = 8 * 8e9 * std::sqrt(R_star * overlap);                          // 2.02e6 N/m
  const Vec3 n(1, 0, 0), v_t(0, 1e-4, 0);
  const double dt = 1e-6, du = 1e-10;  // |v_t| dt
  Vec3 history = Vec3::Zero();
  bool sliding = true;
  double lost = -1;
  int elastic = 0, capped = 0;
  for (int k = 1; k <= 10000; ++k) {
    const Vec3 f = test::tangential_step(law, history, n, v_t, dt, fn, overlap, R_star, sliding, lost);
    const double expected = k_t * k * du;  // the force on j opposes its displacement
    REQUIRE(f.dot(v_t) <= 0);
    if (expected < 0.3 * fn * (1 - 1e-9)) {
      // Incremental: a sum of k equal increments, relative round-off k eps: 1e-12.
      REQUIRE_FALSE(sliding);
      REQUIRE(lost == 0.0);
      REQUIRE(f.norm() == Approx(expected).epsilon(1e-12));
      ++elastic;
    } else if (expected > 0.3 * fn * (1 + 1e-9)) {
      REQUIRE(sliding);
      REQUIRE(f.norm() == Approx(0.3 * fn).epsilon(1e-14));
      // Sliding on at the cap, the contact takes Coulomb's work mu f_n du per step.
      if (capped++ > 0) REQUIRE(lost == Approx(0.3 * fn * du).epsilon(1e-6));
    }
  }
  CHECK(elastic == static_cast<int>(0.3 * fn / (k_t * du)));
  CHECK(capped + elastic >= 9999);  // at most one step lands within 1e-9 of the cap
  // Unloading from the cap is elastic, at the same stiffness.
  const Vec3 f = test::tangential_step(law, history, n, -v_t, dt, fn, overlap, R_star, sliding, lost);
  CHECK_FALSE(sliding);
  CHECK(f.norm() == Approx(0.3 * fn - k_t * du).epsilon(1e-12));
}
