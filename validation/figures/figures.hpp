#pragma once
// The data behind the report's figures (reports/gnuplot/*.gp draw them): pure functions of a
// result's columns, of a scene and of the paper's rows, each giving one table with named columns
// and units. The stress invariants and the pi-plane projection are the engine's own
// (analysis/measurements.hpp, analysis/fabric.hpp), recomputed from the stress and fabric tensors
// written in the time series, so a figure shows what the engine's definitions give.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "core/particles.hpp"
#include "cell/periodic_cell.hpp"
#include "study/results.hpp"
#include "study/series.hpp"
#include "judge/rows.hpp"

namespace validation {

// Fig. 3: the target path of a test from its /legs, as arrows (x_from, y_from, dx, dy) in the
// normalised pi-plane, A at the origin, each distinct leg once.
Table target_path(const Columns& legs);
// Fig. 3: the measured stress path, every row: x, y, cycle.
Table stress_path(const Columns& series);
// Fig. 3: the named states A, TC1..3, TE1..3 of a stress-path stage (p, R), projected.
Table named_states(double mean_stress_Pa, double stress_ratio);
// Fig. 4: the target q of the TC and TE states [kPa] (rows TC, TE).
Table target_q(double mean_stress_Pa, double stress_ratio);

// Figs. 4-6, 12, 13: every row (cycle <= max_cycle if given) of a test.
Table q_against_p(const Columns& series);
Table qp_against_deviatoric_strain(const Columns& series, int max_cycle);
Table volumetric_strain_against(const Columns& series, int test, int max_cycle);  // x: q/p (Tests 2, 3) or s11/s33
Table qp_against_fabric(const Columns& series, const std::string& which, int max_cycle);

// Figs. 7, 10, 11: a quantity at the end of each cycle over the samples given (one test of one
// density per sample): cycle, mean, sd, n, min, max. `from_start` adds cycle 0 = the first row.
struct CycleQuantity {
  std::string name, column, unit;
  double scale = 1;
  bool from_start = true;
};
const std::vector<CycleQuantity>& cycle_quantities();  // epsv_percent, coordination, sliding_percent
Table cycle_statistics(const std::vector<const TestResult*>& tests, const CycleQuantity& q);
// The same over every sample of an ensemble that ran Test `test` of `density` (figure-data,
// ensemble-cycles and the report's notes all read this one table); `runs`, if given, gets how many did.
Table ensemble_cycle_table(const std::vector<Sample>& samples, const std::string& density, int test, const CycleQuantity& q,
                           std::size_t* runs = nullptr);

// Fig. 8: Test 5's eps_v against s11/s33 over all cycles, one block per run of cycles loading the
// same axis (from the /legs targets); each block starts at the previous block's last point.
// `titles` gets one caption per block ("cycles 1–10: A↔TC1 (steps 1–2)").
Table test5_blocks(const Columns& series, const Columns& legs, std::vector<std::string>& titles);

// Fig. 9: the legs of cycle c: measured stress at the leg end, the leg's strain increment in the
// pi-plane, the arrow (increment x scale), leg index and order; and the stress path of the cycle.
Table strain_increments(const Columns& series, int cycle, double scale);
Table cycle_stress_path(const Columns& series, int cycle);
// A round arrow scale (1, 2 or 5 x 10^k) making the longest increment of these cycles about 0.12.
double arrow_scale(const Columns& series, const std::vector<int>& cycles);
int last_cycle(const Columns& series);

// One cyclic test's line of `figure-data tests-table`: steps, the worst leg RMS tracking error
// (% of p) and the largest inertial number of its legs, then εv (%) and the coordination number
// at the end of cycle 1 and of its last cycle (and CN at the first row, cycle 0). Cells that the
// columns cannot give are "—".
struct CyclicTestLine {
  std::string steps, tracking_percent, inertial_number, last_cycle, ev_cycle1, ev_last, cn_start, cn_cycle1, cn_last;
};
CyclicTestLine cyclic_test_line(const Columns& series, const Columns& legs);

// The energy balance of a run, every curve from one common row: the first whose energies are the
// true state, row 0, unless an engine older than the fix wrote it before any force evaluation
// (contacts but no elastic energy): then row 1. Work by the cell, dissipation (damping, sliding,
// rolling) and the change of stored energy (elastic + kinetic) since that row, and the gap
// work - (dissipated + change of stored), which a closed balance keeps near 0.
struct EnergyCurves {
  std::size_t baseline_row = 0;
  std::vector<double> time_s, work_J, damping_J, friction_J, dissipated_J, stored_change_J, gap_J;
  double work_total_J() const { return work_J.empty() ? 0 : work_J.back(); }
  // max |gap| over the run / the run's own work (from the baseline row to the end); NaN without work.
  double closure_relative_to_work() const;
  // The first time the gap exceeds `fraction` of the work done by then, once the work is past 1 %
  // of the run's total (the first rows' tiny work would make any rounding a parting), if ever.
  std::optional<double> parting_time_s(double fraction) const;
};
EnergyCurves energy_curves(const Columns& series);

// The energy figure's data: the curves of energy_curves, every row from the common one, and the
// engine's own closure error (relative to the stored energy at the start + the work).
Table energy_balance(const Columns& series);

// Fig. 1: the scene's grading curve, and the one realised in a set of radii (by mass and count).
Table grading_target(const dem::SceneConfig& scene);
Table grading_realised(const std::vector<double>& radius_m);
// The diameter [m] at `percent` finer on a grading curve (linear between its points).
double grading_diameter_at(const std::vector<double>& diameters_m, const std::vector<double>& percent_finer, double percent);
// Fig. 2: sphere centres and diameters [mm].
Table spheres(const dem::Particles& particles, const dem::PeriodicCell& cell);

// The paper's value of `quantity` for `density` (the row of reference_data/paper.yaml), if any.
std::optional<double> paper_value(const std::vector<Row>& rows, const std::string& quantity, const std::string& density);

// The axis limit of Figs. 12-14: the largest value of the first two columns x 1.05, at least 0.3,
// rounded up to 0.05.
double square_axis_max(const std::vector<const Table*>& tables);

}  // namespace validation
