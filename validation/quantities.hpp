#pragma once
// The quantities the paper's statements are checked on, computed from the results.
#include <optional>
#include <string>

#include "results.hpp"

namespace validation {

struct QuantityRequest {
  std::string quantity, density;
  int cycle = 0, from_cycle = 0, to_cycle = 0;
  int test = 0;  // the test an ordering row is about (ev_lead, ev_lag)
};

struct Measured {
  std::optional<double> value;  // empty: could not be computed (see note)
  std::string note;             // fit quality, tests used, or why it is missing
};

Measured compute(const QuantityRequest& q, const DensityResults& r);

// The names compute() knows, for the reference file's validation.
bool known_quantity(const std::string& name);

// Value of `column` at the end of cycle `c` (the row with cycle_end = 1 and cycle = c), if any.
std::optional<double> at_cycle_end(const TestResult& t, const std::string& column, int c);

}  // namespace validation
