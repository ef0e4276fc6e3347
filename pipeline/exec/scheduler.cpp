#include "exec/scheduler.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "io/hdf5.hpp"
#include "io/xdmf.hpp"

namespace pipeline {

std::string reuse_problem(const std::string& result, const std::string& hash) {
  std::error_code ec;
  if (!std::filesystem::exists(result, ec)) return "not run yet";
  if (!std::filesystem::is_regular_file(result, ec)) return "not a regular file";
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    const std::string status = dem::h5::has_attribute(f, "status") ? dem::h5::get_string_attribute(f, "status") : "";
    if (status != "complete") return "not marked complete (status '" + status + "')";
    if (!dem::h5::has_attribute(f, "input_hash") || dem::h5::get_string_attribute(f, "input_hash") != hash)
      return "written for other inputs";
    return "";
  } catch (const std::exception& e) {
    return std::string("unreadable, truncated or corrupt (") + e.what() + ")";
  }
}

bool up_to_date(const std::string& result, const std::string& hash) { return reuse_problem(result, hash).empty(); }

std::string outcome_file(const std::string& result) { return result + ".outcome"; }

std::optional<Stop> read_stop(const std::string& result) {
  try {
    const YAML::Node n = YAML::LoadFile(outcome_file(result));
    Stop s;
    s.input_hash = n["input_hash"].as<std::string>();
    s.exit_code = n["exit_code"].as<int>();
    s.message = n["message"].as<std::string>();
    return s;
  } catch (const std::exception&) {
    return std::nullopt;  // missing or unreadable: the run is run again
  }
}

void write_stop(const std::string& result, const Stop& stop) {
  YAML::Emitter e;
  e << YAML::BeginMap << YAML::Key << "input_hash" << YAML::Value << stop.input_hash << YAML::Key << "exit_code"
    << YAML::Value << stop.exit_code << YAML::Key << "outcome" << YAML::Value
    << (stop.exit_code == 2 ? "refused" : "stopped") << YAML::Key << "message" << YAML::Value
    << YAML::DoubleQuoted << stop.message << YAML::EndMap;
  const std::string tmp = outcome_file(result) + ".tmp";
  {
    std::ofstream out(tmp);
    out << e.c_str() << "\n";
    if (!out) throw std::runtime_error(tmp + ": cannot be written");
  }
  std::filesystem::rename(tmp, outcome_file(result));  // atomic: never half an outcome
}

std::optional<Stop> recorded_stop(const std::string& result, const std::string& hash) {
  auto s = read_stop(result);
  if (s && s->input_hash == hash) return s;
  return std::nullopt;
}

namespace {

enum class State { Waiting, Running, Done, Failed, Blocked };

// Why a run stopped: the failed status of its .partial result (a run that started), else the last
// "error: " line of its log (input refused before any step).
std::string stop_message(const PlannedRun& r) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(r.result + ".partial");
    const std::string status = dem::h5::get_string_attribute(f, "status");
    if (status.rfind("failed: ", 0) == 0) return status.substr(8);
  } catch (const std::exception&) {
  }
  std::ifstream log(r.log);
  std::string line, last;
  while (std::getline(log, line))
    if (line.rfind("error: ", 0) == 0) last = line.substr(7);
  return last;
}

pid_t spawn(const std::string& dem, const PlannedRun& r, int threads) {
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {  // child: output to the run's log, then exec dem
    // A killed pipeline takes its runs with it: they resume from their checkpoints when the
    // pipeline is started again, instead of racing a new pipeline for the same result.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);  // the pipeline died before prctl
    const int fd = open(r.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    // --force: a result of this run's earlier inputs is the pipeline's own, replaced by design.
    std::vector<std::string> args = {dem, "run", r.scene_file, "--out", r.result, "--quiet", "--input-hash", r.hash,
                                     "--threads", std::to_string(threads), "--force"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(dem.c_str(), argv.data());
    std::perror(("exec " + dem).c_str());
    _exit(127);
  }
  return pid;
}

// The result of `from` as the result of `to`, which computes the same (PlannedRun::copy_of): the
// file copied with `to`'s input hash and scene, renamed into place complete, with its XDMF.
void copy_result(const PlannedRun& from, const PlannedRun& to) {
  const std::string partial = to.result + ".partial";
  std::filesystem::copy_file(from.result, partial, std::filesystem::copy_options::overwrite_existing);
  {
    dem::h5::Handle f = dem::h5::open_file_write(partial);
    dem::h5::set_attribute(f, "input_hash", to.hash);
    dem::h5::set_attribute(f, "scene_file", to.scene_file);
    dem::h5::set_attribute(f, "scene_yaml", to.scene_text);
    dem::h5::set_attribute(f, "copied_from", from.result);
  }
  std::filesystem::rename(partial, to.result);
  dem::write_xdmf(to.result);
  std::ofstream(to.log) << "copy of " << from.result << " (" << from.name << "): the same scene but for its name\n";
}

std::string minutes(double s) {
  char buf[32];
  if (s < 90) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  return buf;
}

}  // namespace

Outcome execute(const std::vector<PlannedRun>& runs, const std::string& dem, int jobs, int threads) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  std::vector<State> state(runs.size(), State::Waiting);
  std::vector<clock::time_point> started(runs.size());
  std::map<pid_t, std::size_t> running;
  Outcome out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string problem = reuse_problem(runs[i].result, runs[i].hash);
    if (problem.empty()) {
      state[i] = State::Done;
      ++out.reused;
    } else if (runs[i].may_fail && recorded_stop(runs[i].result, runs[i].hash)) {
      state[i] = State::Failed;  // stopped before with these inputs: its outcome stands
      ++out.reused;
    } else {
      // Say why an existing result is not reused (a missing one is simply run).
      if (problem != "not run yet")
        std::printf("[pipeline] %s: the existing %s is %s: run again\n", runs[i].name.c_str(), runs[i].result.c_str(),
                    problem.c_str());
    }
  }
  std::printf("[pipeline] %zu runs: %d reused, %zu to run, %d at a time, %d thread%s each\n", runs.size(),
              out.reused, runs.size() - static_cast<std::size_t>(out.reused), jobs, threads, threads > 1 ? "s" : "");
  // ETA: the work left, in seconds of one worker, shared by the workers that can still be busy.
  // Each run's seconds are its estimated particle-steps over the throughput learnt from the finished
  // runs of its kind (preparations, whose hold has no known length, and tests are learnt apart);
  // a running run counts only what is left of it. Before any run of a kind has finished, the other
  // kind's throughput is used, or 2.5e7 particle-steps/s (this 2-core machine's paper study, two
  // runs at a time).
  struct Learnt {
    double cost = 0, wall = 0;
  };
  Learnt learnt[2];  // [0] preparations, [1] tests
  auto kind = [&](std::size_t i) { return runs[i].test.empty() ? 0 : 1; };
  auto rate = [&](int k) {
    if (learnt[k].wall > 0) return learnt[k].cost / learnt[k].wall;
    if (learnt[1 - k].wall > 0) return learnt[1 - k].cost / learnt[1 - k].wall;
    return 2.5e7;
  };
  auto eta = [&] {
    double seconds = 0;
    int left = 0;
    const auto now = clock::now();
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (runs[i].copy_of >= 0 || (state[i] != State::Waiting && state[i] != State::Running)) continue;
      double t = runs[i].cost / rate(kind(i));
      if (state[i] == State::Running) t = std::max(0.0, t - std::chrono::duration<double>(now - started[i]).count());
      seconds += t;
      ++left;
    }
    return seconds / std::max(1, std::min(jobs, left));
  };
  auto report = [&](const std::string& what) {
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("[pipeline %s] %s; %d ran, %d reused, %d failed, %zu running; ETA %s\n", minutes(elapsed).c_str(),
                what.c_str(), out.ran, out.reused, out.failed, running.size(), minutes(eta()).c_str());
    std::fflush(stdout);
  };
  // Longest chain first: a run's priority is its own cost plus that of the runs waiting for it, so
  // every preparation starts before any test and the last sample is not prepared at the end.
  std::vector<double> priority(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    priority[i] += runs[i].cost;
    if (runs[i].depends_on >= 0) priority[static_cast<std::size_t>(runs[i].depends_on)] += runs[i].cost;
  }
  std::vector<std::size_t> order(runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
  // Starts what can start, in priority order; returns true if it copied a result (PlannedRun::copy_of),
  // which may let other runs start.
  auto start_ready = [&] {
    bool copied = false;
    for (std::size_t i : order) {
      if (state[i] != State::Waiting) continue;
      const int dep = runs[i].depends_on;
      if (dep >= 0 && (state[static_cast<std::size_t>(dep)] == State::Failed ||
                       state[static_cast<std::size_t>(dep)] == State::Blocked)) {
        state[i] = State::Blocked;
        ++(runs[i].may_fail ? out.skipped : out.blocked);
        std::printf("[pipeline] %s %s: %s did not finish\n", runs[i].name.c_str(), runs[i].may_fail ? "skipped" : "blocked",
                    runs[static_cast<std::size_t>(dep)].name.c_str());
        continue;
      }
      if (dep >= 0 && state[static_cast<std::size_t>(dep)] != State::Done) continue;
      if (runs[i].copy_of >= 0) {
        const PlannedRun& original = runs[static_cast<std::size_t>(runs[i].copy_of)];
        try {
          copy_result(original, runs[i]);
          state[i] = State::Done;
          ++out.copied;
          copied = true;
          report("copied " + original.name + " as " + runs[i].name);
        } catch (const std::exception& e) {
          state[i] = State::Failed;
          ++out.failed;
          report("FAILED " + runs[i].name + " (copying " + original.result + ": " + e.what() + ")");
        }
        continue;
      }
      if (static_cast<int>(running.size()) >= jobs) continue;
      std::error_code ec;
      std::filesystem::remove(outcome_file(runs[i].result), ec);  // a stale outcome must not outlive a new run
      running[spawn(dem, runs[i], threads)] = i;
      state[i] = State::Running;
      started[i] = clock::now();
      report("started " + runs[i].name);
    }
    return copied;
  };
  while (true) {
    while (start_ready()) {
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t i = it->second;
    running.erase(it);
    const double wall = std::chrono::duration<double>(clock::now() - started[i]).count();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && up_to_date(runs[i].result, runs[i].hash)) {
      state[i] = State::Done;
      ++out.ran;
      learnt[kind(i)].cost += runs[i].cost;
      learnt[kind(i)].wall += wall;
      report("finished " + runs[i].name + " in " + minutes(wall));
    } else if (runs[i].may_fail && WIFEXITED(status) && (WEXITSTATUS(status) == 1 || WEXITSTATUS(status) == 2)) {
      // An expected kind of end: the engine refused the input or stopped the run, with a message.
      state[i] = State::Failed;
      ++out.stopped;
      const Stop stop{runs[i].hash, WEXITSTATUS(status), stop_message(runs[i])};
      write_stop(runs[i].result, stop);
      report("stopped " + runs[i].name + " (allowed: " + stop.message + ")");
    } else {
      state[i] = State::Failed;
      ++out.failed;
      report("FAILED " + runs[i].name + " (see " + runs[i].log + ")");
    }
  }
  out.wall_time_s = std::chrono::duration<double>(clock::now() - start).count();
  return out;
}

}  // namespace pipeline
