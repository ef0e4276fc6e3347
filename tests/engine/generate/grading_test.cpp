// Grading curve sampling by mass and the lattice generator (generate/grading.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/test_support.hpp"
#include "generate/grading.hpp"

using namespace dem;

namespace {

const GradingCurve& curve() {
  static const GradingCurve g({3.0e-3, 3.7e-3, 4.5e-3}, {0, 50, 100});
  return g;
}

struct KS {
  double statistic = 0;  // sup_d |F_N(d) - F(d)| of the mass-weighted empirical CDF
  double n_eff = 0;      // (sum w)^2 / sum w^2, w = d^3
};

// Kolmogorov-Smirnov distance between the mass-weighted empirical CDF of `d` and `F`.
template <class F>
KS mass_ks(std::vector<double> d, F&& cdf) {
  std::sort(d.begin(), d.end());
  double total = 0, total2 = 0;
  for (double x : d) {
    total += x * x * x;
    total2 += x * x * x * x * x * x;
  }
  KS ks;
  ks.n_eff = total * total / total2;
  double below = 0;
  for (double x : d) {  // the empirical CDF jumps at x: compare the curve with both sides of the jump
    const double f = cdf(x);
    ks.statistic = std::max(ks.statistic, std::abs(f - below / total));
    below += x * x * x;
    ks.statistic = std::max(ks.statistic, std::abs(f - below / total));
  }
  return ks;
}

std::vector<double> sample(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> d(n);
  for (double& x : d) x = curve().sample(rng);
  return d;
}

}  // namespace

TEST_CASE("grading curve: the curve itself is piecewise linear through its points", "[generate][grading]") {
  REQUIRE(curve().mass_fraction_finer(2.9e-3) == 0.0);
  REQUIRE(curve().mass_fraction_finer(3.0e-3) == 0.0);
  REQUIRE(curve().mass_fraction_finer(3.35e-3) == Approx(0.25).epsilon(1e-12));
  REQUIRE(curve().mass_fraction_finer(3.7e-3) == Approx(0.5).epsilon(1e-12));
  REQUIRE(curve().mass_fraction_finer(4.1e-3) == Approx(0.75).epsilon(1e-12));
  REQUIRE(curve().mass_fraction_finer(4.5e-3) == 1.0);
  REQUIRE_THROWS_AS(GradingCurve({3e-3, 2e-3}, {0, 100}), std::invalid_argument);
  REQUIRE_THROWS_AS(GradingCurve({3e-3, 4e-3}, {10, 100}), std::invalid_argument);
}

TEST_CASE("grading curve: mass fractions of 20000 sampled diameters follow the curve", "[generate][grading]") {
  const std::vector<double> d = sample(20000, 42);
  REQUIRE(*std::min_element(d.begin(), d.end()) >= 3.0e-3);
  REQUIRE(*std::max_element(d.begin(), d.end()) <= 4.5e-3);
  // Bound: for i.i.d. diameters the weighted empirical CDF F_N(d) = sum_{d_i<=d} w_i / sum w_i has
  // variance ~ E[w^2 (1{d_i<=d} - F)^2] / (N E[w]^2) <= 1 / (4 N_eff), N_eff = (sum w)^2 / sum w^2
  // (N_eff / N = E[w]^2 / E[w^2] = 0.886 for this curve, from the integrals of the mass density
  // c(d) times d^3 and d^-3). sqrt(N_eff) sup|F_N - F| then has
  // the Kolmogorov distribution, which exceeds 1.95 with probability 0.1 %. With a fixed seed the
  // test is deterministic; the bound only has to hold for a typical sample.
  const KS ks = mass_ks(d, [](double x) { return curve().mass_fraction_finer(x); });
  INFO("KS statistic " << ks.statistic << ", N_eff " << ks.n_eff << ", bound " << 1.95 / std::sqrt(ks.n_eff));
  REQUIRE(ks.n_eff == Approx(0.886 * 20000).epsilon(0.02));  // sampling scatter of N_eff ~0.5 %
  REQUIRE(ks.statistic < 1.95 / std::sqrt(ks.n_eff));
  // The same statistic does detect a curve off by 0.1 mm at the midpoint (6 % of the mass there).
  const GradingCurve wrong({3.0e-3, 3.8e-3, 4.5e-3}, {0, 50, 100});
  REQUIRE(mass_ks(d, [&](double x) { return wrong.mass_fraction_finer(x); }).statistic > 1.95 / std::sqrt(ks.n_eff));
  // By number, the fine fraction dominates: the mass-median diameter (3.7 mm) lies above the number median.
  std::vector<double> sorted = d;
  std::nth_element(sorted.begin(), sorted.begin() + 10000, sorted.end());
  REQUIRE(sorted[10000] < 3.7e-3);
}

TEST_CASE("grading curve: same seed gives the same diameters, another seed different ones", "[generate][grading]") {
  REQUIRE(sample(1000, 5) == sample(1000, 5));
  REQUIRE(sample(1000, 5) != sample(1000, 6));
}

TEST_CASE("make_lattice: 20^3 spheres in a 0.1 m cell, graded, no overlaps", "[generate][lattice]") {
  LatticeLayout layout;  // 20 x 20 x 20 at 5 mm spacing
  Particles p;
  PeriodicCell cell;
  make_lattice(layout, curve(), 2650, p, cell);
  REQUIRE(p.size() == 8000);
  for (int k = 0; k < 3; ++k) REQUIRE(cell.lengths()[k] == Approx(0.1).epsilon(1e-15));
  REQUIRE(cell.reference_lengths() == cell.lengths());
  // Every radius from the curve, every mass rho 4/3 pi r^3, all fractional positions inside [0,1).
  std::size_t bad = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool ok = 2 * p.radius[i] >= 3.0e-3 && 2 * p.radius[i] <= 4.5e-3 &&
                    std::abs(p.mass[i] / (2650 * sphere_volume(p.radius[i])) - 1) <= 1e-15 &&
                    p.s[i].minCoeff() >= 0.0 && p.s[i].maxCoeff() < 1.0;
    bad += ok ? 0 : 1;
  }
  REQUIRE(bad == 0);
  // No overlaps, by brute force over all 32 million pairs with the minimum image. The smallest gap
  // on a 5 mm lattice with d <= 4.5 mm is >= 0.5 mm; we only require it to be positive.
  double min_gap = 1;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      min_gap = std::min(min_gap, cell.branch(p.s[i], p.s[j]).norm() - p.radius[i] - p.radius[j]);
  REQUIRE(min_gap >= 0.5e-3 - 1e-12);
  // Same seed, same packing; the diameters are those of the curve's sampler with that seed, in lattice order.
  Particles q;
  PeriodicCell cell_q;
  make_lattice(layout, curve(), 2650, q, cell_q);
  REQUIRE(q.radius == p.radius);
  const std::vector<double> d = sample(8000, layout.seed);
  double worst = 0;
  for (std::size_t i = 0; i < 8000; ++i) worst = std::max(worst, std::abs(2 * p.radius[i] / d[i] - 1));
  REQUIRE(worst <= 1e-15);  // radius = d/2 and back: exact in binary, allow one rounding
  // A spacing below the largest diameter would make spheres overlap: rejected.
  layout.spacing_m = 4.4e-3;
  REQUIRE_THROWS_AS(make_lattice(layout, curve(), 2650, q, cell_q), std::invalid_argument);
}
