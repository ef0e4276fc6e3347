// Contact fabric and the pi-plane (engine/analysis/fabric.hpp; paper Eqs. 8-10, docs/method.md#measures):
//   F   = (1/Nc) sum_c n (x) n                        over all contacts,
//   F^s = (1/Nc) sum_{c: f_n > mean f_n} n (x) n      with the *total* Nc in the denominator,
// invariants m = tr/3 and d = sqrt(((T11-T22)^2 + (T22-T33)^2 + (T11-T33)^2)/2) on the diagonal,
// and the pi-plane x = (v3 - v2)/sqrt(2), y = (2 v1 - v2 - v3)/sqrt(6).
//
// The expectations come from symmetry and hand sums, not from the engine: a set of directions
// invariant under a symmetry group that acts irreducibly on R^3 (the octahedral, icosahedral
// groups) has sum n n = (N/3) I; n = e1 only gives e1 e1; and so on.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/fabric.hpp"
#include "analysis/measurements.hpp"
#include "analysis/time_series.hpp"
#include "engine/test_support.hpp"

using namespace dem;

namespace {

constexpr double phi = std::numbers::phi;  // golden ratio

std::vector<Vec3> normalised(std::vector<Vec3> v) {
  for (Vec3& n : v) n.normalize();
  return v;
}

// The 6 vertices of a regular octahedron: +-e_i.
std::vector<Vec3> octahedron() {
  return {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
}

// The 12 vertices of a regular icosahedron: cyclic permutations of (0, +-1, +-phi).
std::vector<Vec3> icosahedron() {
  std::vector<Vec3> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      v.emplace_back(0, a, b);
      v.emplace_back(a, b, 0);
      v.emplace_back(b, 0, a);
    }
  return normalised(v);
}

// The 20 vertices of a regular dodecahedron: (+-1, +-1, +-1) and cyclic permutations of
// (0, +-1/phi, +-phi).
std::vector<Vec3> dodecahedron() {
  std::vector<Vec3> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0})
      for (double c : {-1.0, 1.0}) v.emplace_back(a, b, c);
  for (double a : {-1 / phi, 1 / phi})
    for (double b : {-phi, phi}) {
      v.emplace_back(0, a, b);
      v.emplace_back(a, b, 0);
      v.emplace_back(b, 0, a);
    }
  return normalised(v);
}

// Largest |entry| of a - b.
double max_diff(const Mat3& a, const Mat3& b) { return (a - b).cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("fabric: isotropic direction sets give F = I/3 and F_d = 0", "[analysis][fabric]") {
  // Round-off: each entry is a sum of N <= 20 products of unit-vector components, error ~N eps.
  const double tol = 1e-15;
  const Mat3 third = Mat3::Identity() / 3.0;
  for (const auto& [name, set] : {std::pair{"octahedron (6)", octahedron()}, std::pair{"icosahedron (12)", icosahedron()},
                                  std::pair{"dodecahedron (20)", dodecahedron()}}) {
    INFO(name);
    REQUIRE(set.size() >= 6);
    for (const Vec3& n : set) REQUIRE(n.norm() == Approx(1.0).epsilon(1e-15));
    const Mat3 f = fabric_tensor(set);
    CHECK(max_diff(f, third) <= tol);
    CHECK(f.trace() == Approx(1.0).epsilon(1e-15));  // tr F = 1 for unit normals, always
    CHECK(mean_invariant(f) == Approx(1.0 / 3).epsilon(1e-15));
    CHECK(std::abs(deviator_invariant(f)) <= tol);
    // The same set rotated arbitrarily is still isotropic (sum n n = (N/3) I is rotation invariant).
    const Mat3 rot = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.9, Vec3(0.3, -1, 0.2).normalized()))
                         .toRotationMatrix();
    std::vector<Vec3> turned;
    for (const Vec3& n : set) turned.push_back(rot * n);
    CHECK(max_diff(fabric_tensor(turned), third) <= 4 * tol);
  }
}

TEST_CASE("fabric: all normals along one axis give F = e1 e1, any sign", "[analysis][fabric]") {
  // n and -n describe the same contact plane: n n is even in n.
  const std::vector<Vec3> along_1 = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(1, 0, 0)};
  Mat3 e11 = Mat3::Zero();
  e11(0, 0) = 1;
  CHECK(fabric_tensor(along_1) == e11);  // exact: only 0s and 1s are summed, then divided by 3
  // Invariants of diag(1, 0, 0): m = 1/3, d = sqrt((1 + 0 + 1)/2) = 1, ratio d/m = 3.
  CHECK(mean_invariant(e11) == Approx(1.0 / 3));
  CHECK(deviator_invariant(e11) == Approx(1.0));
  // Two orthogonal axes in equal numbers: diag(1/2, 1/2, 0).
  const Mat3 f12 = fabric_tensor(std::vector<Vec3>{Vec3(0, 1, 0), Vec3(1, 0, 0)});
  CHECK(f12 == Vec3(0.5, 0.5, 0).asDiagonal().toDenseMatrix());
  // No contacts: zero, not NaN.
  CHECK(fabric_tensor(std::vector<Vec3>{}) == Mat3::Zero());
  CHECK(strong_fabric_tensor(std::vector<Vec3>{}, std::vector<double>{}) == Mat3::Zero());
}

TEST_CASE("fabric: an oblique normal gives the off-diagonal terms n_i n_j", "[analysis][fabric]") {
  // n = (1, 1, 0)/sqrt(2): n n = [[1/2, 1/2, 0], [1/2, 1/2, 0], [0, 0, 0]].
  const Mat3 f = fabric_tensor(std::vector<Vec3>{Vec3(1, 1, 0).normalized()});
  CHECK(f(0, 1) == Approx(0.5));
  CHECK(f(1, 0) == Approx(0.5));
  CHECK(f(0, 0) == Approx(0.5));
  CHECK(f(2, 2) == 0);
  CHECK(f(0, 2) == 0);
}

TEST_CASE("strong fabric: the total contact count divides, and strong means f_n strictly above the mean", "[analysis][fabric]") {
  // 4 contacts: two along e1 with f_n = 3 N, one along e2 and one along e3 with 1 N. Mean 2 N:
  // the two e1 contacts are strong. F^s = (1/4)(2 e1 e1) = diag(1/2, 0, 0) (Eq. 9 divides by the
  // total Nc = 4, not by the 2 strong ones), so tr F^s = 2/4 = the fraction of strong contacts.
  const std::vector<Vec3> n = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Mat3 fs = strong_fabric_tensor(n, std::vector<double>{3, 3, 1, 1});
  CHECK(fs == Vec3(0.5, 0, 0).asDiagonal().toDenseMatrix());
  CHECK(fs.trace() == 0.5);
  // The ordinary fabric of the same set: diag(1/2, 1/4, 1/4); F^s <= F entry by entry on the diagonal.
  const Mat3 f = fabric_tensor(n);
  CHECK(f == Vec3(0.5, 0.25, 0.25).asDiagonal().toDenseMatrix());

  // Forces equal to the mean are not strong (strict >): all equal -> F^s = 0.
  CHECK(strong_fabric_tensor(n, std::vector<double>{2, 2, 2, 2}) == Mat3::Zero());
  // f_n = (1, 2, 3, 2): mean 2; only the e2 contact (3 N) is strong; the two at exactly 2 N are not.
  const Mat3 one = strong_fabric_tensor(n, std::vector<double>{1, 2, 3, 2});
  CHECK(one == Vec3(0, 0.25, 0).asDiagonal().toDenseMatrix());
  // One contact far stronger than the rest: 1 strong of 4 whatever its direction.
  CHECK(strong_fabric_tensor(n, std::vector<double>{0.1, 0.1, 0.1, 100}).trace() == 0.25);
}

TEST_CASE("fabric invariants of diag(a, b, c)", "[analysis][fabric]") {
  // m = (a + b + c)/3, d = sqrt(((a-b)^2 + (b-c)^2 + (a-c)^2)/2), by hand:
  //   diag(3, 1, 1): m = 5/3, d = sqrt((4 + 0 + 4)/2) = 2;
  //   diag(1, 2, 4): m = 7/3, d = sqrt((1 + 4 + 9)/2) = sqrt(7);
  //   diag(2, 2, 2): m = 2, d = 0; d is invariant under a common shift and scales with the tensor.
  const auto diag = [](double a, double b, double c) { return Vec3(a, b, c).asDiagonal().toDenseMatrix(); };
  CHECK(mean_invariant(diag(3, 1, 1)) == Approx(5.0 / 3));
  CHECK(deviator_invariant(diag(3, 1, 1)) == Approx(2.0));
  CHECK(mean_invariant(diag(1, 2, 4)) == Approx(7.0 / 3));
  CHECK(deviator_invariant(diag(1, 2, 4)) == Approx(std::sqrt(7.0)));
  CHECK(mean_invariant(diag(2, 2, 2)) == 2);
  CHECK(deviator_invariant(diag(2, 2, 2)) == 0);
  CHECK(deviator_invariant(diag(11, 12, 14)) == Approx(std::sqrt(7.0)));
  CHECK(deviator_invariant(diag(-2, -4, -8)) == Approx(2 * std::sqrt(7.0)));
  // Order of the entries does not matter.
  CHECK(deviator_invariant(diag(4, 1, 2)) == Approx(std::sqrt(7.0)));
  // For a stress diag(s1, s2, s3) they are p and q: TC1 at p = 100 kPa, R = 1.24 is
  // (114814.8, 92592.6, 92592.6) Pa: q = 22222.2 Pa = 3p(R-1)/(R+2).
  const double p = 1e5, R = 1.24;
  const Mat3 tc1 = diag(3 * p * R / (R + 2), 3 * p / (R + 2), 3 * p / (R + 2));
  CHECK(mean_invariant(tc1) == Approx(p).epsilon(1e-14));
  CHECK(deviator_invariant(tc1) == Approx(3 * p * (R - 1) / (R + 2)).epsilon(1e-12));
  CHECK(deviator_invariant(tc1) == Approx(22222.22).epsilon(1e-6));
}

TEST_CASE("pi-plane: TC1 up, TC2 lower left, TC3 lower right, 120 degrees apart, A at the origin", "[analysis][fabric]") {
  const double p = 1e5, R = 1.24;
  const double major = 3 * p * R / (R + 2), minor = 3 * p / (R + 2);  // TC states
  const Eigen::Vector2d tc1 = pi_plane(Vec3(major, minor, minor));
  const Eigen::Vector2d tc2 = pi_plane(Vec3(minor, major, minor));
  const Eigen::Vector2d tc3 = pi_plane(Vec3(minor, minor, major));
  CHECK(tc1.x() == 0);  // exact: v3 - v2 = 0
  CHECK(tc1.y() > 0);
  CHECK(tc2.x() < 0);
  CHECK(tc2.y() < 0);
  CHECK(tc3.x() > 0);
  CHECK(tc3.y() < 0);
  // Same distance from the origin: |(x, y)| = sqrt(2/3) x the deviator q = sqrt(2/3) (major - minor).
  const double radius = std::sqrt(2.0 / 3.0) * (major - minor);
  for (const Eigen::Vector2d& v : {tc1, tc2, tc3}) CHECK(v.norm() == Approx(radius).epsilon(1e-14));
  // 120 degrees apart: cos = -1/2 for every pair.
  CHECK(tc1.dot(tc2) / (tc1.norm() * tc2.norm()) == Approx(-0.5).epsilon(1e-14));
  CHECK(tc2.dot(tc3) / (tc2.norm() * tc3.norm()) == Approx(-0.5).epsilon(1e-14));
  CHECK(tc3.dot(tc1) / (tc3.norm() * tc1.norm()) == Approx(-0.5).epsilon(1e-14));
  // TC2 is TC1 turned by +120 degrees (counter-clockwise), TC3 by -120 degrees.
  const Eigen::Rotation2Dd turn(2 * std::numbers::pi / 3);
  CHECK((turn * tc1 - tc2).norm() <= 1e-10 * radius);
  CHECK((turn.inverse() * tc1 - tc3).norm() <= 1e-10 * radius);
  // A (isotropic) maps to the origin exactly; adding an isotropic part moves nothing.
  CHECK(pi_plane(Vec3(p, p, p)) == Eigen::Vector2d::Zero());
  CHECK((pi_plane(Vec3(major + 5e4, minor + 5e4, minor + 5e4)) - tc1).norm() <= 1e-10 * radius);
  // TE1 (axis 1 minor) points straight down.
  const Eigen::Vector2d te1 = pi_plane(Vec3(3 * p / (2 * R + 1), 3 * p * R / (2 * R + 1), 3 * p * R / (2 * R + 1)));
  CHECK(te1.x() == 0);
  CHECK(te1.y() < 0);
}

TEST_CASE("measure_row: fabric columns of a simple cubic lattice compressed along one or all axes", "[analysis][fabric]") {
  // Equal spheres of d = 2 mm on a 4 x 4 x 4 simple cubic lattice. Each sphere touches its two
  // neighbours on an axis whose spacing a_k is below d (see lattice_stress_test.cpp): 64
  // contacts per such axis, all with normals +-e_k and force kn (d - a_k).
  const double d = 2e-3, kn = 1e6;
  const auto lattice = [&](const Vec3& a) {
    const PeriodicCell cell(4 * a);
    Particles p;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) p.add(Vec3((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4), d / 2, 2650);
    return Simulation(p, cell, test::material(kn), test::no_damping(), 1e-7, 0.05 * d);
  };
  const auto column = [](const std::vector<double>& row, const std::string& name) {
    const auto& cols = series_columns();
    for (std::size_t c = 0; c < cols.size(); ++c)
      if (cols[c].name == name) return row[c];
    FAIL("no column " << name);
    return 0.0;
  };
  SECTION("contacts along axis 1 only: F = diag(1, 0, 0)") {
    Simulation sim = lattice(Vec3(1.99e-3, 2.1e-3, 2.1e-3));
    sim.step(test::fixed_cell(), ServoSettings{});  // builds the list; the row is measured from the state
    const auto row = measure_row(sim, {});
    CHECK(column(row, "contacts") == 64);
    CHECK(column(row, "fabric_11") == Approx(1.0));
    CHECK(column(row, "fabric_22") == 0);
    CHECK(column(row, "fabric_33") == 0);
    CHECK(column(row, "fabric_12") == 0);
    CHECK(column(row, "fabric_ratio") == Approx(3.0));  // d/m of diag(1, 0, 0)
    // All 64 forces are equal, so by Eq. 10 none is strong; see the known gap below: the engine's
    // mean, a rounded sum / 64, can fall below them, and then all count as strong.
  }
  SECTION("overlaps 20, 10, 10 um: F = I/3; the 64 axis-1 contacts are the strong ones, F^s = diag(1/3, 0, 0)") {
    Simulation sim = lattice(Vec3(d - 20e-6, d - 10e-6, d - 10e-6));
    sim.step(test::fixed_cell(), ServoSettings{});
    const auto row = measure_row(sim, {});
    CHECK(column(row, "contacts") == 192);
    for (const char* name : {"fabric_11", "fabric_22", "fabric_33"}) CHECK(column(row, name) == Approx(1.0 / 3));
    CHECK(std::abs(column(row, "fabric_ratio")) <= 1e-12);
    // Mean f_n = kn (20 + 10 + 10)/3 um: only the axis-1 contacts (20 um) are above it.
    CHECK(column(row, "mean_normal_force") == Approx(kn * 40e-6 / 3).epsilon(1e-6));
    CHECK(column(row, "strong_fabric_11") == Approx(1.0 / 3));
    CHECK(column(row, "strong_fabric_22") == 0);
    CHECK(column(row, "strong_fabric_33") == 0);
    CHECK(column(row, "strong_fabric_ratio") == Approx(3.0));
    // The stress is then diag(s, s/2, s/2) up to the slightly different spacings: sigma_kk =
    // kn delta_k / (a_l a_m). The pi-plane stress point lies on the positive y axis (TC1 direction).
    CHECK(column(row, "stress_11") > column(row, "stress_22"));
    CHECK(column(row, "pi_stress_x") == Approx(0.0).margin(1e-12));
    CHECK(column(row, "pi_stress_y") > 0);
    const double s11 = kn * 20e-6 / ((d - 10e-6) * (d - 10e-6)), s22 = kn * 10e-6 / ((d - 20e-6) * (d - 10e-6));
    CHECK(column(row, "sigma1_over_sigma3") == Approx(s11 / s22).epsilon(1e-6));
    CHECK(column(row, "sigma_max_over_min") == Approx(s11 / s22).epsilon(1e-6));
    CHECK(column(row, "q_over_p") == Approx((s11 - s22) / ((s11 + 2 * s22) / 3)).epsilon(1e-6));
  }
}

TEST_CASE("in a contact network whose normal forces are all equal, no contact is strong", "[analysis][fabric]") {
  // Eq. 10: strong means f_n > mean f_n, so a network of equal forces has F^s = 0 (as
  // strong_fabric_tensor gives for {2, 2, 2, 2} N above). Here 64 equal forces of a lattice
  // (4 x 4 x 4 spheres of d = 2 mm, 10 um overlap along axis 1 only) are not exact binary
  // numbers; their mean, computed as a rounded sum / 64, can come out below them by round-off. The
  // engine compares with the mean raised by a relative 1e-12, so none of them counts as strong.
  const double d = 2e-3, kn = 1e6;
  const Vec3 a(d - 10e-6, 2.1e-3, 2.1e-3);
  Particles p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) p.add(Vec3((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4), d / 2, 2650);
  Simulation sim(p, PeriodicCell(4 * a), test::material(kn), test::no_damping(), 1e-7, 0.05 * d);
  sim.step(test::fixed_cell(), ServoSettings{});
  const ContactCounts c = count_contacts(sim, true);
  REQUIRE(c.contacts == 64);
  // The forces are equal to the last bit (every branch vector is 0.25 L exactly).
  for (double f : c.normal_forces_N) REQUIRE(f == c.normal_forces_N[0]);
  CHECK(strong_fabric_tensor(c.normals, c.normal_forces_N) == Mat3::Zero());
}
