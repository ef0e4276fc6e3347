#pragma once
// What a stress-path stage records about each leg, and the columns of /legs in a result file
// (beside series_columns() of /timeseries): run/ fills the records, io/ writes the columns.
#include <cstdint>
#include <vector>

#include "analysis/columns.hpp"
#include "core/types.hpp"

namespace dem {

struct LegRecord {
  int stage = 0, leg = 0, cycle = 0;
  bool ends_cycle = false;
  Vec3 target_Pa = Vec3::Zero();  // the state the leg ends at
  double duration_s = 0;
  std::int64_t steps = 0, end_step = 0;
  Vec3 rms_error = Vec3::Zero();  // RMS of (sigma_kk - target_k) over the leg's steps, divided by p
  double max_inertial_number = 0;
};

const std::vector<SeriesColumn>& leg_columns();
std::vector<double> leg_row(const LegRecord& r);  // in the order of leg_columns() (both from one table, legs.cpp)

}  // namespace dem
