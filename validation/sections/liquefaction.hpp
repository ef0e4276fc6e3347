#pragma once
// The liquefaction section (compare-runs liquefaction): undrained cyclic triaxial tests
// (scenes/tests/undrained_cyclic.yaml: a consolidation, then a control stage cycling q at
// constant volume until r_u or the double-amplitude strain reaches its limit) and their unloaded
// twins (scenes/tests/undrained_hold.yaml). r_u = 1 - p/p0, p0 the mean stress at the start of the
// control stage, as the engine's pore_pressure_ratio column.
#include <optional>
#include <string>
#include <vector>

#include "study/series.hpp"
#include "study/results.hpp"

namespace validation {

// The first and last rows of stage `stage` (the stage column); throws std::runtime_error naming
// the stage if it has no row.
struct StageRows {
  std::size_t first = 0, last = 0;
};
StageRows stage_rows(const Columns& series, int stage);

// A control stage as run: its start and end (its first and last rows), p0, r_u at the end and the
// number of cycles of `period_s` it lasted, N = (end - start) / period (N_L when it stopped on a
// liquefaction criterion).
struct ControlStage {
  double start_time_s = 0, end_time_s = 0;
  double p0_Pa = 0;   // p at the stage's first row, the engine's p0
  double ru_end = 0;  // pore_pressure_ratio at the last row
  double ru_max = 0;  // its largest value over the stage
  double cycles = 0;
};
ControlStage summarise_control_stage(const Columns& series, int stage, double period_s);

// What ended a control stage, from its stage_end_<name> attribute: "until.pore_pressure_ratio met
// at time 0.2 s after 1.01 cycles" -> "pore_pressure_ratio"; "" when it was not a stop criterion
// ("duration reached").
std::string stop_criterion(const std::string& stage_end);

// The cyclic stress ratio written in a run's name: "loose_csr0.05" -> 0.05; none without "_csr"
// followed by a number.
std::optional<double> csr_from_name(const std::string& run);

// The cyclic stress ratio of a deviator cycle of amplitude q_amp about p0: CSR = q_amp / (2 p0).
double cyclic_stress_ratio(double amplitude_Pa, double p0_Pa);

// `column` of stage `stage` at time t_s after the stage's first row, linear between rows; NaN
// before the stage or past its last row.
double value_since_start(const Columns& series, int stage, const std::string& column, double t_s);

// r_u against the number of cycles (time since the stage start / period) of every row of a stage.
Table ru_against_cycles(const Columns& series, int stage, double period_s);

// N_L of one sample: liquefied after `cycles`, or censored (did not liquefy within the test, whose
// N cycles it lasted: N_L > cycles).
struct CensoredCycles {
  double cycles = 0;
  bool censored = false;
};

// N_L over the samples of one density and CSR, censored ones counted as > N. The median is bounded
// by two medians: `median_low` with every censored N_L at its N, `median_high` with every censored
// N_L at +inf (order statistics only grow when values do). When they agree the median is known
// (median_censored false); otherwise it is censored: written "> median_low" when median_high is
// infinite (the median's own sample did not liquefy; with every censored test at the same N, the
// tests' duration, and every liquefied N_L below it, the true median then exceeds N), or as the
// bracket "median_low – median_high" when both are finite. The range is the least and the largest
// N_L, each with its censoring (the largest censored: "> N"; the least censored: every sample is).
struct CensoredSummary {
  int samples = 0, liquefied = 0, censored = 0;
  double median_low = 0, median_high = 0;
  bool median_censored = false;
  CensoredCycles least, largest;
};
// Throws std::invalid_argument without samples.
CensoredSummary summarise_censored(const std::vector<CensoredCycles>& samples);

// "12.34" or "> 50.00" (`digits` decimals).
std::string censored_text(const CensoredCycles& c, int digits = 2);
// The median as the section writes it: "12.34", "> 50.00" or "12.34 – 20.00".
std::string median_text(const CensoredSummary& s, int digits = 2);

}  // namespace validation
