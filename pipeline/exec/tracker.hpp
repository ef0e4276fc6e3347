#pragma once
// What every executor shares (exec/scheduler.cpp runs local processes, exec/slurm.cpp submits SLURM
// jobs): which runs are reused, the order runs start in, copies, blocking the runs that need a
// failed one, judging how a run ended (done, a may_fail stop or a failure) and the progress line
// with its ETA. An executor only starts runs and tells the tracker how each ended, so both
// executors reuse, copy, record outcomes and report exactly alike.
#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "exec/scheduler.hpp"
#include "plan/run_plan.hpp"

namespace pipeline {

enum class RunState { Waiting, Running, Done, Failed, Blocked };

// How a started run ended, as its executor saw it.
struct Ending {
  bool exited = false;  // false: killed by a signal, or a job the cluster cancelled, timed out or lost
  int code = 0;         // the exit code when exited
  std::string note;     // said in a failure's report beside the log (e.g. "job 12 TIMEOUT")
};

// The `dem run` command line that computes a run: the same for both executors.
std::vector<std::string> dem_command(const std::string& dem, const PlannedRun& r, int threads);

class Tracker {
 public:
  // Finds the reused runs (a complete result, or a may_fail run's recorded stop, with the same
  // input hash) and says why an existing result is not reused.
  explicit Tracker(const std::vector<PlannedRun>& runs);
  // "[pipeline] N runs: R reused, M to run, <how>".
  void announce(const std::string& how) const;
  // Longest chain first: a run's priority is its own cost plus that of the runs waiting for it, so
  // every preparation starts before any test and the last sample is not prepared at the end.
  const std::vector<std::size_t>& order() const { return order_; }
  RunState state(std::size_t i) const { return state_[i]; }
  // Blocks the waiting runs (and queued jobs) whose dependency failed or was blocked and makes the
  // waiting copies whose original is done, until nothing changes. Returns the runs it blocked (an
  // executor cancels their jobs).
  std::vector<std::size_t> settle();
  // A waiting run that is not a copy and whose dependency, if any, is done.
  bool ready(std::size_t i) const;
  // Marks it running from now (a stale outcome file removed), or queued (a SLURM job), and reports
  // `what` (default "started <name>").
  void start(std::size_t i, const std::string& what = "", bool queued = false);
  // Marks it running without a report (a SLURM job adopted from an earlier pipeline).
  void adopt(std::size_t i);
  // A running run whose SLURM job waits in the queue: counted as queued, its whole estimate left.
  // Set false when the job begins to compute, which restarts its clock.
  void set_queued(std::size_t i, bool queued);
  bool queued(std::size_t i) const { return queued_[i]; }
  // Judges how a running run ended: done (exit 0 and its result complete with its input hash), a
  // may_fail stop (exit 1 or 2: its outcome recorded), else a failure, reported with its log.
  void end(std::size_t i, const Ending& e);
  // The particle-steps run i is expected to take: its planned cost times what the finished runs of
  // its family (same density and source scene: liquefaction runs stop early, a preparation's hold
  // is not known ahead) took against theirs; the plan alone before any of them has finished.
  double expected_cost(std::size_t i) const;
  // Seconds until every run is done: the expected cost of each run left (of a running one, what is
  // left of its time) over the throughput learnt for its kind, shared by the busy workers.
  double eta_seconds() const;
  // The progress line: "[pipeline T] what; ran, reused, failed, running[, queued]; ETA".
  void report(const std::string& what) const;
  void set_workers(int workers) { workers_ = std::max(1, workers); }  // runs busy at once, for the ETA
  int running() const;
  bool busy() const;  // some run is waiting or running
  Outcome outcome() const;

 private:
  using clock = std::chrono::steady_clock;
  double rate(int kind) const;
  int kind(std::size_t i) const { return runs_[i].test.empty() ? 0 : 1; }

  const std::vector<PlannedRun>& runs_;
  std::vector<RunState> state_;
  std::vector<clock::time_point> started_;
  std::vector<bool> queued_;
  std::vector<std::size_t> order_;
  clock::time_point start_ = clock::now();
  Outcome out_;
  int workers_ = 1;
  // Learns from a complete result of run i: its particle-steps, against its plan and, with
  // `wall_s` (its own record first), per second.
  void learn(std::size_t i, double wall_s);
  struct Learnt {
    double cost = 0, wall = 0;  // particle-steps done and the wall time they took
  };
  Learnt learnt_[2];  // [0] preparations, [1] tests
  struct Scale {
    double planned = 0, done = 0;  // particle-steps
  };
  std::map<std::string, Scale> scale_;  // per family
};

}  // namespace pipeline
