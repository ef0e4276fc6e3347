// The least-squares line the critical-state section takes to the quasi-static limit
// (validation/study/line_fit.hpp), against fits worked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "study/line_fit.hpp"

TEST_CASE("a line through three exact points: its intercept, no standard error", "[line-fit][critical-state]") {
  // q/p = 0.205 + 3.4 sqrt(I) at the sqrt(I) of the three rates (1, 0.5, 0.25 /s at I = 6e-4 at
  // 1/s: I halves with the rate). The residuals are rounding only (~1e-17), so s, and with it both
  // standard errors, are below 1e-14; the coefficients agree to the doubles' rounding (1e-12 is
  // a thousand times that, for the sums of three products).
  const std::vector<double> x = {std::sqrt(6e-4), std::sqrt(3e-4), std::sqrt(1.5e-4)};
  std::vector<double> y;
  for (double v : x) y.push_back(0.205 + 3.4 * v);
  const validation::LineFit f = validation::fit_line(x, y);
  CHECK(f.n == 3);
  CHECK(f.intercept == Approx(0.205).epsilon(1e-12));
  CHECK(f.slope == Approx(3.4).epsilon(1e-12));
  CHECK(f.intercept_se == Approx(0).margin(1e-14));
  CHECK(f.slope_se == Approx(0).margin(1e-12));
  CHECK(f.r_squared == Approx(1).epsilon(1e-12));
  CHECK(f.monotonic);
}

TEST_CASE("a line through three noisy points: intercept and standard error by hand", "[line-fit][critical-state]") {
  // x = 0, 1, 2; y = 0.20, 0.31, 0.38. mean x = 1, Sxx = 2, mean y = 0.89/3,
  // Sxy = -1 (0.20 - 0.89/3) + 1 (0.38 - 0.89/3) = 0.18: slope 0.09, intercept 0.89/3 - 0.09 = 0.62/3.
  // Residuals -1/150, +2/150, -1/150: SSR = 6/150^2, s^2 = SSR / (3 - 2),
  // se(intercept) = s sqrt(1/3 + 1/2) = sqrt(6/150^2 * 5/6) = sqrt(5)/150, se(slope) = s / sqrt(2) = sqrt(3)/150.
  // Three points in doubles: agreement to 1e-12 relative is rounding with a wide margin.
  const validation::LineFit f = validation::fit_line({0, 1, 2}, {0.20, 0.31, 0.38});
  CHECK(f.slope == Approx(0.09).epsilon(1e-12));
  CHECK(f.intercept == Approx(0.62 / 3).epsilon(1e-12));
  CHECK(f.residual_sd == Approx(std::sqrt(6.0) / 150).epsilon(1e-12));
  CHECK(f.intercept_se == Approx(std::sqrt(5.0) / 150).epsilon(1e-12));
  CHECK(f.slope_se == Approx(std::sqrt(3.0) / 150).epsilon(1e-12));
  // y - mean y = -0.29/3, +0.04/3, +0.25/3: Syy = (0.0841 + 0.0016 + 0.0625)/9 = 0.1482/9.
  CHECK(f.r_squared == Approx(1 - (6.0 / 22500) / (0.1482 / 9)).epsilon(1e-12));
  CHECK(f.monotonic);
}

TEST_CASE("a fit that is poor: not monotonic, said so", "[line-fit][critical-state]") {
  // x = 1, 2, 3; y = 1, 3, 2: slope Sxy/Sxx = 1/2, intercept 2 - 1 = 1; residuals -0.5, 1, -0.5,
  // SSR 1.5 (s^2 = 1.5), se(intercept) = sqrt(1.5 (1/3 + 4/2)) = sqrt(3.5); R^2 = 1 - 1.5/2.
  const validation::LineFit f = validation::fit_line({1, 2, 3}, {1, 3, 2});
  CHECK(f.slope == Approx(0.5).epsilon(1e-12));
  CHECK(f.intercept == Approx(1).epsilon(1e-12));
  CHECK(f.intercept_se == Approx(std::sqrt(3.5)).epsilon(1e-12));
  CHECK(f.r_squared == Approx(0.25).epsilon(1e-12));
  CHECK_FALSE(f.monotonic);
  // The order of the points does not matter: monotonic is judged along x.
  CHECK(validation::fit_line({3, 1, 2}, {0.3, 0.1, 0.2}).monotonic);
}

TEST_CASE("a line through two points has no standard error; one point or one x is refused", "[line-fit][critical-state]") {
  const validation::LineFit f = validation::fit_line({1, 3}, {2, 6});
  CHECK(f.intercept == Approx(0).margin(1e-15));
  CHECK(f.slope == Approx(2));
  CHECK(std::isnan(f.intercept_se));
  CHECK_THROWS_AS(validation::fit_line({1}, {1}), std::invalid_argument);
  CHECK_THROWS_AS(validation::fit_line({1, 1}, {1, 2}), std::invalid_argument);
  CHECK_THROWS_AS(validation::fit_line({1, 2}, {1}), std::invalid_argument);
}
