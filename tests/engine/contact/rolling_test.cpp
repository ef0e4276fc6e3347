// Rolling resistance (contact/rolling.hpp): the rolling spring's moment R* k_r u_r is capped at
// mu_r R* f_n, and spheres rolling on each other stop when the capped moment has taken their spin.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/test_support.hpp"

using namespace dem;

namespace {

// Four equal spheres of radius r on a periodic ring along x, each overlapping both neighbours by
// `overlap` (so the normal forces balance), spinning about z at +w, -w, +w, -w; the linear law
// (kn = ks = 1e6 N/m, mu = 0.5) with a rolling spring of stiffness kr capped at mu_r.
Simulation ring(double r, double overlap, double w, double kr, double mu_r, double dt) {
  const double a = 2 * r - overlap;
  const PeriodicCell cell(Vec3(4 * a, 0.01, 0.01));
  Particles p;
  for (int k = 0; k < 4; ++k) {
    p.add(test::fractional(cell, Vec3((k + 0.5) * a, 0.005, 0.005)), r, 2650);
    p.omega[k] = Vec3(0, 0, k % 2 ? -w : w);
  }
  Material material;
  material.law = LinearRollingLaw{LinearNormal{1e6}, LinearCoulomb{1e6, 0.5}, RollingSpring{kr, mu_r}};
  return Simulation(p, cell, material, test::no_damping(), dt, 1e-4);
}

}  // namespace

TEST_CASE("rolling: counter-rotating spheres in a ring stop at t = I w / (2 mu_r R* f_n)", "[contact][rolling]") {
  // Four equal spheres on a periodic ring along x, each overlapping both neighbours by 10 um, so
  // the normal forces balance. They spin about z at +w, -w, +w, -w: at every contact the surfaces
  // roll without slipping (v_t = arm (omega_i + omega_j) x n = 0), so only the rolling springs act.
  // Each contact's rolling displacement grows at R* 2w until the spring reaches its cap
  // (k_r |u_r| = mu_r f_n, after t_r = mu_r f_n / (k_r R* 2 w) = 1e-7 s, the moment ramping up
  // linearly), then it exerts the moment mu_r R* f_n, twice per sphere, until the spin has gone:
  // t = I w / (2 mu_r R* f_n) + t_r / 2.
  const double r = 1e-3, overlap = 1e-5, kn = 1e6, kr = 1e6, mu_r = 0.1, w = 1e4, dt = 1e-8;
  Simulation sim = ring(r, overlap, w, kr, mu_r, dt);
  const double I = sim.particles().inertia[0], R_star = r / 2;
  const double ke0 = 4 * 0.5 * I * w * w;
  double t_zero = 0;
  for (int n = 0; n < 10000 && t_zero == 0; ++n) {
    const double before = sim.particles().omega[0].z();
    sim.step(test::fixed_cell(), ServoSettings{});
    REQUIRE(sim.sums().contacts == 4);
    const double fn = sim.sums().sum_normal_force_N / 4;
    for (const Vec3& u : sim.history().rolling) REQUIRE(kr * u.norm() <= mu_r * fn * (1 + 1e-12));
    for (const Vec3& u : sim.history().tangential) REQUIRE(u.norm() <= 1e-20);  // pure rolling
    const double after = sim.particles().omega[0].z();
    // Spins are those of the half step, at sim.time() - dt / 2; the crossing is interpolated.
    if (before > 0 && after <= 0) t_zero = sim.time() - dt / 2 - dt * after / (after - before);
  }
  const double fn = kn * overlap;
  const double t_ramp = mu_r * fn / (kr * R_star * 2 * w);
  // The rolling spring is loaded at each force evaluation by the spins of the half step before, so
  // at t = 0 it already holds the step from -dt: the solution's clock starts at -dt.
  const double t_stop = I * w / (2 * mu_r * R_star * fn) + t_ramp / 2 - dt;
  // Tolerance: the ramp lasts 10 steps and the spring reaches its cap within a step (its delay is
  // known to a fraction of dt = 2.2e-4 of t); f_n from positions rounded to fractional coordinates
  // (1e-10 on a 10 um overlap); the crossing interpolated, exact for a spin falling linearly: 1e-4.
  CHECK(t_zero == Approx(t_stop).epsilon(1e-4));
  // The spin's energy went into the rolling caps (what is left is the springs' elastic energy).
  const EnergyBalance& e = sim.energy();
  CHECK(e.dissipated_rolling + sim.sums().elastic_rolling_J == Approx(ke0).epsilon(1e-3));
  CHECK(e.dissipated_friction == 0.0);
  CHECK(e.closure_error() < 1e-6);
  // The spheres stay where they were: rolling resistance exerts no force.
  for (std::size_t k = 0; k < 4; ++k) CHECK(sim.particles().v[k].norm() < 1e-12);
}

TEST_CASE("rolling: an elastic rolling spring makes the spins oscillate at 2 R* sqrt(k_r / I)", "[contact][rolling]") {
  // The ring as above with a cap far away (mu_r = 10): each sphere's angle obeys
  // I theta'' = -2 contacts x k_r R*^2 (2 theta), so omega(t) = w cos(2 R* sqrt(k_r / I) t).
  const double r = 1e-3, overlap = 1e-5, kr = 1e6, w = 100, dt = 1e-8;
  Simulation sim = ring(r, overlap, w, kr, 10.0, dt);
  const double omega0 = 2 * (r / 2) * std::sqrt(kr / sim.particles().inertia[0]);
  const int steps = static_cast<int>(1.3 * test::pi / omega0 / dt);  // past the half period
  double t_zero = 0;
  for (int n = 0; n < steps && t_zero == 0; ++n) {
    const double before = sim.particles().omega[0].z();
    sim.step(test::fixed_cell(), ServoSettings{});
    const double after = sim.particles().omega[0].z();
    if (before > 0 && after <= 0) t_zero = sim.time() - dt / 2 - dt * after / (after - before);
  }
  // The quarter period pi / (2 omega0) = 3.3e-6 s, 330 steps: the leapfrog's frequency error is
  // (omega0 dt)^2 / 24 = 1e-6, the linear interpolation of the crossing (omega0 dt)^2 / 8 of a
  // step: 1e-5.
  CHECK(t_zero == Approx(test::pi / (2 * omega0) - dt).epsilon(1e-5));  // the clock starts at -dt (see above)
  CHECK(sim.energy().dissipated_rolling == 0.0);
  CHECK(sim.energy().closure_error() < 1e-6);
}
