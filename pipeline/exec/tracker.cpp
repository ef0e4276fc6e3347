#include "exec/tracker.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "io/file_lock.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"

namespace pipeline {

namespace {

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

// A run killed where dem's own handlers cannot run (SIGKILL: the out-of-memory killer, kill -9, a
// cluster's hard limit) leaves its .partial with the status "running". The pipeline saw it end, so
// it puts how in the status, unless a process holds the run's lock again (a run started since).
// The checkpoint stays: the next run resumes from it as after any stop.
void mark_killed(const PlannedRun& r, const std::string& how) {
  const std::string partial = r.result + ".partial";
  try {
    std::error_code ec;
    if (!std::filesystem::exists(partial, ec) || dem::FileLock::held_by_a_process(r.result + ".lock")) return;
    dem::h5::Handle f = dem::h5::open_file_write(partial);
    if (dem::h5::has_attribute(f, "status") && dem::h5::get_string_attribute(f, "status") == "running")
      dem::h5::set_attribute(f, "status", "failed: " + (how.empty() ? std::string("ended without a status") : how) + " (seen by the pipeline)");
  } catch (const std::exception&) {  // not a readable result: the run's FAILED line says what is known
  }
}

// The scene a copy records: the source's as the engine resolved it (every default filled in, as in
// any result, so that what is read from it, e.g. the baseline of its settings, is the source's),
// under the copy's own name; the study's text of the copy's scene if the source's has no name line.
std::string copied_scene(const std::string& resolved_source, const std::string& copy_scene_text) {
  std::string name;
  try {
    name = dem::parse_yaml(copy_scene_text, "the copy's scene")["name"].as<std::string>("");
  } catch (const std::exception&) {
  }
  if (name.empty() || resolved_source.rfind("name: ", 0) != 0) return copy_scene_text;
  const std::size_t end = resolved_source.find('\n');
  return "name: " + name + (end == std::string::npos ? "" : resolved_source.substr(end));
}

// The result of `from` as the result of `to`, which computes the same (PlannedRun::copy_of): the
// file copied with `to`'s input hash and scene, renamed into place complete, with its XDMF.
void copy_result(const PlannedRun& from, const PlannedRun& to) {
  const std::string partial = to.result + ".partial";
  std::filesystem::copy_file(from.result, partial, std::filesystem::copy_options::overwrite_existing);
  {
    dem::h5::Handle f = dem::h5::open_file_write(partial);
    const std::string resolved = dem::h5::has_text(f, "scene_yaml") ? dem::h5::read_text(f, "scene_yaml") : "";
    dem::h5::set_attribute(f, "input_hash", to.hash);
    dem::h5::set_attribute(f, "scene_file", to.scene_file);
    dem::h5::write_text(f, "scene_yaml", copied_scene(resolved, to.scene_text));
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

// --force: a result of this run's earlier inputs is the pipeline's own, replaced by design. Its
// stderr goes to the run's log (local or SLURM): a progress line every 30 s there.
std::vector<std::string> dem_command(const std::string& dem, const PlannedRun& r, int threads) {
  return {dem, "run", r.scene_file, "--out", r.result, "--input-hash", r.hash, "--threads", std::to_string(threads), "--force"};
}

Tracker::Tracker(const std::vector<PlannedRun>& runs)
    : runs_(runs), state_(runs.size(), RunState::Waiting), started_(runs.size()), queued_(runs.size(), false), order_(runs.size()) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string problem = reuse_problem(runs[i].result, runs[i].hash);
    if (problem.empty()) {
      state_[i] = RunState::Done;
      ++out_.reused;
      learn(i, 0);
    } else if (runs[i].may_fail && recorded_stop(runs[i].result, runs[i].hash)) {
      state_[i] = RunState::Failed;  // stopped before with these inputs: its outcome stands
      ++out_.reused;
    } else if (problem != "not run yet") {  // say why an existing result is not reused (a missing one is simply run)
      std::printf("[pipeline] %s: the existing %s is %s: run again\n", runs[i].name.c_str(), runs[i].result.c_str(),
                  problem.c_str());
    }
  }
  std::vector<double> priority(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    priority[i] += runs[i].cost;
    if (runs[i].depends_on >= 0) priority[static_cast<std::size_t>(runs[i].depends_on)] += runs[i].cost;
  }
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return priority[a] > priority[b]; });
}

void Tracker::announce(const std::string& how) const {
  std::printf("[pipeline] %zu runs: %d reused, %zu to run, %s\n", runs_.size(), out_.reused,
              runs_.size() - static_cast<std::size_t>(out_.reused), how.c_str());
  std::fflush(stdout);
}

std::vector<std::size_t> Tracker::settle() {
  std::vector<std::size_t> blocked;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i : order_) {
      // A queued SLURM job waits for its dependency's job like a waiting run for its dependency.
      const bool waiting = state_[i] == RunState::Waiting || (state_[i] == RunState::Running && queued_[i]);
      if (!waiting || runs_[i].depends_on < 0) continue;
      const auto dep = static_cast<std::size_t>(runs_[i].depends_on);
      if (state_[dep] == RunState::Failed || state_[dep] == RunState::Blocked) {
        state_[i] = RunState::Blocked;
        queued_[i] = false;
        ++(runs_[i].may_fail ? out_.skipped : out_.blocked);
        std::printf("[pipeline] %s %s: %s did not finish\n", runs_[i].name.c_str(),
                    runs_[i].may_fail ? "skipped" : "blocked", runs_[dep].name.c_str());
        blocked.push_back(i);
        changed = true;
      } else if (state_[i] == RunState::Waiting && runs_[i].copy_of >= 0 && state_[dep] == RunState::Done) {
        const PlannedRun& original = runs_[static_cast<std::size_t>(runs_[i].copy_of)];
        try {
          copy_result(original, runs_[i]);
          state_[i] = RunState::Done;
          ++out_.copied;
          report("copied " + original.name + " as " + runs_[i].name);
        } catch (const std::exception& e) {
          state_[i] = RunState::Failed;
          ++out_.failed;
          report("FAILED " + runs_[i].name + " (copying " + original.result + ": " + e.what() + ")");
        }
        changed = true;
      }
    }
  }
  std::fflush(stdout);
  return blocked;
}

bool Tracker::ready(std::size_t i) const {
  if (state_[i] != RunState::Waiting || runs_[i].copy_of >= 0) return false;
  return runs_[i].depends_on < 0 || state_[static_cast<std::size_t>(runs_[i].depends_on)] == RunState::Done;
}

void Tracker::adopt(std::size_t i) {
  state_[i] = RunState::Running;
  started_[i] = clock::now();
}

void Tracker::set_queued(std::size_t i, bool queued) {
  if (queued_[i] && !queued) started_[i] = clock::now();
  queued_[i] = queued;
}

void Tracker::start(std::size_t i, const std::string& what, bool queued) {
  std::error_code ec;
  std::filesystem::remove(outcome_file(runs_[i].result), ec);  // a stale outcome must not outlive a new run
  adopt(i);
  queued_[i] = queued;
  report(what.empty() ? "started " + runs_[i].name : what);
}

void Tracker::end(std::size_t i, const Ending& e) {
  const PlannedRun& r = runs_[i];
  queued_[i] = false;
  const double wall = std::chrono::duration<double>(clock::now() - started_[i]).count();
  if (e.exited && e.code == 0 && up_to_date(r.result, r.hash)) {
    state_[i] = RunState::Done;
    ++out_.ran;
    learn(i, wall);
    report("finished " + r.name + " in " + minutes(wall));
  } else if (r.may_fail && e.exited && (e.code == 1 || e.code == 2)) {
    // An expected kind of end: the engine refused the input or stopped the run, with a message.
    state_[i] = RunState::Failed;
    ++out_.stopped;
    const Stop stop{r.hash, e.code, stop_message(r)};
    write_stop(r.result, stop);
    report("stopped " + r.name + " (allowed: " + stop.message + ")");
  } else {
    state_[i] = RunState::Failed;
    ++out_.failed;
    if (!e.exited) mark_killed(r, e.note);
    report("FAILED " + r.name + " (" + (e.note.empty() ? "" : e.note + "; ") + "see " + r.log + ")");
  }
}

int Tracker::running() const { return static_cast<int>(std::count(state_.begin(), state_.end(), RunState::Running)); }

bool Tracker::busy() const {
  return std::any_of(state_.begin(), state_.end(),
                     [](RunState s) { return s == RunState::Waiting || s == RunState::Running; });
}

Outcome Tracker::outcome() const {
  Outcome o = out_;
  o.wall_time_s = std::chrono::duration<double>(clock::now() - start_).count();
  return o;
}

void Tracker::learn(std::size_t i, double wall_s) {
  const PlannedRun& r = runs_[i];
  if (r.copy_of >= 0) return;
  const std::optional<ResultCost> c = result_cost(r.result);
  if (!c) return;
  Scale& s = scale_[r.family];
  s.planned += r.cost, s.done += c->particle_steps;
  const double wall = c->wall_s.value_or(wall_s);
  if (wall > 0) learnt_[kind(i)].cost += c->particle_steps, learnt_[kind(i)].wall += wall;
}

double Tracker::expected_cost(std::size_t i) const {
  const auto s = scale_.find(runs_[i].family);
  if (s == scale_.end() || s->second.planned <= 0) return runs_[i].cost;
  return runs_[i].cost * (s->second.done / s->second.planned);
}

// Each run's seconds are its expected particle-steps over the throughput learnt from the finished
// (and reused) runs of its kind (preparations and tests apart: a gas compresses faster per step).
// Before any run of a kind has finished, the other kind's throughput is used, or 2.5e7
// particle-steps/s (this 2-core machine's paper study, two runs at a time).
double Tracker::rate(int k) const {
  if (learnt_[k].wall > 0) return learnt_[k].cost / learnt_[k].wall;
  if (learnt_[1 - k].wall > 0) return learnt_[1 - k].cost / learnt_[1 - k].wall;
  return 2.5e7;
}

// The work left, in seconds of one worker, shared by the workers that can still be busy; a
// running run counts only what is left of it.
double Tracker::eta_seconds() const {
  double seconds = 0;
  int left = 0;
  const auto now = clock::now();
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    if (runs_[i].copy_of >= 0 || (state_[i] != RunState::Waiting && state_[i] != RunState::Running)) continue;
    double t = expected_cost(i) / rate(kind(i));
    if (state_[i] == RunState::Running && !queued_[i]) t = std::max(0.0, t - std::chrono::duration<double>(now - started_[i]).count());
    seconds += t;
    ++left;
  }
  return seconds / std::max(1, std::min(workers_, left));
}

void Tracker::report(const std::string& what) const {
  const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
  const int queued = static_cast<int>(std::count(queued_.begin(), queued_.end(), true));
  std::printf("[pipeline %s] %s; %d ran, %d reused, %d failed, %d running", minutes(elapsed).c_str(), what.c_str(),
              out_.ran, out_.reused, out_.failed, running() - queued);
  if (queued > 0) std::printf(", %d queued", queued);
  std::printf("; ETA %s\n", minutes(eta_seconds()).c_str());
  std::fflush(stdout);
}

}  // namespace pipeline
