// Per-axis cell control (control/stress_servo.hpp): strain-rate axes, stress axes with and without
// contacts, and the affine-stiffness servo acting on a lattice whose stress response is known exactly.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/test_support.hpp"

using namespace dem;

namespace {
AxisTarget stress_target(double sigma, double rate = 0) {
  AxisTarget t;
  t.mode = AxisTarget::Mode::Stress;
  t.stress_Pa = sigma;
  t.stress_rate_Pa_per_s = rate;
  return t;
}
AxisTarget strain_rate_target(double rate) {
  AxisTarget t;
  t.strain_rate_per_s = rate;
  return t;
}
}  // namespace

TEST_CASE("servo: strain-rate axes return the prescribed rate, stress axes without contacts move at the cap",
          "[control][servo]") {
  ServoSettings s;
  s.gain = 0.01;
  s.max_strain_rate_per_s = 0.5;
  const double dt = 1e-6;
  SECTION("no contacts (K = 0): sign of the error, at the cap") {
    const CellTargets t{stress_target(1e5), stress_target(-2e3), stress_target(0)};
    const Vec3 rate = servo_strain_rates(t, Mat3::Zero(), Vec3::Zero(), s, dt);
    REQUIRE(rate == Vec3(0.5, -0.5, 0.0));  // compress towards a compressive target, expand from tension, rest at zero error
  }
  SECTION("strain-rate axes: the prescribed rate, whatever the stress, not capped") {
    Mat3 sigma = Mat3::Identity() * 3e4;
    const CellTargets t{strain_rate_target(0.2), strain_rate_target(-0.05), strain_rate_target(7.0)};
    REQUIRE(servo_strain_rates(t, sigma, Vec3(1e6, 1e6, 1e6), s, dt) == Vec3(0.2, -0.05, 7.0));
    REQUIRE(servo_strain_rates(CellTargets{}, sigma, Vec3(1e6, 1e6, 1e6), s, dt) == Vec3::Zero());
  }
  SECTION("with contacts: rate = (gain error / dt + target rate) / K, zero at zero error, clamped") {
    Mat3 sigma = Mat3::Zero();
    sigma.diagonal() = Vec3(1e5, 2e5, 3e5);
    const Vec3 K(4e7, 5e7, 6e7);
    // x: zero error, static target -> exactly 0. y: error 1e3 Pa -> 0.01 * 1e3 / 1e-6 / 5e7 = 0.2 /s.
    // z: zero error, moving target 6e6 Pa/s -> feed-forward 6e6 / 6e7 = 0.1 /s.
    const CellTargets t{stress_target(1e5), stress_target(2e5 + 1e3), stress_target(3e5, 6e6)};
    const Vec3 rate = servo_strain_rates(t, sigma, K, s, dt);
    REQUIRE(rate.x() == 0.0);
    REQUIRE(rate.y() == Approx(0.2).epsilon(1e-14));
    REQUIRE(rate.z() == Approx(0.1).epsilon(1e-14));
    // An error 10x larger would ask for 2 /s: clamped to the cap, either sign.
    const CellTargets big{stress_target(1e5 + 1e4), stress_target(2e5 - 1e4), stress_target(3e5)};
    REQUIRE(servo_strain_rates(big, sigma, K, s, dt) == Vec3(0.5, -0.5, 0.0));
  }
}

TEST_CASE("servo in a simulation: an empty cell under a stress target shrinks at the capped rate", "[control][servo]") {
  Particles p;
  p.add(Vec3(0.5, 0.5, 0.5), 1e-3, 2650);
  Simulation sim(p, PeriodicCell(Vec3(0.02, 0.02, 0.02)), test::material(1e5), test::no_damping(), 1e-6, 1e-4);
  ServoSettings s;
  s.max_strain_rate_per_s = 0.3;
  const CellTargets t{stress_target(1e4), strain_rate_target(0.1), AxisTarget{}};
  for (int n = 0; n < 10; ++n) sim.step(t, s);
  REQUIRE(sim.strain_rate() == Vec3(0.3, 0.1, 0.0));
  // L = L0 exp(-rate t) after 10 steps of 1 us: ten roundings of exp and a product, relative 1e-14.
  REQUIRE(sim.cell().lengths().x() == Approx(0.02 * std::exp(-0.3 * 1e-5)).epsilon(1e-14));
  REQUIRE(sim.cell().lengths().y() == Approx(0.02 * std::exp(-0.1 * 1e-5)).epsilon(1e-14));
  REQUIRE(sim.cell().lengths().z() == 0.02);
}

TEST_CASE("servo in a simulation: on an affine lattice one step removes the fraction `gain` of the error",
          "[control][servo]") {
  // 4x4x4 simple cubic lattice (spacing a = 0.99 d; all fractional coordinates are multiples of 1/8,
  // so every sphere is balanced exactly and stays at its site: the lattice deforms affinely).
  // sigma_xx = kn (d - a_x)/(a_y a_z) and K_x = kn a_x/(a_y a_z). One servo step with rate r on x
  // changes a_x to a_x exp(-r dt), so the stress changes by exactly
  //   d_sigma = kn a_x (1 - exp(-r dt))/(a_y a_z) = K_x (1 - exp(-g e / K_x)),   r dt = g e / K_x,
  // i.e. g e to first order: the servo removes the fraction g of the error e, as designed.
  const double d = 2e-3, a = 0.99 * d, kn = 1e5, dt = 1e-7;
  Particles p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) p.add(Vec3((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4), d / 2, 2650);
  Simulation sim(p, PeriodicCell(Vec3(4 * a, 4 * a, 4 * a)), test::material(kn), test::no_damping(), dt, 1e-4);
  const double sigma0 = kn * (d - a) / (a * a), K = kn / a;
  const double error = 0.5 * sigma0;  // target 1.5 sigma0
  ServoSettings s;
  s.gain = 0.2;
  s.max_strain_rate_per_s = 1e6;  // not limiting
  const CellTargets t{stress_target(sigma0 + error), AxisTarget{}, AxisTarget{}};
  sim.step(t, s);
  // Tolerances: the lattice formulas hold to relative 1e-13 (overlap round-off, see lattice_stress_test);
  // the stress change g e = 0.1 sigma0 inherits ~1e-12 of that.
  REQUIRE(sim.sums().stress_Pa(0, 0) == Approx(sigma0).epsilon(1e-12));
  REQUIRE(sim.sums().stiffness_Pa.x() == Approx(K).epsilon(1e-12));
  REQUIRE(sim.strain_rate().x() == Approx(s.gain * error / (K * dt)).epsilon(1e-12));
  for (const Vec3& v : sim.particles().v) REQUIRE(v == Vec3::Zero());
  sim.step(CellTargets{}, s);  // measures the stress of the deformed lattice
  const double expected_change = K * (1 - std::exp(-s.gain * error / K));
  REQUIRE(sim.sums().stress_Pa(0, 0) - sigma0 == Approx(expected_change).epsilon(1e-10));
  // First order: r dt = g e / K = 1.0e-3, so the second-order term is 5e-4 relative.
  REQUIRE(expected_change == Approx(s.gain * error).epsilon(1e-3));
}

TEST_CASE("adaptive servo: the shears learn their own stiffness ratio when no axis is stress-controlled",
          "[control][servo]") {
  // A linear "packing" whose shear stress responds to the shear rate with 10 % of the affine
  // estimate sqrt(K_xx K_yy)/3 = 1e7 Pa, while every axis is held at fixed strain (cyclic simple
  // shear at constant volume): the axes teach nothing, so only the shears' own ratio can correct
  // the estimate. Expected (the learning rule in control/stress_servo.cpp): kappa_shear converges
  // to the true ratio 0.1, the axes' ratio stays 1, and with the learnt stiffness and the
  // feed-forward term the shear stress follows its sine.
  const double dt = 1e-6, affine = 1e7, true_ratio = 0.1, amplitude = 1e4, period_steps = 20000;
  const Vec3 axes_stiffness = Vec3::Constant(3 * affine);
  ServoSettings settings;
  settings.max_strain_rate_per_s = 10;
  AdaptiveServo servo(settings);
  CellControl c;  // axes at zero strain rate (the default)
  c.component[4] = c.component[5] = stress_target(0);
  Mat3 stress = Mat3::Identity() * 1e5;
  const double w = 2 * M_PI / period_steps;
  double worst = 0, axial = 0;
  for (int i = 0; i < 3 * period_steps; ++i) {
    c.component[3] = stress_target(amplitude * std::sin(w * i), amplitude * w / dt * std::cos(w * i));
    const CellRates g = servo.rates(c, stress, axes_stiffness, dt);
    axial = std::max(axial, g.axial.cwiseAbs().maxCoeff());
    stress(0, 1) = stress(1, 0) = stress(0, 1) + true_ratio * affine * g.shear[0] * dt;
    if (i >= 2 * period_steps) worst = std::max(worst, std::abs(stress(0, 1) - amplitude * std::sin(w * (i + 1))));
  }
  INFO("kappa_shear " << servo.shear_ratio() << ", worst error in the third cycle " << worst << " Pa");
  CHECK(servo.shear_ratio() == Approx(true_ratio).epsilon(0.02));
  CHECK(servo.stiffness_ratio() == Vec3::Ones());
  CHECK(axial == 0);
  // The servo removes 1e-3 of the error per step and the feed-forward is exact once kappa is: what
  // is left is the learning's last 2 % (the lag of a ramp, rate dt (1 - k/k_true) / (gain k/k_true),
  // at the sine's peak rate 3.1 Pa/step: ~60 Pa); a servo that kept the affine estimate lags by
  // about the whole amplitude (the stress moves 10 times too little per step).
  CHECK(worst < 0.02 * amplitude);
}
