#include "analysis/legs.hpp"

namespace dem {

namespace {

using In = const LegRecord&;

// The columns of /legs, in the file's order: one entry per column.
const ColumnDef<LegRecord> columns[] = {
    {"stage", "1", "stage index", [](In r) { return static_cast<double>(r.stage); }},
    {"leg", "1", "leg index from 0", [](In r) { return static_cast<double>(r.leg); }},
    {"cycle", "1", "cycle of the leg (0 before the first cycle)", [](In r) { return static_cast<double>(r.cycle); }},
    {"ends_cycle", "1", "1 if the leg is the last of its cycle", [](In r) { return r.ends_cycle ? 1.0 : 0.0; }},
    {"target_1", "Pa", "principal stress the leg ends at", [](In r) { return r.target_Pa[0]; }},
    {"target_2", "Pa", "", [](In r) { return r.target_Pa[1]; }},
    {"target_3", "Pa", "", [](In r) { return r.target_Pa[2]; }},
    {"duration", "s", "leg duration", [](In r) { return r.duration_s; }},
    {"steps", "1", "", [](In r) { return static_cast<double>(r.steps); }},
    {"end_step", "1", "step at which the leg ended", [](In r) { return static_cast<double>(r.end_step); }},
    {"rms_error_1", "1", "RMS of (stress_11 - target) over the leg, divided by p", [](In r) { return r.rms_error[0]; }},
    {"rms_error_2", "1", "", [](In r) { return r.rms_error[1]; }},
    {"rms_error_3", "1", "", [](In r) { return r.rms_error[2]; }},
    {"max_inertial_number", "1", "largest inertial number during the leg", [](In r) { return r.max_inertial_number; }},
};

}  // namespace

const std::vector<SeriesColumn>& leg_columns() {
  static const std::vector<SeriesColumn> described = describe(columns);
  return described;
}

std::vector<double> leg_row(const LegRecord& r) { return measure(columns, r); }

}  // namespace dem
