#pragma once
// A straight line through points by ordinary least squares, with the standard errors of its
// intercept and slope: what the critical-state section extrapolates the critical q/p with, to the
// quasi-static limit I -> 0 of q/p against sqrt(I) (compare-runs critical-state --rates).
#include <vector>

namespace validation {

// y = intercept + slope x. With s^2 = sum(residual^2) / (n - 2) (n - 2 degrees of freedom) and
// Sxx = sum((x - mean x)^2) (e.g. Montgomery & Runger, Applied Statistics, ch. 11):
//   se(slope) = s / sqrt(Sxx),  se(intercept) = s sqrt(1/n + mean(x)^2 / Sxx).
// Two points: the line through them, the standard errors NaN (no degree of freedom left).
struct LineFit {
  int n = 0;
  double intercept = 0, slope = 0;
  double intercept_se = 0, slope_se = 0;  // [units of y], [units of y / units of x]
  double residual_sd = 0;                 // s
  double r_squared = 0;                   // 1 - SSR / Syy (NaN when every y is the same)
  bool monotonic = true;                  // the y, ordered by x, move one way only (no reversal)
};

// Throws std::invalid_argument for fewer than two points, sizes that differ, or every x the same.
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace validation
