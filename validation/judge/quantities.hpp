#pragma once
// The quantities a reference row is checked on, computed from the results of the runs it selects.
#include <optional>
#include <string>
#include <vector>

#include "study/results.hpp"

namespace validation {

// The paper's sample size: a cell side is scaled to it, (paper_particles / N)^(1/3) for a sample of
// N spheres, so that smaller samples compare (cell_side_cm_after_preparation, the samples table,
// the report's Fig. 2 note).
constexpr double paper_particles = 8000;

struct QuantityRequest {
  std::string quantity, density;
  int cycle = 0, from_cycle = 0, to_cycle = 0;
  // The test the row names ("" for none). A quantity that reads tests reads only this one; an
  // ordering (ev_lead, ev_lag) reads every test of the density and is about this one.
  std::string test;
};

struct Measured {
  std::optional<double> value;  // empty: could not be computed (see note)
  std::string note;             // fit quality, tests used, or why it is missing
  // Not empty when the quantity does not fit the runs it read (a peak friction angle, meant for a
  // monotonic shear, of a cyclic test): the value is computed all the same, the verdict warns.
  std::string misfit;
};

Measured compute(const QuantityRequest& q, const DensityResults& r);

// Mean angle (degrees) between each leg's strain increment and its stress increment in the
// pi-plane, over the legs of cycle c (none if the test has no such leg).
std::optional<double> strain_increment_misalignment(const TestResult& t, int c);

// Which runs of a density a quantity reads: its preparation, its tests (all of them, or the one
// the row names), or all of its tests with one named (an ordering: that test against the others).
enum class Reads { Preparation, Tests, TestAmongTests };

// The names compute() knows, for the reference file's validation, and what each reads.
bool known_quantity(const std::string& name);
Reads reads_of(const std::string& name);  // throws std::out_of_range for an unknown name
std::vector<std::string> known_quantities();  // without the <name>_magnitude forms

// Value of `column` at the end of cycle `c` (the row with cycle_end = 1 and cycle = c), if any.
std::optional<double> at_cycle_end(const TestResult& t, const std::string& column, int c);

}  // namespace validation
