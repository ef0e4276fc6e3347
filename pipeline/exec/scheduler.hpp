#pragma once
// Runs planned runs as `dem run` subprocesses, at most `jobs` at once, each after the run it
// depends on. A run whose result is complete and carries the same input hash is reused; a failed
// run is reported with its log and blocks only the runs that need it.
#include <string>
#include <vector>

#include "plan/run_plan.hpp"

namespace pipeline {

struct Outcome {
  int ran = 0, reused = 0, failed = 0, blocked = 0;
  double wall_time_s = 0;
};

// True if `result` is a complete result whose `input_hash` attribute equals `hash`.
bool up_to_date(const std::string& result, const std::string& hash);

// `threads`: threads inside each run (dem run --threads).
Outcome execute(const std::vector<PlannedRun>& runs, const std::string& dem_binary, int jobs, int threads = 1);

}  // namespace pipeline
