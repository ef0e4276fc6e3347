// The SLURM executor's jobs (exec/slurm.hpp): the batch script and sbatch command of a run, the
// files beside its result, the queue as squeue lists it and what a later pipeline does with a job
// it finds there. The executor itself, which submits and follows them: exec/slurm.cpp.
#include "exec/slurm.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "exec/tracker.hpp"
#include "io/atomic_file.hpp"

namespace pipeline::slurm {

namespace fs = std::filesystem;

// ---- what a job is --------------------------------------------------------------------------------

long time_limit_minutes(double cost, const SlurmOptions& o) {
  double minutes = std::max(o.time_floor, o.time_factor * cost / o.throughput / 60);
  if (o.time_ceiling > 0) minutes = std::min(minutes, o.time_ceiling);
  return static_cast<long>(std::ceil(minutes));
}

namespace {

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// sbatch expands %j, %x, ... in --output; a '%' of the path itself is written %%.
std::string sbatch_path(const std::string& path) {
  std::string out;
  for (char c : path) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out;
}

}  // namespace

std::string job_script(const PlannedRun& r, const std::string& dem, int threads) {
  std::string command;
  for (const std::string& a : dem_command(dem, r, threads)) {
    if (!command.empty()) command += ' ';
    command += shell_quoted(a);
  }
  const std::string exit = shell_quoted(exit_file(r.result)), tmp = shell_quoted(exit_file(r.result) + ".tmp.") + "$$";
  // The exit code goes to a file because sacct, which would tell it, needs an accounting database
  // that small clusters may not run. A requeued job starts by removing its first life's file. The
  // file is written beside it under the shell's process id ($$), a name no other file has.
  return "#!/bin/sh\n"
         "# " + r.name + ": a run of the cyclic-triax pipeline (input hash " + r.hash + ")\n"
         "rm -f " + exit + "\n" +
         command + "\n"
         "rc=$?\n"
         "echo \"$SLURM_JOB_ID $rc\" > " + tmp + " && mv -f " + tmp + " " + exit + "\n"
         "exit $rc\n";
}

std::vector<std::string> sbatch_command(const PlannedRun& r, const SlurmOptions& o, const std::string& after) {
  std::vector<std::string> args = {"--parsable",
                                   "--job-name=" + r.name,
                                   "--output=" + sbatch_path(r.log),  // stderr too: the log as the local executor writes it
                                   "--open-mode=truncate",
                                   "--chdir=" + fs::path(r.result).parent_path().string(),
                                   "--ntasks=1",
                                   "--cpus-per-task=" + std::to_string(o.cpus_per_run),
                                   "--time=" + std::to_string(time_limit_minutes(r.cost, o))};
  if (!o.partition.empty()) args.push_back("--partition=" + o.partition);
  if (!o.account.empty()) args.push_back("--account=" + o.account);
  if (!after.empty()) {
    args.push_back("--dependency=afterok:" + after);
    // The cluster drops the job itself if its sample fails, even when no pipeline follows it.
    args.push_back("--kill-on-invalid-dep=yes");
  }
  args.insert(args.end(), o.sbatch_args.begin(), o.sbatch_args.end());
  return args;
}

// ---- the files beside a result --------------------------------------------------------------------

std::string record_file(const std::string& result) { return result + ".job"; }
std::string exit_file(const std::string& result) { return result + ".job.exit"; }

std::optional<JobRecord> read_record(const std::string& result) {
  try {
    const YAML::Node n = dem::load_yaml(record_file(result));
    return JobRecord{n["job_id"].as<std::string>(), n["input_hash"].as<std::string>()};
  } catch (const std::exception&) {
    return std::nullopt;  // missing or unreadable: no job to adopt
  }
}

void write_record(const std::string& result, const JobRecord& record) {
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%S", std::localtime(&now));
  // Atomic: a later pipeline never reads half a record.
  dem::write_file_atomically(record_file(result), "job_id: \"" + record.job_id + "\"\ninput_hash: \"" + record.input_hash +
                                                      "\"\nsubmitted: " + when + "\n");
}

std::optional<int> recorded_exit(const std::string& result, const std::string& job_id) {
  std::ifstream in(exit_file(result));
  std::string id;
  int code = 0;
  if (in >> id >> code && id == job_id) return code;
  return std::nullopt;
}

void remove_job_files(const std::string& result) {
  std::error_code ec;
  fs::remove(record_file(result), ec);
  fs::remove(exit_file(result), ec);
}

// ---- the queue ------------------------------------------------------------------------------------

Queue parse_queue(const std::string& text) {
  Queue queue;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find('|'), last = line.rfind('|');
    if (first == std::string::npos || first == last) continue;
    queue[line.substr(0, first)] = {line.substr(first + 1, last - first - 1), line.substr(last + 1)};
  }
  return queue;
}

bool active(const std::string& state) {
  static const std::set<std::string> ended = {"COMPLETED", "FAILED",        "CANCELLED", "TIMEOUT", "NODE_FAIL",
                                              "PREEMPTED", "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE", "REVOKED"};
  return !state.empty() && ended.count(state) == 0;
}

bool waiting(const std::string& state) { return state != "RUNNING" && state != "COMPLETING"; }

Adoption adoption(const PlannedRun& r, const std::optional<JobRecord>& record, const Queue& queue, bool dependency_ok,
                  std::optional<int> exit_code) {
  if (!record) return Adoption::Submit;
  const auto job = queue.find(record->job_id);
  // The job name guards against a job id that a reset cluster gave to another job.
  const bool live = job != queue.end() && job->second.name == r.name && active(job->second.state);
  if (live) return record->input_hash == r.hash && dependency_ok ? Adoption::Adopt : Adoption::Replace;
  if (record->input_hash == r.hash && r.may_fail && exit_code && (*exit_code == 1 || *exit_code == 2))
    return Adoption::Ended;
  return Adoption::Submit;  // ended some other way: computed again, from its checkpoint if it has one
}

}  // namespace pipeline::slurm
