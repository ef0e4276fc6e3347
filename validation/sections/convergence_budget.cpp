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
  f.samples = static_cast<int>(errors.size());
  f.sd = sd_of(errors);
  f.correlation = paired_correlation(paper, quarter);
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
  f.samples = static_cast<int>(linear.size());
  f.sd = sd_of(linear);
  const auto slowest = by_rate.begin();  // the rate furthest from the paper's on the quasi-static side
  if (slowest->first < paper_rate * (1 - 1e-9) && by_rate.count(paper_rate)) f.correlation = paired_correlation(by_rate.at(paper_rate), slowest->second);
  // The interval of the linear form, widened to reach the sqrt form's value.
  const double reach = std::abs(sq.value - lin.value);
  f.error = {lin.value, std::isfinite(lin.half_width) ? std::max(lin.half_width, reach) : lin.half_width};
  f.extrapolated = true;
  f.how = "line in rate to 0, interval covers sqrt(rate)";
  return f;
}

FactorError size_error(const std::map<long, PerSeed>& by_size, long n_paper) {
  FactorError f;
  f.error = {nan, nan};
  // Per size: 1/N, the mean, the count and the sum of squares scaled to the paper's size.
  struct Size {
    double x, mean;
    int n;
  };
  std::vector<Size> sizes;
  double pooled_ss = 0;
  int dof = 0;
  bool has_paper = false;
  for (const auto& [n, values] : by_size) {
    if (values.empty() || n <= 0) continue;
    const std::vector<double> v = [&] { std::vector<double> out; for (const auto& [seed, x] : values) out.push_back(x); return out; }();
    const Spread sp = spread(v);
    sizes.push_back({1.0 / static_cast<double>(n), sp.mean, sp.n});
    if (sp.n > 1) pooled_ss += static_cast<double>(n) / static_cast<double>(n_paper) * sp.sd * sp.sd * (sp.n - 1);
    dof += sp.n - 1;
    has_paper |= n == n_paper;
  }
  if (!has_paper || sizes.size() < 2) {
    f.how = "no other size ran";
    return f;
  }
  if (dof < 1) {
    f.how = "one sample per size: no scatter to weigh the sizes by";
    return f;
  }
  const double s2 = pooled_ss / dof;  // the variance of one sample at the paper's size
  // Weighted least squares on (1/N, mean), weight n N/N0 (the inverse of the mean's variance over s^2).
  double S = 0, Sx = 0, Sxx = 0, Sy = 0, Sxy = 0;
  for (const Size& z : sizes) {
    const double w = z.n / (z.x * static_cast<double>(n_paper));
    S += w, Sx += w * z.x, Sxx += w * z.x * z.x, Sy += w * z.mean, Sxy += w * z.x * z.mean;
  }
  const double det = S * Sxx - Sx * Sx;
  const double slope = (S * Sxy - Sx * Sy) / det, intercept = (Sy - slope * Sx) / S;
  double se = std::sqrt(s2 * S / det) / static_cast<double>(n_paper);
  const int k = static_cast<int>(sizes.size());
  std::string how = "line in 1/N over " + std::to_string(k) + " sizes, " + std::to_string(dof + k) + " samples";
  if (k >= 3) {
    double chi2 = 0;
    for (const Size& z : sizes) {
      const double w = z.n / (z.x * static_cast<double>(n_paper)), r = z.mean - intercept - slope * z.x;
      chi2 += w * r * r / s2;
    }
    f.lack_of_fit = chi2 / (k - 2);
    if (f.lack_of_fit > 1) se *= std::sqrt(f.lack_of_fit);
    how += ", the interval widened by √(χ²/dof) of the means about the line where that exceeds 1";
  } else {
    how += " (two: the 1/N form assumed)";
  }
  f.error = {slope / static_cast<double>(n_paper), t_quantile(0.975, dof) * se};
  f.extrapolated = true;
  f.samples = dof + k;
  f.across_sizes = true;
  f.sd = std::sqrt(s2);
  f.how = how;
  return f;
}

long samples_needed(const FactorError& f, double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(f.error.half_width) || f.samples < 2) return -1;
  if (f.error.half_width <= tolerance) return 0;
  if (f.across_sizes)
    return std::lround(std::ceil(f.samples * std::pow(f.error.half_width / tolerance, 2)));
  if (!std::isfinite(f.sd)) return -1;
  for (long n = 2; n <= 100000; ++n)
    if (t_quantile(0.975, static_cast<int>(n - 1)) * f.sd / std::sqrt(static_cast<double>(n)) <= tolerance) return n;
  return -1;
}

double paired_correlation(const PerSeed& a, const PerSeed& b) {
  std::vector<double> x, y;
  for (const auto& [seed, v] : a)
    if (b.count(seed)) x.push_back(v), y.push_back(b.at(seed));
  if (x.size() < 3) return nan;
  const double mx = mean_of(x).value, my = mean_of(y).value;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx), syy += (y[k] - my) * (y[k] - my);
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : nan;
}

FactorError paired_difference(const PerSeed& a, const PerSeed& b) {
  FactorError f;
  std::vector<double> d;
  for (const auto& [seed, v] : a)
    if (b.count(seed)) d.push_back(v - b.at(seed));
  f.error = mean_of(d);
  f.samples = static_cast<int>(d.size());
  f.sd = sd_of(d);
  f.correlation = paired_correlation(a, b);
  return f;
}

Estimate converged_value(const Estimate& paper, const std::vector<const FactorError*>& factors) {
  Estimate c = paper;
  double hw2 = paper.half_width * paper.half_width;
  for (const FactorError* f : factors) {
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
