#include "sections/convergence_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "study/ensemble.hpp"
#include "study/line_fit.hpp"

namespace validation {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Half-width of the 95 % interval of a mean of n values with standard deviation sd.
double half_width(double sd, int n) { return n < 2 ? nan : t_quantile(0.975, n - 1) * sd / std::sqrt(n); }

std::string fixed(double x, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

}  // namespace

double sd_of(const std::vector<double>& v) { return v.size() < 2 ? nan : spread(v).sd; }

Estimate mean_of(const std::vector<double>& v) {
  if (v.empty()) return {nan, nan};
  const Spread s = spread(v);
  return {s.mean, half_width(s.sd, s.n)};
}

FactorError time_step_error(const PerSeed& paper, const PerSeed& half, const PerSeed& quarter, int order) {
  std::vector<double> d1, d2, q0, q2;
  for (const auto& [seed, v0] : paper) {
    if (!half.count(seed) || !quarter.count(seed)) continue;
    d1.push_back(v0 - half.at(seed));
    d2.push_back(half.at(seed) - quarter.at(seed));
    q0.push_back(v0);
    q2.push_back(quarter.at(seed));
  }
  FactorError f;
  if (d1.empty()) {
    f.error = {nan, nan};
    f.how = "no sample ran all three steps";
    return f;
  }
  const double m1 = mean_of(d1).value, m2 = mean_of(d2).value;
  const double factor = std::pow(2.0, order) - 1;
  std::vector<double> errors;
  // Monotone and shrinking at least at first order (observed order >= 1, |d2| <= |d1| / 2): else the
  // steps are not in the range where the scheme's order governs, and extrapolating at it would not hold.
  const double observed = m1 * m2 > 0 ? std::log2(m1 / m2) : nan;
  f.extrapolated = observed >= 1;
  for (std::size_t k = 0; k < d1.size(); ++k)
    errors.push_back(f.extrapolated ? q0[k] - (q2[k] - d2[k] / factor) : q0[k] - q2[k]);
  f.error = mean_of(errors);
  f.how = f.extrapolated         ? "Richardson, order " + std::to_string(order) + " (observed " + fixed(observed, 1) + ")"
          : std::isfinite(observed) ? "differences not shrinking at first order (observed order " + fixed(observed, 1) + "): finest step"
                                    : "not monotone: finest step";
  return f;
}

FactorError rate_error(const std::map<double, PerSeed>& by_rate, double paper_rate) {
  FactorError f;
  std::map<int, std::vector<std::pair<double, double>>> by_seed;  // seed -> (rate, value), rates up to the paper's
  for (const auto& [rate, values] : by_rate)
    if (rate <= paper_rate * (1 + 1e-9))
      for (const auto& [seed, v] : values) by_seed[seed].push_back({rate, v});
  std::vector<double> linear, root;
  for (const auto& [seed, points] : by_seed) {
    if (points.size() < 2) continue;
    std::vector<double> x, sx, y;
    double at_paper = nan;
    for (const auto& [rate, v] : points) {
      x.push_back(rate);
      sx.push_back(std::sqrt(rate));
      y.push_back(v);
      if (std::abs(rate - paper_rate) <= 1e-9 * paper_rate) at_paper = v;
    }
    if (!std::isfinite(at_paper)) continue;
    linear.push_back(at_paper - fit_line(x, y).intercept);
    root.push_back(at_paper - fit_line(sx, y).intercept);
  }
  if (linear.empty()) {
    f.error = {nan, nan};
    f.how = "fewer than 2 rates up to the paper's on any sample";
    return f;
  }
  const Estimate lin = mean_of(linear), sq = mean_of(root);
  // The interval of the linear form, widened to reach the sqrt form's value.
  const double reach = std::abs(sq.value - lin.value);
  f.error = {lin.value, std::isfinite(lin.half_width) ? std::max(lin.half_width, reach) : lin.half_width};
  f.extrapolated = true;
  f.how = "line in rate to 0, interval covers sqrt(rate)";
  return f;
}

FactorError size_error(const PerSeed& paper, long n_paper, const PerSeed& larger, long n_larger) {
  FactorError f;
  std::vector<double> a, b;
  for (const auto& [seed, v] : paper) a.push_back(v);
  for (const auto& [seed, v] : larger) b.push_back(v);
  if (a.empty() || b.empty() || n_larger <= n_paper) {
    f.error = {nan, nan};
    f.how = "no larger sample ran";
    return f;
  }
  const double scale = 1.0 / (1.0 - static_cast<double>(n_paper) / static_cast<double>(n_larger));
  const double ma = mean_of(a).value, mb = mean_of(b).value;
  const double se = std::sqrt((a.size() > 1 ? std::pow(sd_of(a), 2) / static_cast<double>(a.size()) : nan) +
                              (b.size() > 1 ? std::pow(sd_of(b), 2) / static_cast<double>(b.size()) : nan));
  const int dof = static_cast<int>(std::min(a.size(), b.size())) - 1;
  f.error = {(ma - mb) * scale, dof >= 1 ? t_quantile(0.975, dof) * se * scale : nan};
  f.extrapolated = true;
  f.how = "line in 1/N (two sizes: assumed)";
  return f;
}

Estimate converged_value(const Estimate& paper, const FactorError& dt, const FactorError& rate, const FactorError& size) {
  Estimate c = paper;
  double hw2 = paper.half_width * paper.half_width;
  for (const FactorError* f : {&dt, &rate, &size}) {
    if (!std::isfinite(f->error.value)) continue;  // a factor not measured adds nothing (the table says so)
    c.value -= f->error.value;
    hw2 += f->error.half_width * f->error.half_width;
  }
  c.half_width = std::sqrt(hw2);
  return c;
}

Estimate relative_error_to(const Estimate& x, const Estimate& converged) {
  const double scale = std::abs(converged.value);
  if (!(scale > 0)) return {nan, nan};
  return {std::abs(x.value - converged.value) / scale,
          std::sqrt(x.half_width * x.half_width + converged.half_width * converged.half_width) / scale};
}

}  // namespace validation
