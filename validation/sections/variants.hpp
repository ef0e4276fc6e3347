#pragma once
// Comparing the runs of a study of variants: errors of each variant against a reference
// run with their cost (convergence study), and what became of each case (stability study).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/results.hpp"

namespace validation {

// The quantities a variant is compared on, by name: e0 and the coordination number after the
// preparation, εv, εd (paper Eq. 4) and the coordination number at the end of every cycle of each
// test, the mean angle between strain and stress increments over each cycle's legs, and the slope
// of q/p against F^s_d/F^s_m (the validation's own computations); with two cycles, the changes of
// εv and of the coordination number from the first to the second. Missing ones are left out.
std::map<std::string, double> convergence_quantities(const std::map<std::string, double>& sample,
                                                     const std::vector<std::pair<std::string, TestResult>>& tests);

// A point of the cost-error plane.
struct Point {
  double cost = 0, error = 0;
};

// true for the points no other point dominates (as cheap or cheaper and as accurate or more,
// better in one): the Pareto front of cost against error.
std::vector<bool> pareto_front(const std::vector<Point>& points);

// Index of the cheapest point whose error is at most `tolerance` (ties: the more accurate, then
// the first), or -1 if none is.
int cheapest_within(const std::vector<Point>& points, double tolerance);

// What became of a stability case.
struct CaseRun {
  bool complete = false;         // the result is complete
  std::optional<int> exit_code;  // recorded stop of a may_fail run: 2 refused, 1 stopped
  std::string message;           // its message
  Columns series;                // time series of the result or of its .partial
};

struct CaseOutcome {
  std::string outcome;           // ok, closure above 1 %, non-finite values, refused, stopped, not run, ...
  bool acceptable = false;       // ran with closure within the limit and finite values, or stopped with a message
  std::int64_t steps = 0;        // last step written
  std::optional<double> closure; // largest energy closure error once energy has come in (see .cpp)
  std::string message;
};

// A case's energy closure is read once the energy in has reached this fraction of its largest
// value (before, the ratio is a quotient of round-offs), and must stay within the limit.
inline constexpr double closure_onset_fraction = 0.01;
inline constexpr double closure_limit = 0.01;

CaseOutcome classify_case(const CaseRun& run, double closure_limit = validation::closure_limit);

}  // namespace validation
