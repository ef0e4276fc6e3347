#pragma once
// The columns of the time series a run writes, and one row of them measured from a simulation.
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"

namespace dem {

struct SeriesColumn {
  std::string name, units, doc;
};

const std::vector<SeriesColumn>& series_columns();

// One row, in the order of series_columns(). Computed only when a row is written.
std::vector<double> measure_row(const Simulation& sim, int stage_index);

}  // namespace dem
