#pragma once
// The SLURM executor (pipeline --executor slurm): the same plan, input hashes, reuse, copies,
// may_fail outcomes, output layout and progress line as the local executor (exec/tracker.hpp),
// but each run is one batch job that runs the same `dem run` command line, its output in the
// run's log. A test's job waits for its sample's job (--dependency=afterok), so the cluster orders
// the work; the pipeline follows the jobs with squeue (sacct where the cluster keeps accounting,
// else the exit code the job script writes), cancels them on SIGINT/SIGTERM/SIGHUP, and, started
// again, adopts the jobs of an earlier pipeline that are still queued or running instead of
// submitting them twice. A run whose job was cancelled, timed out or requeued resumes from its
// checkpoint: `dem run` does that by itself when RESULT.h5.checkpoint exists.
//
// Files beside each result, while its job is in the queue: <result>.job (the job id and the input
// hash it computes: what a later pipeline adopts) and <result>.job.exit ("<job id> <exit code>",
// written by the job script when dem ends). Both are removed once the pipeline has judged the run.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "exec/scheduler.hpp"
#include "plan/run_plan.hpp"

namespace pipeline::slurm {

// The cluster cannot be used as asked (a command missing, squeue failing, an option sbatch refuses).
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run's job time limit in whole minutes: time_factor x cost / throughput, at least time_floor,
// at most time_ceiling when that is set (SlurmOptions).
long time_limit_minutes(double cost, const SlurmOptions& o);

// The batch script of a run: the local executor's dem command line, then "<job id> <exit code>"
// written to exit_file(result) (atomically), and dem's exit code as the job's.
std::string job_script(const PlannedRun& r, const std::string& dem, int threads);

// sbatch's command line for a run (the script comes on stdin); `after`: the job id whose success
// the run waits for (its sample's), or "".
std::vector<std::string> sbatch_command(const PlannedRun& r, const SlurmOptions& o, const std::string& after);

struct JobRecord {
  std::string job_id, input_hash;
};
std::string record_file(const std::string& result);  // <result>.job
std::string exit_file(const std::string& result);    // <result>.job.exit
std::optional<JobRecord> read_record(const std::string& result);
void write_record(const std::string& result, const JobRecord& record);  // atomically
void remove_job_files(const std::string& result);  // both files, once the run is judged
// The exit code that job `job_id`'s script wrote for `result`, if it wrote one.
std::optional<int> recorded_exit(const std::string& result, const std::string& job_id);

// The jobs squeue lists (`squeue --format=%i|%j|%T`), by job id.
struct QueuedJob {
  std::string name, state;
};
using Queue = std::map<std::string, QueuedJob>;
Queue parse_queue(const std::string& squeue_output);
// True for a job that is queued, running or finishing (PENDING, RUNNING, COMPLETING, REQUEUED, ...),
// false for one that ended (COMPLETED, FAILED, CANCELLED, TIMEOUT, ...).
bool active(const std::string& state);
// Queued, not computing: waiting for resources or its dependency, or put back in the queue.
bool waiting(const std::string& state);

// What a starting pipeline does with a run that is not reused, given its job record (if any), the
// queue, whether its dependency is done or has a job of its own in the queue, and the exit code
// the recorded job wrote (if any):
enum class Adoption {
  Submit,   // no job of these inputs in the queue: submit one (the run resumes from its checkpoint)
  Adopt,    // its job is queued or running for these inputs: follow it
  Replace,  // its job computes other inputs, or waits for a sample that will be computed again:
            // cancel it, then submit
  Ended,    // its job ended while no pipeline followed it, as a may_fail stop: record the outcome
};
Adoption adoption(const PlannedRun& r, const std::optional<JobRecord>& record, const Queue& queue, bool dependency_ok,
                  std::optional<int> exit_code);

// The cluster's commands (names looked up in PATH, or paths).
struct Commands {
  std::string sbatch = "sbatch", squeue = "squeue", scancel = "scancel", sacct = "sacct";
};

// Runs `runs` as SLURM jobs, run i with options[i] (its study's `slurm:`). Throws Error before
// anything is submitted if the commands are missing, squeue fails or sbatch refuses the options
// (sbatch --test-only); if submitting the k-th job fails, cancels the k-1 before and throws.
Outcome execute(const std::vector<PlannedRun>& runs, const std::vector<SlurmOptions>& options, const std::string& dem,
                const Commands& commands = {});

}  // namespace pipeline::slurm
