// Contact stress of a simple cubic lattice (analysis of StepSums and analysis/measurements.hpp).
//
// Equal spheres of diameter d on an n1 x n2 x n3 simple cubic lattice with spacing a_k < d per axis
// in a periodic cell L_k = n_k a_k. Each sphere has two contacts per axis, so there are N = n1 n2 n3
// contacts along each axis, each with overlap delta_k = d - a_k, force kn delta_k and branch a_k:
//   sigma_kk = (1/V) sum_c f_k l_k = N kn delta_k a_k / (N a1 a2 a3) = kn delta_k / (a_l a_m),
// and sigma_kl = 0 (k != l) because every contact force is parallel to an axis. The servo stiffness
// is K_k = (1/V) sum_c kn (n_k l_k)^2 = kn a_k / (a_l a_m).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "analysis/measurements.hpp"
#include "engine/test_support.hpp"

using namespace dem;

namespace {

Simulation lattice(const std::array<int, 3>& n, const Vec3& a, double d, double kn) {
  const PeriodicCell cell(Vec3(n[0] * a[0], n[1] * a[1], n[2] * a[2]));
  Particles p;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) p.add(Vec3((i + 0.5) / n[0], (j + 0.5) / n[1], (k + 0.5) / n[2]), d / 2, 2650);
  return Simulation(p, cell, test::material(kn), test::no_damping(), 1e-7, 0.05 * d);
}

// Tolerance: an overlap delta_k = d - a_k is the difference of two nearly equal numbers, so its
// relative round-off is ~ eps a/delta (~50 eps for a = 0.98 d); summing N equal terms adds ~N eps.
// Both are < 1e-13 here; we require relative 1e-12.
void check_lattice(const std::array<int, 3>& n, const Vec3& a) {
  const double d = 2e-3, kn = 1e5;
  Simulation sim = lattice(n, a, d, kn);
  sim.step(test::fixed_cell(), ServoSettings{});
  const std::size_t N = static_cast<std::size_t>(n[0] * n[1] * n[2]);
  const Mat3& sigma = sim.sums().stress_Pa;
  const Vec3 expected(kn * (d - a[0]) / (a[1] * a[2]), kn * (d - a[1]) / (a[0] * a[2]), kn * (d - a[2]) / (a[0] * a[1]));
  INFO("sigma =\n" << sigma);
  REQUIRE(sim.sums().contacts == 3 * N);
  for (int k = 0; k < 3; ++k) {
    REQUIRE(sigma(k, k) == Approx(expected[k]).epsilon(1e-12));
    REQUIRE(sim.sums().stiffness_Pa[k] == Approx(kn * a[k] * a[k] / a.prod()).epsilon(1e-12));
    for (int l = 0; l < 3; ++l)
      if (l != k) REQUIRE(std::abs(sigma(k, l)) <= 1e-12 * expected.maxCoeff());
  }
  // The measurements built on the stress: p = tr(sigma)/3 and q from the principal (= diagonal) values.
  REQUIRE(mean_stress(sigma) == Approx(expected.sum() / 3).epsilon(1e-12));
  const double q = std::sqrt(0.5 * ((expected[0] - expected[1]) * (expected[0] - expected[1]) +
                                    (expected[1] - expected[2]) * (expected[1] - expected[2]) +
                                    (expected[0] - expected[2]) * (expected[0] - expected[2])));
  REQUIRE(deviator_stress(sigma) == Approx(q).epsilon(1e-9).margin(1e-9 * expected.maxCoeff()));
  // Every sphere is balanced: the two contacts per axis cancel (round-off only).
  REQUIRE(unbalanced_force_ratio(sim) <= 1e-12);
  const ContactCounts counts = count_contacts(sim);
  REQUIRE(counts.contacts == 3 * N);
  REQUIRE(counts.particles_no_contact == 0);
  REQUIRE(coordination_number(counts.contacts, N) == 6.0);
  REQUIRE(mechanical_coordination_number(counts, N) == 6.0);
  // The survey recomputes the stress from the state after the step; the balanced lattice has not
  // moved (net forces are round-off), so it gives the same tensor, and the mean normal force is the
  // average of kn delta_k over the three axes (N contacts each).
  for (int k = 0; k < 3; ++k) REQUIRE(counts.stress_Pa(k, k) == Approx(expected[k]).epsilon(1e-12));
  REQUIRE((counts.stress_Pa - Mat3(expected.asDiagonal())).norm() <= 1e-12 * expected.norm());
  REQUIRE(counts.mean_normal_force_N == Approx(kn * (3 * d - a.sum()) / 3).epsilon(1e-12));
  // Void ratio: cell volume per sphere a1 a2 a3 against the sphere volume.
  REQUIRE(void_ratio(sim.particles(), sim.cell()) == Approx(a.prod() / sphere_volume(d / 2) - 1).epsilon(1e-13));
}

}  // namespace

TEST_CASE("simple cubic lattice: sigma_kk = kn (d - a)/a^2, no shear stress", "[analysis][stress]") {
  const double d = 2e-3;
  check_lattice({4, 4, 4}, Vec3(0.99, 0.99, 0.99) * d);
}

TEST_CASE("simple cubic lattice with a different spacing and count per axis: sigma_kk = kn delta_k/(a_l a_m)",
          "[analysis][stress]") {
  const double d = 2e-3;
  check_lattice({4, 5, 6}, Vec3(0.99, 0.995, 0.98) * d);
  check_lattice({6, 4, 5}, Vec3(0.985, 0.999, 0.97) * d);
}

TEST_CASE("simple cubic lattice without overlap carries no stress", "[analysis][stress]") {
  Simulation sim = lattice({4, 4, 4}, Vec3(1.001, 1.001, 1.001) * 2e-3, 2e-3, 1e5);
  sim.step(test::fixed_cell(), ServoSettings{});
  REQUIRE(sim.sums().contacts == 0);
  REQUIRE(sim.sums().stress_Pa.norm() == 0.0);
}

TEST_CASE("an overlapping lattice is measured before its first step", "[analysis][stress]") {
  // A simulation built from particles has no neighbour list until its first step; the survey
  // (the first row of a run, e.g. of a packing read from a CSV file) must still see the contacts
  // of the positions. It reported no contacts and zero stress before (found by the
  // LAMMPS test, tests/lammps/contact_stress_test.sh). Same expectation and tolerance as above.
  const double d = 2e-3, kn = 1e5;
  const std::array<int, 3> n{4, 5, 6};
  const Vec3 a = Vec3(0.99, 0.995, 0.98) * d;
  const Simulation sim = lattice(n, a, d, kn);
  REQUIRE(sim.step_count() == 0);
  REQUIRE(sim.pairs().size() == 0);  // no list yet
  const ContactCounts counts = count_contacts(sim);
  const std::size_t N = static_cast<std::size_t>(n[0] * n[1] * n[2]);
  REQUIRE(counts.contacts == 3 * N);
  const Vec3 expected(kn * (d - a[0]) / (a[1] * a[2]), kn * (d - a[1]) / (a[0] * a[2]), kn * (d - a[2]) / (a[0] * a[1]));
  REQUIRE((counts.stress_Pa - Mat3(expected.asDiagonal())).norm() <= 1e-12 * expected.norm());
  REQUIRE(counts.mean_normal_force_N == Approx(kn * (3 * d - a.sum()) / 3).epsilon(1e-12));
  REQUIRE(sim.verlet_list().builds() == 0);  // measuring did not touch the simulation
}
