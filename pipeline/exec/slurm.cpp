// The SLURM executor (exec/slurm.hpp): submits a plan's runs as jobs and follows them to the end.
// Its jobs (script, records, queue, adoption): exec/slurm_jobs.cpp; the commands it runs and the
// stop signals it answers: exec/cluster_command.*.
#include "exec/slurm.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <thread>

#include "exec/cluster_command.hpp"
#include "exec/tracker.hpp"

namespace pipeline::slurm {

namespace {

// ---- the executor ---------------------------------------------------------------------------------

class Executor {
 public:
  Executor(const std::vector<PlannedRun>& runs, const std::vector<SlurmOptions>& options, std::string dem, Commands commands)
      : runs_(runs), options_(options), dem_(std::move(dem)), commands_(std::move(commands)), user_(user_name()),
        tracker_(runs), job_(runs.size()), missing_since_(runs.size()) {}

  Outcome run() {
    check_commands();
    queue_ = look_at_queue();  // the cluster must answer before anything is submitted
    const int adopted = adopt_jobs();
    test_options();
    tracker_.announce("submitted as SLURM jobs" +
                      (adopted > 0 ? std::string(", ") + std::to_string(adopted) + " already in the queue (adopted)" : ""));
    submit_first();
    follow();
    Outcome out = tracker_.outcome();
    if (stop_signal()) {
      cancel_all();
      out.interrupted = true;
    }
    return out;
  }

 private:
  // Every command the executor needs, before anything is submitted.
  void check_commands() const {
    for (const std::string* c : {&commands_.sbatch, &commands_.squeue, &commands_.scancel})
      if (!on_path(*c))
        throw Error("the slurm executor needs SLURM's commands sbatch, squeue and scancel; '" + *c +
                    "' is not on the PATH of this machine (nothing was submitted)");
  }

  // The jobs of this user that squeue lists (recently ended ones too: --states=all).
  Queue look_at_queue() const {
    const CommandResult r =
        run_command({commands_.squeue, "--noheader", "--user=" + user_, "--states=all", "--format=%i|%j|%T"});
    if (r.status != 0) throw Error("squeue failed: " + trimmed(r.err.empty() ? r.out : r.err));
    return parse_queue(r.out);
  }

  // A starting pipeline takes over the jobs an earlier one left in the queue (killed, or its
  // terminal closed): no run is submitted twice. Index order: a sample before its tests.
  int adopt_jobs() {
    int adopted = 0;
    std::vector<std::string> replaced;
    for (std::size_t i = 0; i < runs_.size(); ++i) {
      const std::optional<JobRecord> record = read_record(runs_[i].result);
      if (!record) continue;
      if (tracker_.state(i) != RunState::Waiting || runs_[i].copy_of >= 0) {  // reused: the record is stale
        remove_job_files(runs_[i].result);
        continue;
      }
      const int dep = runs_[i].depends_on;
      const bool dependency_ok = dep < 0 || (dep < static_cast<int>(i) && (tracker_.state(static_cast<std::size_t>(dep)) == RunState::Done ||
                                                                        !job_[static_cast<std::size_t>(dep)].empty()));
      switch (adoption(runs_[i], record, queue_, dependency_ok, recorded_exit(runs_[i].result, record->job_id))) {
        case Adoption::Adopt:
          job_[i] = record->job_id;
          tracker_.adopt(i);
          tracker_.set_queued(i, waiting(queue_[record->job_id].state));
          std::printf("[pipeline] %s: adopted job %s (%s)\n", runs_[i].name.c_str(), record->job_id.c_str(),
                      queue_[record->job_id].state.c_str());
          ++adopted;
          break;
        case Adoption::Replace:
          replaced.push_back(record->job_id);
          std::printf("[pipeline] %s: job %s computes other inputs or waits for a sample computed again: cancelled\n",
                      runs_[i].name.c_str(), record->job_id.c_str());
          remove_job_files(runs_[i].result);
          break;
        case Adoption::Ended:
          tracker_.adopt(i);
          tracker_.end(i, {true, *recorded_exit(runs_[i].result, record->job_id), "job " + record->job_id});
          remove_job_files(runs_[i].result);
          break;
        case Adoption::Submit:
          remove_job_files(runs_[i].result);
          break;
      }
    }
    cancel_and_wait(replaced);
    return adopted;
  }

  // sbatch --test-only with each study's options and its longest time limit: a partition, account,
  // time limit or extra option the cluster refuses is an error before anything is submitted.
  void test_options() const {
    for (std::size_t i = 0; i < runs_.size(); ++i) {
      if (!to_submit(i)) continue;
      bool first_of_its_options = true;
      for (std::size_t k = 0; k < i && first_of_its_options; ++k)
        if (to_submit(k) && options_[k] == options_[i]) first_of_its_options = false;
      if (!first_of_its_options) continue;
      PlannedRun longest = runs_[i];
      for (std::size_t k = i; k < runs_.size(); ++k)
        if (to_submit(k) && options_[k] == options_[i]) longest.cost = std::max(longest.cost, runs_[k].cost);
      std::vector<std::string> argv = {commands_.sbatch, "--test-only"};
      for (const std::string& a : sbatch_command(longest, options_[i], "")) argv.push_back(a);
      const CommandResult r = run_command(argv, job_script(runs_[i], dem_, options_[i].cpus_per_run));
      if (r.status != 0)
        throw Error("sbatch --test-only refuses the job of " + runs_[i].name + " with its study's slurm: options (nothing was submitted): " +
                    trimmed(r.err.empty() ? r.out : r.err));
    }
  }

  bool to_submit(std::size_t i) const { return tracker_.state(i) == RunState::Waiting && runs_[i].copy_of < 0; }

  // Submits one run's job; returns its id, throws Error with sbatch's message.
  std::string submit(std::size_t i, const std::string& after) {
    std::vector<std::string> argv = {commands_.sbatch};
    for (const std::string& a : sbatch_command(runs_[i], options_[i], after)) argv.push_back(a);
    const CommandResult r = run_command(argv, job_script(runs_[i], dem_, options_[i].cpus_per_run));
    const std::string id = trimmed(r.out.substr(0, r.out.find(';')));  // --parsable: "id" or "id;cluster"
    if (r.status != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
      throw Error("sbatch failed for " + runs_[i].name + ": " + trimmed(r.err.empty() ? r.out : r.err));
    write_record(runs_[i].result, {id, runs_[i].hash});
    return id;
  }

  // Submits every run that can be: its sample done, or in the queue as a job it can wait for.
  // A copy's tests wait until the pipeline has made the copy.
  void submit_ready(bool throw_on_failure) {
    for (bool more = true; more && !stop_signal();) {
      more = false;
      tracker_.settle();
      for (std::size_t i : tracker_.order()) {
        if (!to_submit(i) || stop_signal()) continue;
        const int dep = runs_[i].depends_on;
        std::string after;
        if (dep >= 0 && tracker_.state(static_cast<std::size_t>(dep)) != RunState::Done) {
          after = job_[static_cast<std::size_t>(dep)];
          if (after.empty() || tracker_.state(static_cast<std::size_t>(dep)) != RunState::Running) continue;
        }
        std::string id;
        try {
          id = submit(i, after);
        } catch (const Error& e) {
          if (throw_on_failure) throw;
          tracker_.adopt(i);
          tracker_.end(i, {false, 0, e.what()});
          more = true;
          continue;
        }
        job_[i] = id;
        submitted_.push_back(i);
        tracker_.start(i, "submitted " + runs_[i].name + " as job " + id + (after.empty() ? "" : " (after job " + after + ")"),
                       true);
        more = true;
      }
    }
  }

  // The first submission is all or nothing: if the k-th sbatch fails, the k-1 jobs before are
  // cancelled and the error goes up.
  void submit_first() {
    try {
      submit_ready(true);
    } catch (const Error&) {
      std::vector<std::string> ids;
      for (std::size_t i : submitted_) {
        ids.push_back(job_[i]);
        remove_job_files(runs_[i].result);
      }
      cancel_and_wait(ids);
      if (!ids.empty())
        std::printf("[pipeline] cancelled the %zu job%s submitted before the error\n", ids.size(), ids.size() == 1 ? "" : "s");
      throw;
    }
  }

  // Follows the jobs until every run has ended or a stop signal came.
  void follow() {
    double poll = 3600;
    for (const SlurmOptions& o : options_) poll = std::min(poll, o.poll_interval);
    grace_s_ = std::max(30.0, 3 * poll);
    int workers = 1;
    bool squeue_failing = false;
    while (tracker_.busy() && !stop_signal()) {
      nap(poll);
      if (stop_signal()) break;
      try {
        queue_ = look_at_queue();
        squeue_failing = false;
      } catch (const Error& e) {  // a controller restarting: the jobs go on; look again
        if (!squeue_failing) std::printf("[pipeline] %s; trying again every %.0f s\n", e.what(), poll);
        squeue_failing = true;
        continue;
      }
      // Index order: a sample is judged before its tests, and a test whose sample failed is left
      // to settle() to block (the cluster may have cancelled its job already: not a failure of its own).
      for (std::size_t i = 0; i < runs_.size(); ++i)
        if (tracker_.state(i) == RunState::Running && !job_[i].empty() && !sample_failed(i)) look_at(i);
      workers = std::max(workers, tracker_.running() - queued_count());
      tracker_.set_workers(workers);  // as many at once as the cluster has given us so far
      std::vector<std::string> ids;
      for (std::size_t i : tracker_.settle())
        if (!job_[i].empty()) {
          ids.push_back(job_[i]);
          job_[i].clear();
          remove_job_files(runs_[i].result);
        }
      cancel(ids);  // their sample failed: they would never start
      submit_ready(false);
    }
  }

  bool sample_failed(std::size_t i) const {
    const int dep = runs_[i].depends_on;
    if (dep < 0) return false;
    const RunState s = tracker_.state(static_cast<std::size_t>(dep));
    return s == RunState::Failed || s == RunState::Blocked;
  }

  int queued_count() const {
    int n = 0;
    for (std::size_t i = 0; i < runs_.size(); ++i) n += tracker_.state(i) == RunState::Running && tracker_.queued(i);
    return n;
  }

  // One followed job: queued, computing, or ended (then judged like a local run's process).
  void look_at(std::size_t i) {
    const auto q = queue_.find(job_[i]);
    const bool ours = q != queue_.end() && q->second.name == runs_[i].name;
    if (ours && active(q->second.state)) {
      missing_since_[i].reset();
      const bool queued = waiting(q->second.state);
      if (tracker_.queued(i) && !queued) {
        tracker_.set_queued(i, false);
        tracker_.report("running " + runs_[i].name + " (job " + job_[i] + ")");
      } else if (!tracker_.queued(i) && queued) {
        tracker_.set_queued(i, true);  // requeued: it resumes from its checkpoint when it starts again
        tracker_.report("requeued " + runs_[i].name + " (job " + job_[i] + ", " + q->second.state + ")");
      }
      return;
    }
    const std::optional<Ending> ending = how_it_ended(i, ours ? q->second.state : "");
    if (!ending) return;
    tracker_.end(i, *ending);
    remove_job_files(runs_[i].result);
    job_[i].clear();
  }

  // How a job that left the queue ended: the exit code its script wrote, else its result, else
  // the state squeue or sacct gives. None yet if the exit file may still be on its way (a shared
  // filesystem shows another node's new file late).
  std::optional<Ending> how_it_ended(std::size_t i, std::string state) {
    const PlannedRun& r = runs_[i];
    const std::string job = "job " + job_[i];
    if (const auto code = recorded_exit(r.result, job_[i]))
      return Ending{true, *code, job + " exited with code " + std::to_string(*code)};
    if (up_to_date(r.result, r.hash)) return Ending{true, 0, ""};
    std::optional<int> code;
    if (state.empty()) std::tie(state, code) = ask_sacct(job_[i]);
    if (code) return Ending{true, *code, job + " " + state + " with code " + std::to_string(*code)};
    static const std::set<std::string> killed = {"CANCELLED", "TIMEOUT", "NODE_FAIL", "PREEMPTED", "OUT_OF_MEMORY",
                                                 "BOOT_FAIL", "DEADLINE", "REVOKED"};
    if (killed.count(state)) return Ending{false, 0, job + " " + state};
    const auto now = std::chrono::steady_clock::now();
    if (!missing_since_[i]) missing_since_[i] = now;
    if (std::chrono::duration<double>(now - *missing_since_[i]).count() < grace_s_) return std::nullopt;
    return Ending{false, 0, job + " ended" + (state.empty() ? "" : " " + state) + " without writing its exit code"};
  }

  // The state and exit code sacct records, where the cluster keeps accounting ({"", none} if not).
  std::pair<std::string, std::optional<int>> ask_sacct(const std::string& id) {
    if (!sacct_works_ || !on_path(commands_.sacct)) return {"", std::nullopt};
    const CommandResult r = run_command(
        {commands_.sacct, "--noheader", "--allocations", "--parsable2", "--jobs=" + id, "--format=State,ExitCode"});
    if (r.status != 0) {  // "Slurm accounting storage is disabled": the exit files and squeue it is
      sacct_works_ = false;
      return {"", std::nullopt};
    }
    const std::string line = trimmed(r.out.substr(0, r.out.find('\n')));
    const auto bar = line.find('|');
    if (bar == std::string::npos) return {"", std::nullopt};
    const std::string state = line.substr(0, std::min(line.find(' '), bar));  // "CANCELLED by 0" -> CANCELLED
    int code = 0, signal = 0;  // ExitCode is "code:signal"
    if ((state == "COMPLETED" || state == "FAILED") && std::sscanf(line.c_str() + bar + 1, "%d:%d", &code, &signal) == 2 &&
        signal == 0)
      return {state, code};
    return {state, std::nullopt};
  }

  void cancel(const std::vector<std::string>& ids) const {
    if (ids.empty()) return;
    std::vector<std::string> argv = {commands_.scancel};
    argv.insert(argv.end(), ids.begin(), ids.end());
    const CommandResult r = run_command(argv);
    if (r.status != 0) std::printf("[pipeline] scancel failed: %s\n", trimmed(r.err).c_str());
  }

  // Cancels and waits (at most 2 min) until the jobs have left the nodes, so that a job submitted
  // for the same result does not find dem's lock still held.
  void cancel_and_wait(const std::vector<std::string>& ids) const {
    if (ids.empty()) return;
    cancel(ids);
    for (int k = 0; k < 240; ++k) {
      Queue q;
      try {
        q = look_at_queue();
      } catch (const Error&) {
        return;
      }
      if (std::none_of(ids.begin(), ids.end(), [&](const std::string& id) { return q.count(id) && active(q[id].state); }))
        return;
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  }

  // On SIGINT/SIGTERM/SIGHUP: every job this pipeline submitted or adopted is cancelled.
  void cancel_all() {
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < runs_.size(); ++i)
      if (!job_[i].empty()) {
        ids.push_back(job_[i]);
        remove_job_files(runs_[i].result);
      }
    std::printf("[pipeline] stopped by signal %d: cancelling %zu job%s; started again, the pipeline submits them again "
                "and each run resumes from its checkpoint\n",
                static_cast<int>(stop_signal()), ids.size(), ids.size() == 1 ? "" : "s");
    std::fflush(stdout);
    cancel_and_wait(ids);
  }

  const std::vector<PlannedRun>& runs_;
  const std::vector<SlurmOptions>& options_;
  const std::string dem_;
  const Commands commands_;
  const std::string user_;
  Tracker tracker_;
  std::vector<std::string> job_;  // the job id computing run i ("" if none)
  std::vector<std::size_t> submitted_;  // the runs this pipeline submitted (not adopted), in order
  std::vector<std::optional<std::chrono::steady_clock::time_point>> missing_since_;
  Queue queue_;
  double grace_s_ = 30;
  bool sacct_works_ = true;
};

}  // namespace

Outcome execute(const std::vector<PlannedRun>& runs, const std::vector<SlurmOptions>& options, const std::string& dem,
                const Commands& commands) {
  if (options.size() != runs.size()) throw std::logic_error("slurm::execute: one SlurmOptions per run");
  const SignalGuard guard;
  return Executor(runs, options, dem, commands).run();
}

}  // namespace pipeline::slurm
