#include "study/line_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace validation {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_line: " + std::to_string(x.size()) + " x for " + std::to_string(y.size()) + " y");
  if (x.size() < 2) throw std::invalid_argument("fit_line: a line needs two points, got " + std::to_string(x.size()));
  LineFit f;
  f.n = static_cast<int>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / f.n, my = std::accumulate(y.begin(), y.end(), 0.0) / f.n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0)) throw std::invalid_argument("fit_line: every x is the same, no slope");
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ssr = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - (f.intercept + f.slope * x[i]);
    ssr += r * r;
  }
  f.r_squared = syy > 0 ? 1 - ssr / syy : std::nan("");
  if (f.n > 2) {
    f.residual_sd = std::sqrt(ssr / (f.n - 2));
    f.slope_se = f.residual_sd / std::sqrt(sxx);
    f.intercept_se = f.residual_sd * std::sqrt(1.0 / f.n + mx * mx / sxx);
  } else {
    f.residual_sd = f.slope_se = f.intercept_se = std::nan("");
  }
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  int direction = 0;  // +1 rising, -1 falling, 0 not known yet
  for (std::size_t k = 1; k < order.size(); ++k) {
    const double d = y[order[k]] - y[order[k - 1]];
    const int s = d > 0 ? 1 : d < 0 ? -1 : 0;
    if (s == 0) continue;
    if (direction != 0 && s != direction) f.monotonic = false;
    direction = s;
  }
  return f;
}

}  // namespace validation
