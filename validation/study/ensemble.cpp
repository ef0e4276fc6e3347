#include "study/ensemble.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace validation {

Region paper_region(const std::string& check, double reference, double tolerance) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (check == "within") return {reference - tolerance, reference + tolerance};
  if (check == "at_least") return {reference, inf};
  if (check == "at_most") return {-inf, reference};
  throw std::invalid_argument("unknown check '" + check + "' (within, at_least, at_most)");
}

double t_quantile(double p, int dof) {
  return boost::math::quantile(boost::math::students_t_distribution<double>(dof), p);
}

Spread spread(const std::vector<double>& values, double level) {
  Spread s;
  s.n = static_cast<int>(values.size());
  if (s.n == 0) return s;
  for (double v : values) s.mean += v;
  s.mean /= s.n;
  if (s.n < 2) return s;
  double ss = 0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  return summary_spread(s.mean, std::sqrt(ss / (s.n - 1)), s.n, level);
}

Spread summary_spread(double mean, double sd, int n, double level) {
  Spread s;
  s.n = n;
  s.mean = mean;
  if (n < 2) return s;
  s.sd = sd;
  const double half = t_quantile(0.5 + level / 2, s.n - 1) * s.sd * std::sqrt(1.0 + 1.0 / s.n);
  s.low = s.mean - half;
  s.high = s.mean + half;
  return s;
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Consistent: return "consistent";
    case Verdict::Inconsistent: return "inconsistent";
    case Verdict::NotJudged: return "not judged";
  }
  throw std::logic_error("to_string: not a Verdict");
}

Verdict verdict_from_string(const std::string& text) {
  for (Verdict v : {Verdict::Consistent, Verdict::Inconsistent})
    if (text == to_string(v)) return v;
  return Verdict::NotJudged;
}

Verdict judge(const Spread& s, const Region& paper) {
  if (!s.low || !s.high) return Verdict::NotJudged;
  return *s.low <= paper.high && paper.low <= *s.high ? Verdict::Consistent : Verdict::Inconsistent;
}

}  // namespace validation
