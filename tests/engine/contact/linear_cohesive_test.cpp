// The linear spring with a constant pull-off force (contact/linear_cohesive.hpp): two spheres in a
// large periodic cell, against the closed forms of the oscillator m* x'' = -(kn x - f_c) while the
// overlap x is > 0, and its scene keys.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/test_support.hpp"

using namespace dem;
using test::pi;

namespace {

AnyContactLaw cohesive(double kn, double fc, double ks = 0, double mu = 0) {
  if (mu > 0) return LinearCohesiveFrictionLaw{LinearCohesiveNormal{{kn}, fc}, LinearCoulomb{ks, mu}, {}};
  return LinearCohesiveLaw{LinearCohesiveNormal{{kn}, fc}, {}, {}};
}

// Two spheres of radius 1 mm (density 2650) on the x axis at overlap `overlap` (< 0: a gap),
// moving at -+v along x (closing speed 2 v).
Simulation two_spheres(const AnyContactLaw& law, double overlap, double v, const Damping& damping, double dt) {
  const double r = 1e-3;
  PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(test::fractional(cell, Vec3(0.01 - r + overlap / 2, 0.01, 0.01)), r, 2650);
  p.add(test::fractional(cell, Vec3(0.01 + r - overlap / 2, 0.01, 0.01)), r, 2650);
  p.v[0] = Vec3(v, 0, 0);
  p.v[1] = Vec3(-v, 0, 0);
  return Simulation(p, cell, Material{2650, law}, damping, dt, 1e-4);
}

double overlap_of(const Simulation& sim) {
  const Particles& p = sim.particles();
  return p.radius[0] + p.radius[1] - sim.cell().branch(p.s[0], p.s[1]).norm();
}

}  // namespace

TEST_CASE("cohesive: a head-on contact lasts (pi + 2 atan(f_c omega / (kn V))) / omega", "[contact][cohesive]") {
  // Inside the contact m* x'' = -kn (x - x_eq), x_eq = f_c / kn, from x = 0 at the closing speed V:
  // x = x_eq + A sin(omega t - phi), sin(phi) = x_eq / A, A omega cos(phi) = V, so x is > 0 for
  // omega t in (0, pi + 2 phi), phi = atan(x_eq omega / V). f_c = 0 gives the linear law's pi / omega;
  // the pull lengthens the contact. Undamped, the spheres leave at the closing speed (U(0) = 0 at
  // entry and exit). Contact start and end are each detected within one step (2 dt); the pull
  // missed for part of the entry step (at most f_c V dt of energy) changes A by at most
  // (x_eq / A) V dt and t_c by at most 2 (x_eq / A)^2 dt < 2 dt: |t - t_c| <= 4 dt. The leapfrog's
  // period error, ~(omega dt)^2 / 24 of t_c with dt = t_c / 2000, is far smaller.
  const double kn = 1e5, m_star = 0.5 * 2650 * sphere_volume(1e-3), omega = std::sqrt(kn / m_star);
  const double v = 0.05, V = 2 * v;
  for (const double fc : {0.0, 0.05, 0.5}) {
    const double t_c = (pi + 2 * std::atan(fc * omega / (kn * V))) / omega, dt = t_c / 2000;
    Simulation sim = two_spheres(cohesive(kn, fc), -1e-7, v, test::no_damping(), dt);
    long first = -1, last = -1;
    double peak = 0;
    for (long n = 0; n < 10000 && (first < 0 || last < 0); ++n) {
      sim.step(test::fixed_cell(), ServoSettings{});
      if (sim.sums().contacts == 1 && first < 0) first = n;
      if (sim.sums().contacts == 1) peak = std::max(peak, overlap_of(sim));
      if (sim.sums().contacts == 0 && first >= 0) last = n;
    }
    REQUIRE(first >= 0);
    REQUIRE(last > first);
    const double t = double(last - first) * dt;
    const double x_eq = fc / kn, A = std::hypot(x_eq, V / omega);
    INFO("f_c " << fc << ": contact " << t << " s, closed form " << t_c << " s; peak overlap " << peak << " m, closed form "
                << x_eq + A);
    REQUIRE(std::abs(t - t_c) <= 4 * dt);
    // The peak overlap x_eq + A: the entry step's missed pull shifts A by at most (x_eq / A) V dt
    // < V dt; sampling the peak once a step (the speed is ~0 there) adds ~omega^2 A dt^2, far less.
    REQUIRE(std::abs(peak - (x_eq + A)) <= 2 * V * dt);
    // Elastic: the spheres leave at the speed they came with, up to the leapfrog's entry and exit
    // phases ((omega dt)^2 / 8) and one step of the f_c jump (f_c dt / (m* V) of V).
    const double leaving = (sim.particles().v[1] - sim.particles().v[0]).x();
    REQUIRE(std::abs(leaving / V - 1) <= std::pow(omega * dt, 2) / 8 + 2 * fc * dt / (m_star * V));
  }
}

TEST_CASE("cohesive: two spheres at rest settle at overlap f_c / kn, held by f_c", "[contact][cohesive]") {
  // With viscous body damping (C = 0.05 on each sphere: a relative-motion damping ratio
  // C / sqrt(2) = 0.035), the oscillation about x_eq = f_c / kn decays as exp(-0.035 omega t);
  // 150 periods (6.6e4 steps of T/440) take it below exp(-33) of its start, x_eq. At rest the
  // leapfrog's fixed point is exactly kn x = f_c: what is left is the rounding of positions of
  // O(1e-2) m (~1e-18 m) against x_eq = 5e-7 m.
  const double kn = 1e5, fc = 0.05, m_star = 0.5 * 2650 * sphere_volume(1e-3), omega = std::sqrt(kn / m_star);
  const double dt = 2 * pi / omega / 440.3;
  Simulation sim = two_spheres(cohesive(kn, fc), 1e-3 * fc / kn, 0, Damping{}, dt);
  for (int n = 0; n < 66000; ++n) sim.step(test::fixed_cell(), ServoSettings{});
  REQUIRE(sim.sums().contacts == 1);
  INFO("overlap " << overlap_of(sim) << " m, f_c / kn " << fc / kn << " m");
  REQUIRE(overlap_of(sim) == Approx(fc / kn).epsilon(1e-9));
  // The contact pulls each sphere with f_c less the spring: net zero at rest.
  REQUIRE(std::abs(sim.net_force()[1].x()) <= 1e-9 * fc);
}

TEST_CASE("cohesive: f_n = kn x - f_c, and friction capped at mu kn x (the elastic part)", "[contact][cohesive][friction]") {
  // Two spheres at overlap x sliding past each other along y, fast enough to slide after one
  // step (as linear_spring_test.cpp's oblique contact): the normal force on j is kn x - f_c along
  // x, the tangential force mu kn x (not mu (kn x - f_c)), the contact flagged sliding. Tolerance:
  // the overlap comes through fractional coordinates of a 0.02 m cell, a few roundings of ~2e-18 m;
  // we allow 1e-16 m of overlap (kn 1e-16 = 1e-11 N), absolute, as x goes down to 2e-7 m.
  const double r = 1e-3, kn = 1e5, ks = 8e4, mu = 0.5, dt = 1e-7;
  for (const double x : {2e-5, 2e-7}) {
    const double fc = 0.5;  // above kn x at the smaller overlap: the contact pulls, and still slides at mu kn x
    PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
    Particles p;
    p.add(test::fractional(cell, Vec3(0.01 - r + x / 2, 0.01, 0.01)), r, 2650);
    p.add(test::fractional(cell, Vec3(0.01 + r - x / 2, 0.01, 0.01)), r, 2650);
    p.v[0] = Vec3(0, -1000, 0);
    p.v[1] = Vec3(0, 1000, 0);
    Simulation sim(p, cell, Material{2650, cohesive(kn, fc, ks, mu)}, test::no_damping(), dt, 1e-4);
    sim.step(test::fixed_cell(), ServoSettings{});
    REQUIRE(sim.sums().contacts == 1);
    const Vec3 f = sim.net_force()[1];
    INFO("overlap " << x << ": force on j " << f.transpose());
    REQUIRE(sim.history().sliding.at(0) != 0);
    REQUIRE(std::abs(f.x() - (kn * x - fc)) <= kn * 1e-16);
    REQUIRE(std::abs(f.y() - (-mu * kn * x)) <= mu * kn * 1e-16);
  }
}

TEST_CASE("cohesive: material.law linear_cohesive reads kn and cohesion_force, friction as the linear law",
          "[contact][cohesive][config]") {
  const auto scene = [](const std::string& material) {
    return "name: c\nparticles:\n  lattice: {n: [3, 3, 3], spacing: 5.0e-3, seed: 1}\n"
           "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\nmaterial: " + material +
           "\nnumerics: {time_step: 1.0e-6}\nstages:\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-4}\n";
  };
  const SceneConfig with = scene_from_text(scene("{law: linear_cohesive, kn: 1.0e6, cohesion_force: 0.2, ks: 1.0e6, friction: 0.5}"), "c.yaml");
  REQUIRE(std::holds_alternative<LinearCohesiveFrictionLaw>(with.material.law));
  const auto& law = std::get<LinearCohesiveFrictionLaw>(with.material.law);
  CHECK(law.normal.kn == 1e6);
  CHECK(law.normal.cohesion_force_N == 0.2);
  CHECK(law.tangential.mu == 0.5);
  CHECK(law_name(with.material.law) == "linear_cohesive");
  CHECK(std::holds_alternative<LinearCohesiveLaw>(
      scene_from_text(scene("{law: linear_cohesive, kn: 1.0e6, cohesion_force: 0.2, friction: 0}"), "c.yaml").material.law));
  // The resolved scene writes it back as read.
  CHECK_THAT(with.resolved_yaml, Catch::Matchers::Contains("cohesion_force: 0.2"));
  // f_c >= 0 and required; the linear law does not read it.
  const auto refused = [&](const std::string& material) {
    try {
      scene_from_text(scene(material), "c.yaml");
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(refused("{law: linear_cohesive, kn: 1.0e6, cohesion_force: -0.1, friction: 0}"),
             Catch::Matchers::Contains("material.cohesion_force: must be in [0, 1e+06]"));
  CHECK_THAT(refused("{law: linear_cohesive, kn: 1.0e6, friction: 0}"), Catch::Matchers::Contains("material.cohesion_force: missing"));
  CHECK_THAT(refused("{kn: 1.0e6, cohesion_force: 0.1, friction: 0}"),
             Catch::Matchers::Contains("material.cohesion_force: belongs to material.law: linear_cohesive"));
  // `dem keys` documents it.
  CHECK_THAT(scene_key_reference(), Catch::Matchers::Contains("material.cohesion_force [N]; [0, 1e+06]; required;"));
}
