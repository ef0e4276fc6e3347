#pragma once
// What the report reads of a calibration's posterior.json (calibrate writes it:
// calibration/posterior_report.cpp, rows_consistent in calibration/row_verdicts.cpp), declared
// once: the keys, their types, and a missing one as an absence. calibration/ includes this
// header (a room may include those below it), so the writer can name its keys from here.
#include <optional>
#include <string>
#include <vector>

#include "study/stamp.hpp"

namespace validation {

namespace posterior_keys {
inline constexpr const char* best_set = "best_set";                  // {name, chi2}
inline constexpr const char* name = "name";
inline constexpr const char* stamp = "stamp";                        // study/stamp.hpp
inline constexpr const char* rows_consistent = "rows_consistent";    // {best_set: {name, consistent, judged}, per_row: [...]}
inline constexpr const char* per_row = "per_row";                    // [{name, consistent_at_best_set, ...}]
inline constexpr const char* consistent_at_best_set = "consistent_at_best_set";
inline constexpr const char* consistent = "consistent";
inline constexpr const char* judged = "judged";
}  // namespace posterior_keys

struct PosteriorSummary {
  std::string best_set;  // the best set's name
  Stamp stamp;           // the engine and baseline of the calibration's runs (nothing recorded: none in the file)
  // rows_consistent: each validation row judged on the sets' own samples (absent: the calibration
  // scored no validation rows).
  struct Row {
    std::string name;
    std::optional<bool> consistent_at_best_set;  // none: the best set did not judge it
  };
  std::vector<Row> rows;
  std::optional<int> best_consistent, best_judged;  // rows consistent at the best set, of those it judged
};

// FILE's summary. Throws std::runtime_error naming FILE and the key ("best_set.name: missing") when
// it cannot be read, is not JSON or lacks the best set's name; any other key may be absent.
PosteriorSummary read_posterior_summary(const std::string& file);

}  // namespace validation
