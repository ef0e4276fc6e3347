#pragma once
// Whether a planned run's result can be reused (its input hash and completeness), and a may_fail
// run's recorded stop: what --plan, the executors and the calibration all ask of a result.
#include <optional>
#include <string>

namespace pipeline {

// True if `result` is a complete result whose `input_hash` attribute equals `hash`.
bool up_to_date(const std::string& result, const std::string& hash);

// Why `result` cannot be reused for `hash`: "" if it can, else "not run yet", "not a complete result
// (status '...')", "written for other inputs" or "unreadable, truncated or corrupt (...)".
std::string reuse_problem(const std::string& result, const std::string& hash);

// A may_fail run's recorded stop: <result>.outcome, written atomically when it stopped.
struct Stop {
  std::string input_hash;
  int exit_code = 0;     // 2: refused before any step; 1: stopped during the run
  std::string message;   // the engine's message (status attribute of the .partial, or the log's error line)
};
std::string outcome_file(const std::string& result);
std::optional<Stop> read_stop(const std::string& result);
void write_stop(const std::string& result, const Stop& stop);
// The recorded stop of `result` if it has the input hash `hash`.
std::optional<Stop> recorded_stop(const std::string& result, const std::string& hash);

}  // namespace pipeline
