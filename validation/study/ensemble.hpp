#pragma once
// Judging the paper's one sample against an ensemble of ours: the spread of a row's per-sample
// values, the 95 % prediction interval of a single new sample (Student t with n - 1 degrees of
// freedom), and the verdict: consistent when the paper's value, widened by the row's reading
// tolerance, overlaps that interval.
#include <optional>
#include <string>
#include <vector>

namespace validation {

// The region of values that agree with the paper's statement: [low, high], either end open
// (infinite) for "at least" and "at most" statements.
struct Region {
  double low, high;
  bool contains(double x) const { return x >= low && x <= high; }
};

// within: [reference - tolerance, reference + tolerance]; at_least: [reference, inf);
// at_most: (-inf, reference]. Throws std::invalid_argument for another check.
Region paper_region(const std::string& check, double reference, double tolerance);

struct Spread {
  int n = 0;
  double mean = 0, sd = 0;                // sd: sample standard deviation (n - 1); 0 for n = 1
  std::optional<double> low, high;        // prediction interval of one new sample; none for n < 2
};

// Student t quantile with `dof` degrees of freedom at probability `p` (Boost.Math).
double t_quantile(double p, int dof);

// mean, sd and the two-sided `level` prediction interval mean -/+ t sd sqrt(1 + 1/n).
// The coverage of the prediction interval the verdicts use (rule interval).
inline constexpr double prediction_level = 0.95;
Spread spread(const std::vector<double>& values, double level = prediction_level);
// The same from a summary a file records (mean, sd, n) instead of the values.
Spread summary_spread(double mean, double sd, int n, double level = prediction_level);

enum class Verdict { Consistent, Inconsistent, NotJudged };
const char* to_string(Verdict v);
// The verdict to_string names; any other text (a record without one): NotJudged.
Verdict verdict_from_string(const std::string& text);

// NotJudged with fewer than two samples (no verdict rests on one sample); otherwise whether the
// prediction interval and the paper's region overlap.
Verdict judge(const Spread& s, const Region& paper);

}  // namespace validation
