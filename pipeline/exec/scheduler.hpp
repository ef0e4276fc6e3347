#pragma once
// Runs planned runs as `dem run` subprocesses, at most `jobs` at once, each after the run it
// depends on; a copy (PlannedRun::copy_of) gets its original's result with its own input hash.
// A run whose result is complete and carries the same input hash is reused; a failed run is
// reported with its log and blocks only the runs that need it. A run marked may_fail that
// stops with a message (refused input, exit 2; or a failed run, exit 1) is an outcome: recorded in
// <result>.outcome with its input hash, reused like a result, and not a failure of the study.
// What the SLURM executor (exec/slurm.hpp) shares with it is in exec/tracker.hpp.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/file_lock.hpp"
#include "plan/plan_cost.hpp"  // result_cost (the tracker and calibrate read it through here)
#include "plan/reuse.hpp"  // up_to_date, recorded_stop (the executors and calibrate read them through here)
#include "plan/run_plan.hpp"

namespace pipeline {

struct Outcome {
  int ran = 0, reused = 0, failed = 0, blocked = 0;
  int stopped = 0;  // may_fail runs that stopped with a message this time (reused ones count as reused)
  int skipped = 0;  // may_fail runs not run because the run they need stopped
  int copied = 0;   // runs whose result is a copy of another's (PlannedRun::copy_of)
  bool interrupted = false;  // SIGINT/SIGTERM stopped the SLURM executor (it cancelled its jobs)
  double wall_time_s = 0;
};

// The engine's source hash and result schema (`dem --source-hash`), what a result's reuse depends
// on; "" if `dem` cannot be run or fails. The path goes to the kernel as one argument
// (posix_spawn), never through a shell: any folder name works, none is run as a command.
std::string engine_version(const std::string& dem);

// One pipeline per results folder: holds <out_dir>/.pipeline.lock (io/file_lock.hpp; created with
// the folder, removed when the pipeline ends). A second pipeline on the same folder would run the
// same runs at once (dem refuses the second writer of a result, so runs the first finishes are
// reported FAILED by the second) and write into the same logs; it is refused instead
// (dem::ConfigError naming the folder and the holder's pid, exit 2), before it writes anything.
std::unique_ptr<dem::FileLock> lock_results_folder(const std::string& out_dir);

// One `tool` per folder, the same way: holds <dir>/<name> or throws dem::ConfigError "another
// <tool> is running in <dir> (pid ... on host): <why>; wait for it ..." (`calibrate` locks its
// report folder with it: two calibrations there would each write the ledger and the posterior).
std::unique_ptr<dem::FileLock> lock_folder(const std::string& dir, const std::string& name, const std::string& tool,
                                           const std::string& why);

// `threads`: threads inside each run (dem run --threads).
Outcome execute(const std::vector<PlannedRun>& runs, const std::string& dem_binary, int jobs, int threads = 1);

}  // namespace pipeline
