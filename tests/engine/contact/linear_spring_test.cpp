// Linear spring contact with Coulomb friction (contact/linear_spring.hpp, LinearCoulomb): the tangential spring
// grows elastically as ks u_t, is capped at exactly mu f_n (sliding flag set), and is rotated into
// a new tangent plane with its magnitude kept.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/linear_spring.hpp"
#include "engine/contact/contact_support.hpp"
#include "engine/test_support.hpp"

using namespace dem;

TEST_CASE("Coulomb: elastic tangential force ks*u_t below mu*f_n, capped at mu*f_n above", "[contact][friction]") {
  const LinearCoulomb law{1e5, 0.5};         // ks [N/m], mu
  const double fn = 10.0;              // fixed normal force [N] -> cap mu fn = 5 N at u_t = 5e-5 m
  const double cap = law.mu * fn;
  const Vec3 n(1, 0, 0);
  const double dt = 1e-4, speed = 7e-3;  // 0.7 um of tangential displacement per call: cap reached between calls 71 and 72
  const Vec3 v_t(0, speed, 0);
  Vec3 spring = Vec3::Zero();
  bool sliding = true;
  double lost = -1;  // spring energy removed by the cap [J]
  int elastic_calls = 0, sliding_calls = 0;
  for (int k = 1; k <= 120; ++k) {
    const Vec3 f = test::tangential_step(law, spring, n, v_t, dt, fn, 0.0, 0.0, sliding, lost);
    const double elastic = law.ks * k * speed * dt;  // ks u_t with u_t = k v dt, the spring never having slipped
    // The spring stays in the tangent plane (v_t is tangential, n fixed), and opposes the motion of j.
    REQUIRE(std::abs(f.dot(n)) <= 1e-15 * f.norm());
    REQUIRE(f.dot(v_t) < 0);
    // Tolerances: u_t is a sum of k identical increments, so its relative round-off is <= k eps ~ 3e-14;
    // the capped magnitude is computed as ks * (|u| * limit / (ks |u|)), a few roundings: 1e-14.
    if (elastic < cap * (1 - 1e-9)) {
      REQUIRE_FALSE(sliding);
      REQUIRE(lost == 0.0);
      REQUIRE(f.norm() == Approx(elastic).epsilon(1e-12));
      ++elastic_calls;
    } else if (elastic > cap * (1 + 1e-9)) {
      REQUIRE(sliding);
      REQUIRE(f.norm() == Approx(cap).epsilon(1e-14));
      REQUIRE(spring.norm() == Approx(cap / law.ks).epsilon(1e-14));
      // Sliding on from the cap, the spring stays at the cap and slips by du = v dt: the cap takes
      // Coulomb's work mu fn du. (Round-off: a dot product of ~1e-5 m vectors and a difference of
      // two equal ~1e-4 J energies, relative 1e-10.)
      const double du = speed * dt;
      if (sliding_calls > 0) REQUIRE(lost == Approx(cap * du).epsilon(1e-9));
      ++sliding_calls;
    } else {
      continue;
    }
  }
  REQUIRE(elastic_calls == 71);
  REQUIRE(sliding_calls == 49);

  // Reversing the motion unloads the spring elastically from the cap: |f| = mu fn - ks * k v dt, not sliding.
  for (int k = 1; k <= 10; ++k) {
    const Vec3 f = test::tangential_step(law, spring, n, -v_t, dt, fn, 0.0, 0.0, sliding, lost);
    REQUIRE_FALSE(sliding);
    REQUIRE(f.norm() == Approx(cap - law.ks * k * speed * dt).epsilon(1e-12));
  }

  // A drop of the normal force below |f_t|/mu makes the contact slide at once, at the new cap.
  const Vec3 f = test::tangential_step(law, spring, n, Vec3::Zero(), dt, 2.0, 0.0, 0.0, sliding, lost);
  REQUIRE(sliding);
  REQUIRE(f.norm() == Approx(law.mu * 2.0).epsilon(1e-14));
}

TEST_CASE("Coulomb: a new normal rotates the spring into the new tangent plane, magnitude kept", "[contact][friction]") {
  const LinearCoulomb law{2e5, 0.6};
  const double fn = 1e3;  // cap 600 N, far above ks u = 2 N: no sliding
  const double u = 1e-5;
  bool sliding = true;
  double lost = 0;
  SECTION("rotation about z: (0,u,0) with n=(cos t, sin t, 0) becomes u(-sin t, cos t, 0)") {
    for (double theta : {0.1, 0.7, 1.3}) {
      Vec3 spring(0, u, 0);
      const Vec3 n(std::cos(theta), std::sin(theta), 0);
      const Vec3 f = test::tangential_step(law, spring, n, Vec3::Zero(), 1e-4, fn, 0.0, 0.0, sliding, lost);
      REQUIRE_FALSE(sliding);
      // The expected vector is the unit tangent closest to the old spring, times |u|; round-off only.
      const Vec3 expected = u * Vec3(-std::sin(theta), std::cos(theta), 0);
      REQUIRE((spring - expected).norm() <= 1e-14 * u);
      REQUIRE(f.norm() == Approx(law.ks * u).epsilon(1e-14));
      REQUIRE(std::abs(f.dot(n)) <= 1e-14 * f.norm());
    }
  }
  SECTION("rotation about y: (u,0,0) with n=(sin t, 0, cos t) becomes u(cos t, 0, -sin t)") {
    const double theta = 0.4;
    Vec3 spring(u, 0, 0);
    const Vec3 n(std::sin(theta), 0, std::cos(theta));
    test::tangential_step(law, spring, n, Vec3::Zero(), 1e-4, fn, 0.0, 0.0, sliding, lost);
    REQUIRE((spring - u * Vec3(std::cos(theta), 0, -std::sin(theta))).norm() <= 1e-14 * u);
  }
}

TEST_CASE("oblique contact in a simulation: normal kn*overlap, tangential -ks*v_t*dt, torques, sliding", "[contact][friction]") {
  // Two spheres overlapping along x, sliding past each other along y (j up, i down). After one force
  // evaluation the spring is u = v_rel dt, v_rel = 2w along y, so the tangential force on j is
  // -ks * 2 w dt along y, and both spheres get the torque -arm n x f_t = +arm ks 2 w dt along z.
  const double r = 1e-3, overlap = 2e-5, kn = 1e5, ks = 8e4, dt = 1e-7;
  const Vec3 L(0.02, 0.02, 0.02);
  PeriodicCell cell(L);
  const auto run = [&](double w, double mu, Vec3& f_j, Vec3& omega_i, Vec3& omega_j, bool& sliding) {
    Particles p;
    const Vec3 xi(0.01 - r + overlap / 2, 0.01, 0.01), xj(0.01 + r - overlap / 2, 0.01, 0.01);
    p.add(test::fractional(cell, xi), r, 2650);
    p.add(test::fractional(cell, xj), r, 2650);
    p.v[0] = Vec3(0, -w, 0);
    p.v[1] = Vec3(0, w, 0);
    Simulation sim(p, cell, test::material(kn, ks, mu), test::no_damping(), dt, 1e-4);
    sim.step(test::fixed_cell(), ServoSettings{});
    REQUIRE(sim.sums().contacts == 1);
    f_j = sim.net_force()[1];
    REQUIRE((sim.net_force()[0] + f_j).norm() <= 1e-15 * f_j.norm());  // action = reaction
    omega_i = sim.particles().omega[0];
    omega_j = sim.particles().omega[1];
    sliding = sim.history().sliding.at(0) != 0;
    return sim.particles().inertia[0];
  };
  Vec3 f, wi, wj;
  bool sliding = true;
  // Tolerance: the overlap comes from positions of O(1e-2) m converted to fractional coordinates and
  // back (a few roundings of ~1e-18 m) against an overlap of 2e-5 m: relative ~1e-13 on the normal
  // force and on the lever arm. The tangential values are products of exact inputs. We allow 1e-11.
  const double w = 0.05;  // ks 2 w dt = 8e-4 N, far below mu kn overlap = 1 N
  const double inertia = run(w, 0.5, f, wi, wj, sliding);
  REQUIRE_FALSE(sliding);
  REQUIRE(f.x() == Approx(kn * overlap).epsilon(1e-11));
  REQUIRE(f.y() == Approx(-ks * 2 * w * dt).epsilon(1e-11));
  REQUIRE(std::abs(f.z()) <= 1e-15);
  const double arm = r - overlap / 2;
  REQUIRE(wj.z() == Approx(dt * arm * ks * 2 * w * dt / inertia).epsilon(1e-11));
  REQUIRE(wi.z() == Approx(wj.z()).epsilon(1e-12));
  REQUIRE(std::abs(wi.x()) + std::abs(wi.y()) <= 1e-12 * wi.z());

  // Fast sliding: ks 2 w dt = 16 N > mu kn overlap = 1 N -> capped at exactly mu f_n, flag set.
  run(1000.0, 0.5, f, wi, wj, sliding);
  REQUIRE(sliding);
  REQUIRE(f.y() == Approx(-0.5 * f.x()).epsilon(1e-12));
}
