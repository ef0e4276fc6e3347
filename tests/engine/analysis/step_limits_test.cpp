// The time-step measures of a state (analysis/measurements.hpp): the time step over the law's
// critical step, over the leapfrog limit at the stiffest contact, and the contact dashpots' step
// number; and the cause the energy guard names from them (run/run_scene.hpp).
#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/measurements.hpp"
#include "engine/test_support.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

// Two spheres of radius 1 mm, density 2650, overlapping by 10 um along x in a 20 mm cell, at rest,
// after one step of dt (1e-9 s: they move by F dt^2 / m, 3e-12 m for the 35 N of the glass Hertz
// contact, so the overlap stays 10 um to 1e-6 of it); the test takes the overlap back from the
// positions.
struct Pair {
  Simulation sim;
  double overlap;
};
Pair pressed(const AnyContactLaw& law, double dt = 1e-9) {
  const double r = 1e-3, overlap = 1e-5;
  PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(test::fractional(cell, Vec3(0.01 - r + overlap / 2, 0.01, 0.01)), r, 2650);
  p.add(test::fractional(cell, Vec3(0.01 + r - overlap / 2, 0.01, 0.01)), r, 2650);
  Damping off;
  off.form = Damping::Form::Local, off.translational = 0, off.rotational = 0;
  Simulation sim(p, cell, Material{2650, law}, off, dt, 1e-4);
  sim.step(test::fixed_cell(), ServoSettings{});
  const double dist = sim.cell().branch(sim.particles().s[0], sim.particles().s[1]).norm();
  return {std::move(sim), 2 * r - dist};
}

const HertzNormal glass{70e9, 0.25};

}  // namespace

TEST_CASE("time step over the critical step: the law's formula, and Hertz at its stiffest contact", "[analysis][step]") {
  const double m = 2650 * sphere_volume(1e-3), m_star = m / 2, R = 0.5e-3;
  SECTION("linear: both are 2 sqrt(m_min / kn)") {
    const Pair pair = pressed(linear_law(1e6, 1e6, 0.5));
    const double critical = 2 * std::sqrt(m / 1e6);
    CHECK(time_step_over_critical(pair.sim) == Approx(1e-9 / critical).epsilon(1e-12));
    CHECK(time_step_over_contact_critical(pair.sim) == Approx(1e-9 / critical).epsilon(1e-12));
  }
  SECTION("Hertz: Rayleigh's step, and 2 sqrt(m_min / k_n) with k_n = 2 E* sqrt(R* overlap)") {
    const Pair pair = pressed(HertzMindlinLaw{glass, MindlinCoulomb::of(glass, 0.5), {}});
    const double G = 70e9 / (2 * 1.25);
    const double rayleigh = test::pi * 1e-3 * std::sqrt(2650 / G) / (0.1631 * 0.25 + 0.8766);
    CHECK(time_step_over_critical(pair.sim) == Approx(1e-9 / rayleigh).epsilon(1e-12));
    const double kn = 2 * (70e9 / (2 * (1 - 0.25 * 0.25))) * std::sqrt(R * pair.overlap);  // 2 E* sqrt(R* overlap)
    CHECK(std::abs(pair.overlap - 1e-5) < 1e-11);
    CHECK(time_step_over_contact_critical(pair.sim) == Approx(1e-9 / (2 * std::sqrt(m / kn))).epsilon(1e-9));
  }
  SECTION("contact dashpots: the limit times sqrt(1 + zeta^2) - zeta; the step number dt sum c / m") {
    const double zeta = 0.3;
    const Pair pair = pressed(HertzMindlinDashpotLaw{Dashpot<HertzNormal>{glass, zeta}, MindlinCoulomb::of(glass, 0.5), {}});
    const double kn = 2 * (70e9 / (2 * (1 - 0.25 * 0.25))) * std::sqrt(R * pair.overlap);
    const double G_star = 70e9 / (2 * 1.25) / (2 * (2 - 0.25));  // G / (2 (2 - nu)), G = E / (2 (1 + nu))
    const double kt = 8 * G_star * std::sqrt(R * pair.overlap);
    const double factor = std::sqrt(1 + zeta * zeta) - zeta;
    CHECK(time_step_over_contact_critical(pair.sim) == Approx(1e-9 / (2 * std::sqrt(m / kn) * factor)).epsilon(1e-9));
    // One contact per sphere: dt c / m with c = 2 zeta sqrt(m* max(k_n, k_t)).
    CHECK(dashpot_step_number(pair.sim) == Approx(1e-9 * 2 * zeta * std::sqrt(m_star * std::max(kn, kt)) / m).epsilon(1e-9));
  }
  SECTION("no dashpots: step number 0; no contact: contact measure 0") {
    CHECK(dashpot_step_number(pressed(linear_law(1e6, 1e6, 0.5)).sim) == 0.0);
    PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
    Particles p;
    p.add(Vec3(0.1, 0.1, 0.1), 1e-3, 2650);
    p.add(Vec3(0.6, 0.6, 0.6), 1e-3, 2650);
    Simulation sim(p, cell, test::material(1e6), test::no_damping(), 1e-9, 1e-4);
    sim.step(test::fixed_cell(), ServoSettings{});
    CHECK(time_step_over_contact_critical(sim) == 0.0);
  }
}

TEST_CASE("the energy guard's cause: dashpots past their explicit limit, the time step, Mindlin's spring", "[analysis][step][energy]") {
  // One contact between equal spheres: dt sum c / m = dt 2 zeta sqrt(m/2 kn) / m = sqrt(2) zeta w,
  // w = dt sqrt(kn / m); zeta = 0.95 and w = 0.45 give 0.60 (>= 0.5: the dashpots are named), and
  // the step moves each sphere by w^2 = 0.2 of the overlap, so the contact stays.
  const double m = 2650 * sphere_volume(1e-3), omega = std::sqrt(1e6 / m);
  const auto linear_dashpot = [](double zeta) { return AnyContactLaw{LinearDashpotLaw{Dashpot<LinearNormal>{{1e6}, zeta}, {}, {}}}; };
  const Pair stiff = pressed(linear_dashpot(0.95), 0.45 / omega);
  REQUIRE(stiff.sim.sums().contacts == 1);
  REQUIRE(dashpot_step_number(stiff.sim) == Approx(std::sqrt(2.0) * 0.95 * 0.45).epsilon(1e-9));
  CHECK(energy_error_cause(stiff.sim).find("the contact dashpots are past their explicit limit") == 0);
  // Dashpots at dt = 1e-7 s (w = 0.03, step number 0.021): the time step is named, hedged.
  const std::string fine = energy_error_cause(pressed(linear_dashpot(0.5), 1e-7).sim);
  CHECK(fine.find("the time step (1e-07 s") == 0);
  CHECK(fine.find("may be too large") != std::string::npos);
  // Above 0.2 x critical (allowed on purpose): the time step, plainly.
  const std::string coarse = energy_error_cause(pressed(linear_law(1e6, 1e6, 0.5), 1.5 * std::sqrt(m / 1e6)).sim);
  CHECK(coarse.find("x critical, 2 sqrt(m_min/kn)) is too large") != std::string::npos);
  // Hertz-Mindlin within the limit: its tangential spring.
  const std::string mindlin = energy_error_cause(pressed(HertzMindlinLaw{glass, MindlinCoulomb::of(glass, 0.5), {}}).sim);
  CHECK(mindlin.find("Hertz-Mindlin's tangential spring is incremental") == 0);
  CHECK(mindlin.find("raise numerics.max_energy_error") != std::string::npos);
}
