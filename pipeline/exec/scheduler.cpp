#include "exec/scheduler.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <csignal>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "exec/tracker.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/result_file.hpp"

namespace pipeline {

std::unique_ptr<dem::FileLock> lock_folder(const std::string& dir, const std::string& name, const std::string& tool,
                                           const std::string& why) {
  std::filesystem::create_directories(dir);
  const std::string path = (std::filesystem::path(dir) / name).string();
  auto lock = std::make_unique<dem::FileLock>(path);
  if (!lock->held()) {
    if (!lock->error().empty()) throw dem::ConfigError(dir + ": " + lock->error());
    std::string holder = dem::FileLock::read_note(path);
    while (!holder.empty() && holder.back() == '\n') holder.pop_back();
    throw dem::ConfigError("another " + tool + " is running in " + dir + (holder.empty() ? "" : " (" + holder + ")") + ": " + why +
                           "; wait for it to end, or stop it (it resumes where it stopped); nothing was run");
  }
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  lock->note("pid " + std::to_string(getpid()) + " on " + host + "\n");
  return lock;
}

std::unique_ptr<dem::FileLock> lock_results_folder(const std::string& out_dir) {
  return lock_folder(out_dir, ".pipeline.lock", "pipeline", "two would run the same runs at once and write the same logs");
}

std::string engine_version(const std::string& dem) {
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) return "";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  std::string path = dem, flag = "--source-hash";
  char* argv[] = {path.data(), flag.data(), nullptr};
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, path.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string text;
  if (spawned == 0) {
    char buf[256];
    for (ssize_t n; (n = read(out[0], buf, sizeof buf)) != 0;) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) break;
      text.append(buf, static_cast<std::size_t>(n));
    }
  }
  close(out[0]);
  if (spawned != 0) return "";
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return "";
  text = text.substr(0, text.find('\n'));
  while (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

namespace {

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
    std::vector<std::string> args = dem_command(dem, r, threads);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(dem.c_str(), argv.data());
    std::perror(("exec " + dem).c_str());
    _exit(127);
  }
  return pid;
}

}  // namespace

Outcome execute(const std::vector<PlannedRun>& runs, const std::string& dem, int jobs, int threads) {
  Tracker tracker(runs);
  tracker.announce(std::to_string(jobs) + " at a time, " + std::to_string(threads) + " thread" + (threads > 1 ? "s" : "") +
                   " each");
  tracker.set_workers(jobs);
  std::map<pid_t, std::size_t> running;
  while (true) {
    tracker.settle();  // copies and blocked runs first: a copy may let other runs start
    for (std::size_t i : tracker.order()) {
      if (static_cast<int>(running.size()) >= jobs) break;
      if (!tracker.ready(i)) continue;
      running[spawn(dem, runs[i], threads)] = i;
      tracker.start(i);
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t i = it->second;
    running.erase(it);
    const std::string signal = WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                                                         sigabbrev_np(WTERMSIG(status)) + ")"
                                                   : "";
    tracker.end(i, {WIFEXITED(status), WIFEXITED(status) ? WEXITSTATUS(status) : 0, signal});
  }
  return tracker.outcome();
}

}  // namespace pipeline
