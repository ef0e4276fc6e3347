#pragma once
// What a plan costs (pipeline --plan): each run's estimated particle-steps (PlannedRun::cost), the
// critical path (the longest chain of runs, each starting from the one before it) and the wall
// time on a number of cores, each run on one core at a given throughput.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plan/run_plan.hpp"

namespace pipeline {

// The particle-steps per second of one run on one core that the estimates assume unless told
// otherwise: the engine's measured throughput, `make bench` on this project's 2-core machine
// (reports/bench.md, 8,000 spheres, mu = 0.5, dt = 1 us): 3.53e7 for one run on one thread, 3.49e7
// each for two runs at once. Output rows and the preparations' gas phase are not in it.
inline constexpr double default_throughput = 3.5e7;

// What a complete result cost: particle-steps (the /state step count times the spheres) and, if
// recorded, the run's wall time (seconds, over all its resumptions). None if it cannot be read.
struct ResultCost {
  double particle_steps = 0;
  std::optional<double> wall_s;
};
std::optional<ResultCost> result_cost(const std::string& result);

// Costs from finished runs. A run whose result is there (for these or for earlier inputs) is planned
// at the particle-steps it recorded (cost_basis "recorded"); one without, at the steps per run its
// family's finished runs recorded (the same scene's other samples, with the same variants and
// spheres; cost_basis "as <that run>"), times its spheres. Returns the particle-steps per second
// of their recorded wall times together, none without one.
std::optional<double> use_recorded_costs(std::vector<PlannedRun>& runs);

// What the finished runs of one engine source recorded on this machine, for a plan whose own runs
// have none yet: the particle-steps over the wall time of every complete result listed in a
// runs.tsv at most three folders below `root` (results/<study>/<profile>/runs.tsv, a
// calibration's one deeper) whose first line names `engine_version`. None when no such run
// recorded a wall time.
struct MachineThroughput {
  double particle_steps_per_s = 0;
  int runs = 0, studies = 0;
};
std::optional<MachineThroughput> recorded_throughput_under(const std::string& root, const std::string& engine_version);

// `todo[i]`: run i has to run; a reused result or a copy (copy_of) costs nothing.
std::vector<double> run_costs(const std::vector<PlannedRun>& runs, const std::vector<bool>& todo);

struct CriticalPath {
  std::vector<int> runs;  // first to last, only runs that cost something
  double cost = 0;        // particle-steps along it
};
// The chain of runs (each depends_on the one before) with the most particle-steps to do.
CriticalPath critical_path(const std::vector<PlannedRun>& runs, const std::vector<double>& cost);

// Seconds the runs take on `cores` cores, one run per core at `throughput` particle-steps/s:
// list scheduling (a free core takes the ready run with the longest chain still behind it, as the
// scheduler orders them), a run ready once the run it starts from is done.
double estimated_wall_time_s(const std::vector<PlannedRun>& runs, const std::vector<double>& cost, int cores,
                             double throughput);

// The throughput a plan's estimates assume, and where it is from: `given` (--throughput), else
// what the plan's finished runs recorded (use_recorded_costs), else what this engine's finished
// runs under `results_root` recorded (recorded_throughput_under), else default_throughput.
struct PlanThroughput {
  double particle_steps_per_s = default_throughput;
  std::string from;  // a sentence for the plan's last line
};
PlanThroughput plan_throughput(std::optional<double> given, std::optional<double> recorded, const std::string& results_root,
                               const std::string& engine_version);

// What `pipeline --plan` prints, as data: each run's action (reuse, stopped, copy, run), the
// particle-steps still to run, the critical path and the wall time on 1, 2, 16 and 64 cores.
struct PlanSummary {
  std::vector<std::string> action;  // per run: "reuse", "stopped", "copy" or "run"
  std::vector<double> cost;         // per run: the particle-steps it still costs (run_costs)
  int to_run = 0;                   // runs whose action is "run"
  double particle_steps = 0;        // the sum of cost
  CriticalPath critical;
  PlanThroughput throughput;
  std::vector<std::pair<int, double>> wall_time_s;  // (cores, estimated_wall_time_s)
};
PlanSummary summarize_plan(const std::vector<PlannedRun>& runs, const PlanThroughput& throughput);

}  // namespace pipeline
