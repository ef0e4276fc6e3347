// The tilted cell (cell/periodic_cell.hpp) and the control of all six components
// (control/stress_servo.hpp): nearest images against brute force, the re-mapping, the affine
// stress of a sheared lattice, constant volume, energy, and the same result whichever way a
// sheared run is computed (threads, vector widths, re-mapped or not).
#include <catch2/catch.hpp>

#include <omp.h>

#include <cmath>
#include <random>

#include "dynamics/kernel_simd.hpp"
#include "engine/dynamics/packing_support.hpp"
#include "engine/test_support.hpp"

using namespace dem;

namespace {

// A random cell with tilts anywhere within half a length, as re-mapping keeps them.
PeriodicCell random_cell(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> length(0.8, 1.6), unit(-0.5, 0.5);
  PeriodicCell cell(Vec3(length(rng), length(rng), length(rng)));
  cell.set_tilts(Vec3(unit(rng) * cell.lengths()[0], unit(rng) * cell.lengths()[0], unit(rng) * cell.lengths()[1]));
  return cell;
}

// Simple shear xy of a packing: the axes held, xy at `rate`, xz and yz at zero shear stress.
CellControl simple_shear(double rate) {
  CellControl c;
  c.component[3] = {AxisTarget::Mode::StrainRate, rate, 0, 0};
  return c;
}

}  // namespace

TEST_CASE("tilted cell: the branch vector is the nearest of the 27 images within half the smallest width",
          "[cell][sheared]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int c = 0; c < 200; ++c) {
    const PeriodicCell cell = random_cell(rng);
    const Mat3 H = cell.matrix();
    // The widths are V / |b x c| and so on, from the cell vectors.
    const Vec3 a = H.col(0), b = H.col(1), cc = H.col(2);
    const double V = a.dot(b.cross(cc));
    CHECK(cell.widths()[0] == Approx(V / b.cross(cc).norm()).epsilon(1e-13));
    CHECK(cell.widths()[1] == Approx(V / cc.cross(a).norm()).epsilon(1e-13));
    CHECK(cell.widths()[2] == Approx(V / a.cross(b).norm()).epsilon(1e-13));
    CHECK(cell.volume() == Approx(V).epsilon(1e-14));
    const double half_width = 0.5 * cell.widths().minCoeff();
    for (int p = 0; p < 50; ++p) {
      const Vec3 si(unit(rng), unit(rng), unit(rng)), sj(unit(rng), unit(rng), unit(rng));
      Vec3 best;
      double best2 = 1e300;
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k) {
            const Vec3 d = H * (sj + Vec3(i, j, k) - si);
            if (d.squaredNorm() < best2) best2 = d.squaredNorm(), best = d;
          }
      if (std::sqrt(best2) >= half_width) continue;  // the promise holds below half the smallest width
      ++compared;
      const Vec3 l = cell.branch(si, sj);
      INFO("cell " << c << " pair " << p);
      CHECK((l - best).norm() <= 1e-14 * cell.lengths().maxCoeff());
    }
  }
  CHECK(compared > 1000);  // most random pairs are close enough to be compared
}

TEST_CASE("tilted cell: re-mapping keeps every real position and the lattice of images", "[cell][sheared]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PeriodicCell cell(Vec3(1.0, 1.3, 0.9));
  cell.set_tilts(Vec3(0.62, -0.71, 0.9));  // every tilt past half a length
  const PeriodicCell before = cell;
  REQUIRE(cell.remap());
  CHECK(std::abs(cell.tilts()[0]) <= 0.5 * cell.lengths()[0]);
  CHECK(std::abs(cell.tilts()[1]) <= 0.5 * cell.lengths()[0]);
  CHECK(std::abs(cell.tilts()[2]) <= 0.5 * cell.lengths()[1]);
  CHECK_FALSE(cell.remap());  // nothing left to re-map
  // The new cell vectors are integer combinations of the old ones (and back): the same lattice.
  const Mat3 n = before.matrix().inverse() * cell.matrix();
  CHECK((n - n.array().round().matrix()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(std::abs(n.determinant()) == Approx(1.0).epsilon(1e-12));
  for (int p = 0; p < 100; ++p) {
    const Vec3 s(unit(rng), unit(rng), unit(rng));
    const Vec3 moved = cell.remapped(before, s);
    CHECK((moved.minCoeff() >= 0.0 && moved.maxCoeff() < 1.0));
    // The same point, up to a lattice vector: zero distance to its nearest image.
    CHECK(PeriodicCell::min_image(cell.to_fractional(before.to_real(s)) - moved).norm() < 1e-12);
  }
}

TEST_CASE("tilted cell: the contact stress of a simple cubic lattice under simple shear is the affine one",
          "[cell][sheared]") {
  // Spheres of radius r on a simple cubic lattice of spacing a < 2r, sheared by tilting the cell:
  // x = H s with the fractional positions fixed. Along x and z the neighbours stay at a (overlap
  // d0 = 2r - a); along y they move to l = (g a, a, 0), |l| = a sqrt(1 + g^2), overlap
  // d = 2r - |l|. One contact of each kind per sphere in a^3, so (compression positive)
  //   sigma_xy = kn d (g a) a / (|l| a^3),  sigma_yy = kn d a a / (|l| a^3),
  //   sigma_xx = kn d0 / a^2 + kn d (g a)^2 / (|l| a^3),  sigma_zz = kn d0 / a^2.
  const int n = 6;
  const double a = 1e-3, r = 0.51e-3, kn = 1e5, g = 0.04;
  Particles p;
  PeriodicCell cell(Vec3::Constant(n * a));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) p.add(Vec3((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n), r, 2650);
  cell.set_tilts(Vec3(g * n * a, 0, 0));
  Simulation sim(std::move(p), cell, test::material(kn), test::no_damping(), 1e-7, 1e-5);
  sim.step(test::fixed_cell(), ServoSettings{});
  const Mat3& s = sim.sums().stress_Pa;
  const double l = a * std::sqrt(1 + g * g), d = 2 * r - l, d0 = 2 * r - a;
  CHECK(s(0, 1) == Approx(kn * d * g * a * a / (l * a * a * a)).epsilon(1e-10));
  CHECK(s(1, 1) == Approx(kn * d * a * a / (l * a * a * a)).epsilon(1e-10));
  CHECK(s(0, 0) == Approx(kn * d0 / (a * a) + kn * d * g * g * a * a / (l * a * a * a)).epsilon(1e-10));
  CHECK(s(2, 2) == Approx(kn * d0 / (a * a)).epsilon(1e-10));
  CHECK(std::abs(s(0, 2)) < 1e-9 * s(1, 1));
  CHECK(std::abs(s(1, 2)) < 1e-9 * s(1, 1));
}

TEST_CASE("cell control: constant volume holds the volume to round-off while an axis is compressed",
          "[cell][sheared][control]") {
  Simulation sim = test::compressed(0.5, 1, 300, 6);
  const double v0 = sim.cell().volume(), e0 = sim.cell().strain()[2];
  CellControl c;
  c.component[2] = {AxisTarget::Mode::StrainRate, 5.0, 0, 0};
  c.component[0].mode = c.component[1].mode = AxisTarget::Mode::Follow;
  c.constraint.kind = CellConstraint::Kind::ConstantVolume;
  REQUIRE(control_error(c).empty());
  AdaptiveServo servo(ServoSettings{});
  for (int i = 0; i < 2000; ++i) sim.step(c, servo);
  // 2,000 steps of exp(-rate dt) per axis: each product rounds by ~1e-16, so 2,000 of them
  // drift by at most ~1e-13 (a random walk, usually far less).
  CHECK(sim.cell().strain()[2] - e0 == Approx(5.0 * 2000 * 1e-6).epsilon(1e-9));
  CHECK(std::abs(sim.cell().volume() / v0 - 1) < 1e-12);
  CHECK(sim.rates().axial[0] == -2.5);
  CHECK(sim.rates().axial[1] == -2.5);
}

TEST_CASE("cell control: errors name what is wrong", "[cell][sheared][control]") {
  CellControl c;
  c.component[0].mode = AxisTarget::Mode::Follow;
  CHECK_THAT(control_error(c), Catch::Matchers::Contains("no constraint"));
  c.constraint.kind = CellConstraint::Kind::ConstantVolume;
  CHECK(control_error(c).empty());
  c.component[1].mode = c.component[2].mode = AxisTarget::Mode::Follow;
  CHECK_THAT(control_error(c), Catch::Matchers::Contains("all three axes"));
  c.constraint.kind = CellConstraint::Kind::ConstantMeanStress;
  c.constraint.mean_stress_Pa = 1e5;
  CHECK_THAT(control_error(c), Catch::Matchers::Contains("exactly two axes"));
  c.component[2] = {AxisTarget::Mode::Stress, 0, 1e5, 0};
  CHECK_THAT(control_error(c), Catch::Matchers::Contains("must be strain-rate controlled"));
  c.component[2] = {AxisTarget::Mode::StrainRate, 0.1, 0, 0};
  CHECK(control_error(c).empty());
  c.component[3].mode = AxisTarget::Mode::Follow;
  CHECK_THAT(control_error(c), Catch::Matchers::Contains("xy cannot follow"));
}

TEST_CASE("cell control: constant mean stress holds p while one axis is compressed", "[cell][sheared][control]") {
  Simulation sim = test::compressed(0.5, 1, 8000, 6);
  CellControl c;
  c.component[2] = {AxisTarget::Mode::StrainRate, 2.0, 0, 0};
  c.component[0].mode = c.component[1].mode = AxisTarget::Mode::Follow;
  c.constraint = {CellConstraint::Kind::ConstantMeanStress, 1e5, 0.5};
  ServoSettings settings;
  settings.max_strain_rate_per_s = 50;
  AdaptiveServo servo(settings);
  double sum_p = 0, sum_b = 0;
  int n_p = 0, n_b = 0;
  for (int i = 0; i < 30000; ++i) {
    sim.step(c, servo);
    const Mat3& s = sim.sums().stress_Pa;
    if (i < 12000) continue;  // the servo brings p from ~60 kPa (the packing is not yet at 100 kPa) to p0
    sum_p += s.trace() / 3, ++n_p;
    if (s(2, 2) - s(0, 0) < 0.2e5) continue;  // b is a ratio of small differences until the leader is loaded
    sum_b += (s(1, 1) - s(0, 0)) / (s(2, 2) - s(0, 0)), ++n_b;
  }
  // A 216-sphere packing jumps by several % of p when contacts slip (single steps reach 5 % of p
  // and b 0.86), which the servo (1e-3 of the error per step) cannot follow. Averaged over the
  // 18,000 steps after it settled, p is held within 2 % (measured: +1.2 %) and b is near 0.5
  // (measured: 0.41; the followers lag the leader while it loads, see resolved() in
  // control/stress_servo.cpp): a wrong split, b = 0 or 1, would be off by 0.5.
  const double mean_p = sum_p / n_p, mean_b = sum_b / n_b;
  INFO("mean p " << mean_p << " Pa, mean b " << mean_b << " over " << n_b << " steps");
  CHECK(std::abs(mean_p - 1e5) < 2e3);
  CHECK(n_b > 5000);
  CHECK(std::abs(mean_b - 0.5) < 0.15);
  CHECK(sim.sums().stress_Pa(2, 2) > 1.1e5);  // the leader was loaded
}

TEST_CASE("sheared cell: the energy balance closes with the cell's shear work", "[cell][sheared][energy]") {
  Simulation sim = test::compressed(0.5, 1, 8000, 8);
  const CellControl shear = simple_shear(20.0);
  AdaptiveServo servo(ServoSettings{});
  for (int i = 0; i < 10000; ++i) sim.step(shear, servo);
  const EnergyBalance& e = sim.energy();
  INFO("work " << e.work_by_cell << " J, closure error " << e.closure_error());
  CHECK(sim.cell().shear_strain()[0] == Approx(20.0 * 10000 * 1e-6).epsilon(1e-9));
  CHECK(sim.cell().tilts()[0] == Approx(-0.2 * sim.cell().lengths()[1]).epsilon(1e-6));
  // The shear work dominates (the axes do not move) and the balance closes to the accuracy the
  // unsheared runs reach (energy_balance_test: 1e-3 of the energy put in).
  CHECK(e.work_by_cell > 0);
  CHECK(e.closure_error() < 2e-3);
}

TEST_CASE("sheared cell: 1 and 2 threads, every vector width, and a re-mapped run agree", "[cell][sheared][threads]") {
  const auto run = [](int threads, int width, bool remap, int steps) {
    Simulation sim = test::compressed(0.5, 1, 8000, 8);
    const int saved_threads = omp_get_max_threads(), saved_width = simd_width();
    omp_set_num_threads(threads);
    cap_simd_width(width);
    sim.set_cell_remapping(remap);
    const CellControl shear = simple_shear(-50.0);  // tilt +0.05 L per 1,000 steps: a re-map after 10,000
    AdaptiveServo servo(ServoSettings{});
    for (int i = 0; i < steps; ++i) sim.step(shear, servo);
    omp_set_num_threads(saved_threads);
    cap_simd_width(saved_width);
    return sim;
  };
  const Simulation one = run(1, 8, true, 10800);
  REQUIRE(one.cell_remaps() == 1);
  for (const auto& [threads, width] : {std::pair{2, 8}, std::pair{1, 4}, std::pair{1, 0}}) {
    const Simulation other = run(threads, width, true, 10800);
    INFO(threads << " threads, width " << width);
    CHECK(other.particles().s == one.particles().s);
    CHECK(other.particles().v == one.particles().v);
    CHECK(other.sums().stress_Pa == one.sums().stress_Pa);
  }
  // Without re-mapping the tilt goes on past half a length; the positions are the same real
  // points, to round-off (the re-mapped run's fractional positions were recomputed once, about
  // 1e-16 relative, and 800 steps of a dense packing amplify such a difference only modestly).
  const Simulation straight = run(1, 8, false, 10800);
  REQUIRE(straight.cell_remaps() == 0);
  CHECK(std::abs(straight.cell().tilts()[0]) > 0.5 * straight.cell().lengths()[0]);
  const Mat3 s1 = one.sums().stress_Pa, s2 = straight.sums().stress_Pa;
  INFO("stress difference " << (s1 - s2).norm() / s1.norm());
  CHECK((s1 - s2).norm() <= 1e-9 * s1.norm());
  double worst = 0;
  for (std::size_t i = 0; i < one.particles().size(); ++i)
    worst = std::max(worst, one.cell().branch(one.particles().s[i], one.cell().to_fractional(straight.cell().to_real(straight.particles().s[i]))).norm());
  CHECK(worst < 1e-12);
}
