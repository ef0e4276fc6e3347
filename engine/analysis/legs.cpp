#include "analysis/legs.hpp"

namespace dem {

const std::vector<SeriesColumn>& leg_columns() {
  static const std::vector<SeriesColumn> columns = {
      {"stage", "1", "stage index"},
      {"leg", "1", "leg index from 0"},
      {"cycle", "1", "cycle of the leg (0 before the first cycle)"},
      {"ends_cycle", "1", "1 if the leg is the last of its cycle"},
      {"target_1", "Pa", "principal stress the leg ends at"},
      {"target_2", "Pa", ""},
      {"target_3", "Pa", ""},
      {"duration", "s", "leg duration"},
      {"steps", "1", ""},
      {"end_step", "1", "step at which the leg ended"},
      {"rms_error_1", "1", "RMS of (stress_11 - target) over the leg, divided by p"},
      {"rms_error_2", "1", ""},
      {"rms_error_3", "1", ""},
      {"max_inertial_number", "1", "largest inertial number during the leg"},
  };
  return columns;
}

std::vector<double> leg_row(const LegRecord& r) {
  return {static_cast<double>(r.stage), static_cast<double>(r.leg), static_cast<double>(r.cycle), r.ends_cycle ? 1.0 : 0.0,
          r.target_Pa[0], r.target_Pa[1], r.target_Pa[2], r.duration_s, static_cast<double>(r.steps),
          static_cast<double>(r.end_step), r.rms_error[0], r.rms_error[1], r.rms_error[2], r.max_inertial_number};
}

}  // namespace dem
