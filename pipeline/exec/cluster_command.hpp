#pragma once
// Running the cluster's commands (sbatch, squeue, sacct, scancel) for the SLURM executor
// (exec/slurm.cpp), and the stop signals it answers by cancelling its jobs.
#include <signal.h>

#include <string>
#include <vector>

namespace pipeline::slurm {

struct CommandResult {
  int status = -1;  // exit code; -1 if it could not run or was killed
  std::string out, err;
};

// Runs argv with `input` on its stdin. In a process group of its own, so that a Ctrl-C at the
// terminal reaches the pipeline only (which then cancels its jobs) and never kills an sbatch
// half-way, leaving a job the pipeline does not know of.
CommandResult run_command(const std::vector<std::string>& argv, const std::string& input = "");

std::string trimmed(std::string s);            // without its trailing blanks
bool on_path(const std::string& command);      // a path that can be run, or a name found on PATH
std::string user_name();                       // the effective user's name (its id if it has none)

// The signal that asked the pipeline to stop (SIGINT, SIGTERM, SIGHUP) since the SignalGuard was
// made, or 0.
int stop_signal();

// Installs the stop handlers for the executor's lifetime (without SA_RESTART, so that a sleep
// ends at once), and ignores SIGPIPE from a command that exits before reading its script.
class SignalGuard {
 public:
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  const int signals_[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction old_[4];
};

// Sleeps `seconds`, or less if a stop signal comes.
void nap(double seconds);

}  // namespace pipeline::slurm
