#include "exec/scheduler.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

#include "io/hdf5.hpp"

namespace pipeline {

bool up_to_date(const std::string& result, const std::string& hash) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(result, ec)) return false;
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    return dem::h5::has_attribute(f, "status") && dem::h5::get_string_attribute(f, "status") == "complete" &&
           dem::h5::has_attribute(f, "input_hash") && dem::h5::get_string_attribute(f, "input_hash") == hash;
  } catch (const std::exception&) {
    return false;  // unreadable or truncated: run it again
  }
}

namespace {

enum class State { Waiting, Running, Done, Failed, Blocked };

pid_t spawn(const std::string& dem, const PlannedRun& r, int threads) {
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {  // child: output to the run's log, then exec dem
    const int fd = open(r.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    std::vector<std::string> args = {dem, "run", r.scene_file, "--out", r.result, "--quiet", "--input-hash", r.hash,
                                     "--threads", std::to_string(threads)};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(dem.c_str(), argv.data());
    std::perror(("exec " + dem).c_str());
    _exit(127);
  }
  return pid;
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
  double cost_done = 0, busy_wall = 0, cost_left = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (up_to_date(runs[i].result, runs[i].hash)) {
      state[i] = State::Done;
      ++out.reused;
    } else {
      cost_left += runs[i].cost;
    }
  }
  std::printf("[pipeline] %zu runs: %d reused, %zu to run, %d at a time, %d thread%s each\n", runs.size(),
              out.reused, runs.size() - static_cast<std::size_t>(out.reused), jobs, threads, threads > 1 ? "s" : "");
  auto report = [&](const std::string& what) {
    // ETA from the throughput of the runs finished so far (particle-steps per second per worker),
    // or 8e6 per worker before any has finished (the engine's benchmark).
    const double rate = busy_wall > 0 ? cost_done / busy_wall : 8e6;
    const double workers = std::max(1.0, std::min<double>(jobs, static_cast<double>(running.size())));
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("[pipeline %s] %s; %d ran, %d reused, %d failed, %zu running; ETA %s\n", minutes(elapsed).c_str(),
                what.c_str(), out.ran, out.reused, out.failed, running.size(), minutes(std::max(0.0, cost_left) / rate / workers).c_str());
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
  while (true) {
    // Start what can start.
    for (std::size_t i : order) {
      if (static_cast<int>(running.size()) >= jobs) break;
      if (state[i] != State::Waiting) continue;
      const int dep = runs[i].depends_on;
      if (dep >= 0 && (state[static_cast<std::size_t>(dep)] == State::Failed ||
                       state[static_cast<std::size_t>(dep)] == State::Blocked)) {
        state[i] = State::Blocked;
        ++out.blocked;
        cost_left -= runs[i].cost;
        std::printf("[pipeline] %s blocked: %s failed\n", runs[i].name.c_str(), runs[static_cast<std::size_t>(dep)].name.c_str());
        continue;
      }
      if (dep >= 0 && state[static_cast<std::size_t>(dep)] != State::Done) continue;
      running[spawn(dem, runs[i], threads)] = i;
      state[i] = State::Running;
      started[i] = clock::now();
      report("started " + runs[i].name);
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
    cost_left -= runs[i].cost;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && up_to_date(runs[i].result, runs[i].hash)) {
      state[i] = State::Done;
      ++out.ran;
      cost_done += runs[i].cost;
      busy_wall += wall;
      report("finished " + runs[i].name + " in " + minutes(wall));
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
