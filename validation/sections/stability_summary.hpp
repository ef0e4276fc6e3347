#pragma once
// The stability study's committed summary (reports/stability/summary.json): what became of each
// case, as data, so that its table is re-drawn without the results (compare-runs stability
// --without-results redraw). Declared once: stability() writes it, stability_from_summary() reads it.
#include <optional>
#include <string>
#include <vector>

namespace sections {

struct StabilityCase {
  std::string name;      // the variant, with its test when it has one ("base", "dt_x2 test1")
  std::string settings;  // the variant's settings as runs.tsv gives them
  bool acceptable = true;
  std::string outcome;   // what happened ("ran; energy closure within the limit", "stopped: ...")
  long steps = 0;        // of the last row written
  std::optional<double> dt_over_critical;          // the largest time_step_over_critical (none: no such column or row)
  std::optional<double> dt_over_contact_critical;  // the largest time_step_over_contact_critical
  std::optional<double> closure;                   // the energy closure error, relative (none: not measured)
  std::string message;   // the engine's, without the resolved scene's path
};

// summary.json: {"schema": 1, "cases": [{name, settings, acceptable, outcome, steps, dt_over_critical,
// dt_over_contact_critical, closure, message}]}; an absent value is null.
std::string stability_summary_json(const std::vector<StabilityCase>& cases);
// FILE's cases. Throws std::runtime_error naming FILE and the key ("cases[2].steps: ...") when it is
// not such a summary.
std::vector<StabilityCase> read_stability_summary(const std::string& file);

// table.md: one row per case (a cell over the table's limit cut, in full in a note beneath it).
std::string stability_table(const std::vector<StabilityCase>& cases);

}  // namespace sections
