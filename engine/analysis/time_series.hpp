#pragma once
// The columns of the time series a run writes, and one row of them measured from a simulation.
// Each column is declared once, with its value (time_series.cpp; analysis/columns.hpp).
#include <vector>

#include "analysis/columns.hpp"
#include "dynamics/simulation.hpp"

namespace dem {

const std::vector<SeriesColumn>& series_columns();

// Where in the run a row is taken.
struct RowContext {
  int stage = 0;
  int cycle = 0;           // stress-path cycle (0 outside cycles)
  int leg = -1;            // stress-path leg index (-1 outside stress paths)
  bool leg_end = false;    // the row is taken at the end of a leg
  bool cycle_end = false;  // ... which is also the end of a cycle
  Vec3 strain_at_previous_leg_end = Vec3::Zero();  // for the strain increment vector
  double mean_stress_at_stage_start = 0;  // control stages: p0 of the pore pressure ratio (0: none)
  double double_amplitude_strain = 0;     // control stages with cyclic loading: in the current cycle
};

// One row, in the order of series_columns(). Computed only when a row is written.
std::vector<double> measure_row(const Simulation& sim, const RowContext& where);

}  // namespace dem
