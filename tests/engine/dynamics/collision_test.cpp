// Head-on collision of two equal spheres (no friction) in a large periodic cell: the linear spring
// makes the contact half a period of a harmonic oscillator of reduced mass m* = m/2.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/test_support.hpp"

using namespace dem;
using test::pi;

namespace {

struct Collision {
  double contact_time = 0;   // (first step without contact - first step with contact) * dt [s]
  double speed_before = 0;   // relative speed at the half step before the first contact step [m/s]
  double speed_after = 0;    // relative speed at the half step after the first step without contact [m/s]
  double mass = 0;           // mass of one sphere [kg]
};

// Spheres of radius 1 mm approach each other along x at +-v with an initial surface gap of 1 um.
Collision collide(double kn, double dt, double v, Damping damping) {
  const double r = 1e-3, gap = 1e-6;
  PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(test::fractional(cell, Vec3(0.01 - r - gap / 2, 0.01, 0.01)), r, 2650);
  p.add(test::fractional(cell, Vec3(0.01 + r + gap / 2, 0.01, 0.01)), r, 2650);
  p.v[0] = Vec3(v, 0, 0);
  p.v[1] = Vec3(-v, 0, 0);
  Simulation sim(p, cell, test::material(kn), damping, dt, 1e-4);
  Collision c;
  c.mass = sim.particles().mass[0];
  std::int64_t start = -1;
  double v_prev = 2 * v;
  for (int n = 0; n < 10'000'000; ++n) {
    sim.step(test::fixed_cell(), ServoSettings{});
    const double v_rel = (sim.particles().v[0] - sim.particles().v[1]).x();  // closing speed, > 0 on approach
    if (start < 0 && sim.sums().contacts == 1) {
      start = n;
      c.speed_before = v_prev;
    } else if (start >= 0 && sim.sums().contacts == 0) {
      c.contact_time = static_cast<double>(n - start) * dt;
      c.speed_after = -v_rel;
      return c;
    }
    v_prev = v_rel;
  }
  FAIL("no complete collision");
  return c;
}

}  // namespace

TEST_CASE("head-on spheres: linear contact lasts pi*sqrt(m*/kn), m* = m/2", "[dynamics][collision]") {
  const double kn = 1e5;
  const double m = 2650 * sphere_volume(1e-3);
  const double t_c = pi * std::sqrt(0.5 * m / kn);  // 23 us
  const double dt = t_c / 2000;
  const Collision c = collide(kn, dt, 0.1, test::no_damping());
  REQUIRE(c.mass == Approx(m).epsilon(1e-15));
  // Contact start and end are each detected within one step, so |t - t_c| < 2 dt; the leapfrog
  // frequency error (t_c (omega dt)^2 / 24 ~ 1e-7 t_c) is far below one step.
  REQUIRE(std::abs(c.contact_time - t_c) <= 2 * dt);
}

TEST_CASE("head-on spheres: undamped rebound speed equals approach speed within the leapfrog bound",
          "[dynamics][collision]") {
  // Leapfrog on the overlap delta (w = omega dt, omega^2 = kn/m*) conserves exactly
  //   J = (delta_{n+1} - delta_n)^2 + w^2 delta_n delta_{n+1}
  // inside the contact. Entering with the first overlap phi v dt (phi in (0,1]) gives
  // J = (v dt)^2 (1 - w^2 phi (1 - phi)), and leaving with phase psi likewise, so
  //   v_out^2 / v_in^2 = (1 - w^2 phi(1-phi)) / (1 - w^2 psi(1-psi)),   |v_out / v_in - 1| <= w^2 / 8 (1 + O(w^2)).
  // Out of contact the speed is exactly constant. We test at a coarse step (about 40 steps per
  // contact, a non-integer count so that entry and exit phases differ) where the bound is 7.5e-4.
  const double kn = 1e5;
  const double m_eff = 0.5 * 2650 * sphere_volume(1e-3);
  const double omega = std::sqrt(kn / m_eff);
  for (double steps_per_contact : {40.5, 40.27, 200.3}) {
    const double dt = pi / omega / steps_per_contact;
    const double w = omega * dt;
    const Collision c = collide(kn, dt, 0.1, test::no_damping());
    INFO("steps per contact " << steps_per_contact << ", v_out/v_in - 1 = " << c.speed_after / c.speed_before - 1);
    REQUIRE(c.speed_before == Approx(0.2).epsilon(1e-14));  // no force before contact: speed exact
    REQUIRE(std::abs(c.speed_after / c.speed_before - 1) <= w * w / 8 * (1 + w * w) + 1e-12);
    REQUIRE(std::abs(c.contact_time - pi / omega) <= 2 * dt);
  }
}

TEST_CASE("head-on spheres: viscous damping gives the damped-oscillator restitution", "[dynamics][collision][damping]") {
  // Body damping -c v on each sphere, c = 2 C_t sqrt(kn m): the overlap obeys
  //   delta'' + (c/m) delta' + (2 kn / m) delta = 0,   omega0^2 = 2 kn / m,   zeta = C_t / sqrt(2),
  // so the contact lasts pi / omega_d (omega_d = omega0 sqrt(1 - zeta^2)) and the rebound speed is
  //   e = exp(-zeta pi / sqrt(1 - zeta^2)) times the speed at contact onset.
  // The measured speeds are taken up to 2 dt away from the true onset/end, during which free flight
  // damps them at the rate c/m: relative error <= 2 dt c/m (4.4e-4 here); the semi-implicit damping
  // and the leapfrog add O((omega0 dt)^2) ~ 2.5e-6.
  const double kn = 1e5, C_t = 0.1;
  const double m = 2650 * sphere_volume(1e-3);
  const double omega0 = std::sqrt(2 * kn / m), zeta = C_t / std::sqrt(2.0);
  const double omega_d = omega0 * std::sqrt(1 - zeta * zeta);
  const double dt = pi / omega0 / 2000;
  Damping d = test::no_damping();
  d.translational = C_t;
  const Collision damped = collide(kn, dt, 0.1, d);
  const Collision elastic = collide(kn, dt, 0.1, test::no_damping());
  const double e = std::exp(-zeta * pi / std::sqrt(1 - zeta * zeta));  // 0.80
  const double c_over_m = 2 * C_t * std::sqrt(kn / m);
  REQUIRE(damped.speed_after < 0.9 * elastic.speed_after);
  REQUIRE(std::abs(damped.speed_after / damped.speed_before - e) <= e * (2 * dt * c_over_m + (omega0 * dt) * (omega0 * dt)));
  REQUIRE(std::abs(damped.contact_time - pi / omega_d) <= 2 * dt);
}
