// dem: the command-line front end of the engine (arguments through CLI11; every sub-command
// answers --help).
//   dem run SCENE.yaml --out RESULT.h5     run a scene, write its result
//   dem keys                               the reference of every scene key
//   dem columns [--legs]                   the columns of a result's /timeseries (/legs), as engine/README.md lists them
//   dem table | state | summary RESULT.h5  read a result
//   dem render RESULT.h5 --out FRAME.png   draw its last frame with ParaView (reports/render/render.sh)
//   dem plot RESULT.h5 X Y [MORE.h5 ...]   one column against another, results overlaid (gnuplot; cli/plot.cpp)
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "cli/plot.hpp"
#include "io/hdf5.hpp"
#include "io/result_file.hpp"
#include "io/result_writer.hpp"  // describe_failure
#include "io/state_io.hpp"
#include "io/xdmf.hpp"
#include "run/output_path.hpp"
#include "run/run_request.hpp"
#include "source_hash.hpp"
#include "version.hpp"

namespace {

const char* run_footer =
    "The result is written to RESULT.h5.partial while the run goes on and renamed to RESULT.h5\n"
    "(status 'complete') only when it finishes and is on the disk; RESULT.h5.checkpoint holds the\n"
    "newest checkpoint until then. --out must end in .h5 or .hdf5 and may not name a non-regular\n"
    "file (device, folder, FIFO, link) or a file the scene reads. Paths typed on the command line\n"
    "(--out, --set particles.state=FILE) are relative to the current folder; paths inside the\n"
    "scene file are relative to the scene file. Exit status: 0 success, 1 run failed (the reason\n"
    "on stderr and in the status of RESULT.h5.partial), 2 bad input (nothing written).";

// The progress of a run (`dem run` without --quiet). On a terminal one line, redrawn at most every
// 0.5 s; otherwise (a log file, a batch job's output) a line of its own every --progress-interval
// seconds of wall time (0: at every report the run makes, each 256 steps). A line gives the step,
// the simulated time, the steps per second since the line before and the time left in the stage
// from its progress so far. Warnings and notes start on a line of their own.
class ProgressLine {
 public:
  ProgressLine(bool terminal, double interval_s) : terminal_(terminal), interval_s_(terminal ? 0.5 : interval_s) {}
  void draw(const dem::RunProgress& p) {
    if (!started_) {  // the first report: the first interval starts
      started_ = true, last_step_ = p.step, last_elapsed_s_ = p.elapsed_s;
      if (interval_s_ > 0) return;
    } else if (p.elapsed_s - last_elapsed_s_ < interval_s_) {
      return;
    }
    std::fprintf(stderr, "%s[%s %d/%d '%s'] step %lld, t = %.4g s", terminal_ ? "\r\033[K" : "", p.scene.c_str(), p.stage + 1,
                 p.stages, p.stage_name.c_str(), static_cast<long long>(p.step), p.time_s);
    if (p.step > last_step_ && p.elapsed_s > last_elapsed_s_)
      std::fprintf(stderr, ", %.3g steps/s", static_cast<double>(p.step - last_step_) / (p.elapsed_s - last_elapsed_s_));
    last_step_ = p.step, last_elapsed_s_ = p.elapsed_s;
    if (p.stage_fraction > 0) {
      if (stage_seen_ != p.stage) stage_seen_ = p.stage, stage_start_s_ = p.elapsed_s;
      const double stage_elapsed = p.elapsed_s - stage_start_s_;
      std::fprintf(stderr, ", %.0f %% of stage, ETA %.0f s", 100 * p.stage_fraction,
                   stage_elapsed * (1 - p.stage_fraction) / p.stage_fraction);
    }
    if (!p.status.empty()) std::fprintf(stderr, ", %s", p.status.c_str());
    std::fputs(terminal_ ? "" : "\n", stderr);
    std::fflush(stderr);
    drawn_ = terminal_;
  }
  void new_line() {  // before a message: the line drawn so far stays
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }
  void clear() {  // at the end of the run: the line goes
    if (drawn_) std::fprintf(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  bool terminal_;
  double interval_s_;         // wall time between lines [s]
  bool started_ = false;      // a report seen: the times below are set
  std::int64_t last_step_ = 0;
  double last_elapsed_s_ = 0; // the step and wall time [s since the run started] of the last line, or the first report
  bool drawn_ = false;        // a terminal line is on the screen
  int stage_seen_ = -1;       // for the ETA: the stage being timed and when it started
  double stage_start_s_ = 0;  // [s since the run started]
};

// The warning for a stage that, at the speed measured over its first long_stage_sample_s of wall
// time, needs more than long_stage_s more: once per stage (a run of 1e10 steps is accepted, but
// says how long it will take).
constexpr double long_stage_sample_s = 10, long_stage_s = 86400;
class LongStageWarning {
 public:
  std::string check(const dem::RunProgress& p) {
    if (p.stage != stage_) stage_ = p.stage, start_s_ = p.elapsed_s, start_fraction_ = p.stage_fraction, warned_ = false;
    const double spent = p.elapsed_s - start_s_, done = p.stage_fraction - start_fraction_;
    if (warned_ || spent < long_stage_sample_s || !(done > 0)) return "";
    const double left_s = spent * (1 - p.stage_fraction) / done;
    if (!(left_s > long_stage_s)) return "";
    warned_ = true;
    char text[256];
    std::snprintf(text, sizeof text, "stage %d/%d '%s': at its speed so far (%.3g %% of it in %.0f s) it needs about %.3g days more; "
                  "shorten it or raise numerics.time_step if that was not meant", p.stage + 1, p.stages, p.stage_name.c_str(),
                  100 * done, spent, left_s / 86400);
    return text;
  }

 private:
  int stage_ = -1;
  double start_s_ = 0, start_fraction_ = 0;
  bool warned_ = false;
};

// The line after a failed run that kept RESULT.h5.partial. Its status says why the run failed;
// out of memory or on a full disk HDF5 may not manage to write that status (the file then says
// "running", has none, or cannot be read), and the line says so. A .partial is never taken for a
// result either way.
std::string partial_kept_line(const std::string& partial) {
  std::string status = "missing";
  try {
    dem::h5::Handle f = dem::h5::open_file_read(partial);
    if (dem::h5::has_attribute(f, "status")) status = "'" + dem::h5::get_string_attribute(f, "status") + "'";
  } catch (const std::exception&) {
    status = "unreadable";
  }
  std::string line = "(partial result kept in " + partial;
  if (status.rfind("'failed: ", 0) != 0) line += "; its status could not be set to the reason above: it is " + status;
  return line + ")\n";
}

// The signal that asked the run to stop (SIGTERM, SIGINT, SIGHUP), or 0: read by the run before
// every step (RunObserver::stop), which then marks its partial result as interrupted and lets go
// of its lock; main then ends the process by that signal, as it would have ended without dem's
// handler (the caller, e.g. the pipeline, sees a run killed by a signal).
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void on_stop_signal(int signo) { stop_signal = signo; }

void catch_stop_signals() {
  struct sigaction sa{};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int signo : {SIGTERM, SIGINT, SIGHUP}) {
    struct sigaction before{};
    sigaction(signo, nullptr, &before);
    if (before.sa_handler != SIG_IGN) sigaction(signo, &sa, nullptr);  // one ignored by the caller (nohup) stays so
  }
}

// What a run asked for more than one thread did with them (run/thread_choice.hpp), for the last line.
std::string threads_line(int asked, const dem::RunSummary& s) {
  char text[256];
  if (s.threads == 1) {
    std::snprintf(text, sizeof text, "; on 1 thread: %d asked, but one chunk of 512 particles leaves a second thread nothing", asked);
  } else {
    const double share = s.steps > 0 ? 100.0 * static_cast<double>(s.steps_on_one_thread) / static_cast<double>(s.steps) : 0;
    std::snprintf(text, sizeof text, "; %d threads, %.0f %% of the steps on 1 thread: %d trial%s of the other count, %d won", s.threads,
                  share, s.thread_trials, s.thread_trials == 1 ? "" : "s", s.thread_switches);
  }
  return text;
}

struct RunArgs {
  std::string scene_file, out, input_hash;
  std::vector<std::string> sets;  // KEY=VALUE
  int threads = 1;
  double progress_interval_s = 30;  // between progress lines when stderr is not a terminal
  bool quiet = false, resume = false, no_resume = false, force = false;
};

int run(const RunArgs& args) {
  dem::RunRequest request;
  request.scene_file = args.scene_file;
  request.out = args.out;
  request.input_hash = args.input_hash;
  request.threads = args.threads;
  request.force = args.force;
  request.resume = args.resume ? dem::Resume::Always : args.no_resume ? dem::Resume::Never : dem::Resume::IfValid;
  for (const std::string& kv : args.sets) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) { std::fprintf(stderr, "dem run: --set needs KEY=VALUE, got '%s'\n", kv.c_str()); return 2; }
    request.overrides.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  ProgressLine line(isatty(STDERR_FILENO) != 0, args.progress_interval_s);
  try {
    LongStageWarning long_stage;
    dem::RunObserver observer;
    observer.stop = &stop_signal;
    catch_stop_signals();
    observer.warning = [&](const std::string& w) {
      line.new_line();
      std::fprintf(stderr, "warning: %s\n", w.c_str());
    };
    observer.progress = [&](const dem::RunProgress& p) {
      if (!args.quiet) line.draw(p);
      if (const std::string w = long_stage.check(p); !w.empty()) observer.warning(w);
    };
    observer.note = [&](const std::string& n) {
      line.new_line();
      std::fprintf(stderr, "%s\n", n.c_str());
    };
    const dem::RunSummary s = dem::run_request(request, observer);
    line.clear();
    std::fprintf(stderr, "%s: %lld steps in %.1f s (%.3g steps/s", s.scene.c_str(), static_cast<long long>(s.steps),
                 s.wall_time_s, static_cast<double>(s.steps) / s.wall_time_s);
    if (args.threads > 1) std::fputs(threads_line(args.threads, s).c_str(), stderr);
    std::fprintf(stderr, ") -> %s\n", args.out.c_str());
    return 0;
  } catch (const dem::OutputPathError& e) {  // nothing was written
    std::fprintf(stderr, "error: %s; nothing was run\n", e.what());
    return 2;
  } catch (const dem::ConfigError& e) {  // bad input: nothing was written
    line.new_line();
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    line.new_line();
    std::fprintf(stderr, "error: %s: %s\n", args.scene_file.c_str(), dem::describe_failure(e).c_str());
    if (std::filesystem::exists(args.out + ".partial")) std::fputs(partial_kept_line(args.out + ".partial").c_str(), stderr);
    return 1;
  }
}

// The unit of a column from the registry (series_columns, leg_columns); "" if it has none.
std::string unit_of(const std::string& name, bool legs) {
  for (const auto& c : legs ? dem::leg_columns() : dem::series_columns())
    if (c.name == name) return c.units;
  return "";
}

// "name [unit]", or the name alone for a column without a unit: the headers of table and summary.
std::string with_unit(const std::string& name, const std::string& unit) { return unit.empty() ? name : name + " [" + unit + "]"; }

struct TableArgs {
  std::string file;
  std::vector<std::string> columns;
  bool legs = false, csv = false;
};

// Prints time-series (or per-leg) columns of a result (all of them if none are named): a header
// of `name [unit]` entries, then one row per line; tab-separated with 10 significant digits after
// a '#' header, or CSV with 17 (every double read back exactly, e.g. by pandas.read_csv).
int table(const TableArgs& args) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(args.file);
    const char* group = args.legs ? "legs" : "timeseries";
    dem::h5::open_group(f, group);  // a file without the table: HDF5's error, naming it
    const dem::Table table = dem::read_table(f, group, args.file);  // every column as long as the others, checksums checked
    std::vector<std::string> names = args.columns;
    if (names.empty())
      for (const auto& c : args.legs ? dem::leg_columns() : dem::series_columns()) names.push_back(c.name);
    std::vector<std::vector<double>> cols;
    for (const auto& n : names) {
      if (!table.count(n)) { std::fprintf(stderr, "dem table: %s has no column '%s'\n", args.file.c_str(), n.c_str()); return 2; }
      cols.push_back(table.at(n));
    }
    const char* sep = args.csv ? "," : "\t";
    std::printf("%s", args.csv ? "" : "# ");
    for (std::size_t c = 0; c < names.size(); ++c) {
      std::printf("%s%s", c ? sep : "", with_unit(names[c], unit_of(names[c], args.legs)).c_str());
    }
    std::printf("\n");
    const char* number = args.csv ? "%.17g" : "%.10g";
    for (std::size_t r = 0; r < cols[0].size(); ++r) {
      for (std::size_t c = 0; c < cols.size(); ++c) {
        if (c) std::fputs(sep, stdout);
        std::printf(number, cols[c][r]);
      }
      std::printf("\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}

// The final particles of a result: real position and radius, one tab-separated line each.
int state(const std::string& file) {
  try {
    const dem::SavedState st = dem::read_state(file);
    std::printf("# x\ty\tz\tradius (m); cell %.10g %.10g %.10g\n", st.cell.lengths()[0], st.cell.lengths()[1],
                st.cell.lengths()[2]);
    for (std::size_t i = 0; i < st.particles.size(); ++i) {
      const dem::Vec3 x = st.cell.to_real(st.particles.s[i]);
      std::printf("%.10g\t%.10g\t%.10g\t%.10g\n", x[0], x[1], x[2], st.particles.radius[i]);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}

// One tab-separated line per complete result: file, wall time, then the last time-series row;
// the header names each column with its unit, as table's does.
int summary(const std::vector<std::string>& files) {
  std::printf("# file\twall_time [s]");
  for (const auto& c : dem::series_columns()) std::printf("\t%s", with_unit(c.name, c.units).c_str());
  std::printf("\n");
  int status = 0;
  for (const std::string& file : files) {
    try {
      dem::h5::Handle f = dem::h5::open_file_read(file);
      if (const std::string why = dem::result_problem(f); !why.empty()) throw std::runtime_error("not a complete result: " + why);
      const dem::Table table = dem::read_table(f, "timeseries", file);
      std::printf("%s\t%.6g", file.c_str(), dem::h5::get_double_attribute(f, "wall_time_s"));
      for (const auto& c : dem::series_columns()) {  // columns a result's schema lacks print as nan
        const auto it = table.find(c.name);
        std::printf("\t%.10g", it == table.end() || it->second.empty() ? std::nan("") : it->second.back());
      }
      std::printf("\n");
    } catch (const std::exception& e) {
      const std::string what = e.what();  // the table reader's errors name the file already
      std::fprintf(stderr, "dem summary: %s\n", (what.rfind(file, 0) == 0 ? what : file + ": " + what).c_str());
      status = 1;
    }
  }
  return status;
}

// OpenMP threads that wait for work spin by default (libgomp: 300,000 iterations), so one that
// waits while the other's core is taken by another process burns its own core for nothing. Test 1
// (1,000 spheres) cut to its first leg, beside a busy shell loop on a shared 2-core machine (load
// average 20): 1 thread 3.3 s, 2 threads spinning 90.9 s, 2 threads waiting passively (asleep
// until woken) 1.4 s. libgomp reads OMP_WAIT_POLICY once, when it is loaded,
// before main: so a run on several threads starts itself again with it set, unless the caller set
// it (or GOMP_SPINCOUNT) on purpose. If the new start fails, the run goes on as it is.
void wait_passively(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");  // not started again: nothing changed
}

struct RenderArgs {
  std::string result, png, title;
};

// The render script: installed beside the programs (PREFIX/bin/../share/cyclic-triax/render) or, in
// a clone, the source tree's (build/bin/../../reports/render); "" if neither is there.
std::string render_script() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path bin = fs::canonical("/proc/self/exe", ec).parent_path();
  for (const fs::path& p : {bin / "../share/cyclic-triax/render/render.sh", bin / "../../reports/render/render.sh"})
    if (fs::is_regular_file(p, ec)) return fs::weakly_canonical(p, ec).string();
  return "";
}

// Runs `argv` and waits for it: its exit status, 127 if it could not be started.
int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

// `dem render`: the result's XDMF view is written into a folder of its own beside a link to the
// result (nothing is written beside the result, which may be read-only, e.g. a shipped sample),
// and the render script draws its last frame with ParaView.
int render(const RenderArgs& args) {
  namespace fs = std::filesystem;
  const std::string script = render_script();
  if (script.empty()) {
    std::fprintf(stderr, "error: dem render: no render.sh in share/cyclic-triax/render or reports/render beside this dem\n");
    return 2;
  }
  std::error_code ec;
  if (!fs::is_regular_file(args.result, ec)) {
    std::fprintf(stderr, "error: dem render: %s is not a result file\n", args.result.c_str());
    return 2;
  }
  std::string folder = (fs::temp_directory_path() / "dem-render-XXXXXX").string();
  if (!mkdtemp(folder.data())) {
    std::fprintf(stderr, "error: dem render: cannot make a folder in %s: %s\n", fs::temp_directory_path().c_str(), std::strerror(errno));
    return 1;
  }
  const fs::path name = fs::path(args.result).stem();
  const fs::path link = fs::path(folder) / (name.string() + ".h5");
  int rc = 1;
  try {
    fs::create_symlink(fs::absolute(args.result), link);
    dem::write_xdmf(link.string());
    rc = run_program({"/bin/bash", script, dem::xdmf_path_for(link.string()), args.png, args.title.empty() ? name.string() : args.title});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: dem render: %s: %s\n", args.result.c_str(), e.what());
    rc = 2;
  }
  fs::remove_all(folder, ec);
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  // HDF5 must not close files itself at exit: one whose close failed (a full disk) would crash
  // the library there (HDF5 1.10), after the error was reported. Every file dem opens is closed
  // by its handle before main returns.
  H5dont_atexit();
  // A file size limit (ulimit -f) is a full disk: with SIGXFSZ ignored, a write past it fails with
  // EFBIG and the run ends as on a full disk (exit 1, the reason on stderr and in the status of
  // RESULT.h5.partial) instead of being killed by the signal with nothing said.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"dem: the DEM engine of cyclic-triax (spheres in a periodic, stress- or strain-controlled cell)"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("dem ") + dem::software_version + " (result schema " +
                                        std::to_string(dem::schema_version) + ", engine source " + dem::engine_source_hash + ")");
  // What the pipeline keys its reuse of results on.
  app.add_flag_callback("--source-hash", [] {
    std::printf("%s schema %d\n", dem::engine_source_hash, dem::schema_version);
    throw CLI::Success();
  }, "print the engine source hash and the result schema (what the pipeline keys reuse on)");

  RunArgs ra;
  CLI::App* run_cmd = app.add_subcommand("run", "run a scene and write its result (HDF5)");
  run_cmd->add_option("scene", ra.scene_file, "the scene file (YAML; dem keys lists every key)")->required();
  run_cmd->add_option("--out", ra.out, "the result file, RESULT.h5 (or .hdf5)")->required();
  run_cmd->add_option("--set", ra.sets, "KEY=VALUE: override a scene key, e.g. particles.lattice.seed=2 (repeatable)")
      ->allow_extra_args(false);
  run_cmd->add_option("--threads", ra.threads, "threads inside the run (the result is bit for bit the same for any count): the run tries 1 thread "
                      "now and then and keeps whichever steps faster, e.g. 1 beside other busy processes")
      ->check(CLI::Range(1, 256))->default_val(1);
  run_cmd->add_flag("--quiet", ra.quiet, "no progress line");
  run_cmd->add_option("--progress-interval", ra.progress_interval_s,
                      "seconds of wall time between progress lines when stderr is not a terminal (a log file, a batch "
                      "job); 0: a line every 256 steps")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  CLI::Option* resume = run_cmd->add_flag("--resume", ra.resume,
      "continue from RESULT.h5.checkpoint, which must exist and match (exit 2 otherwise)");
  CLI::Option* no_resume = run_cmd->add_flag("--no-resume", ra.no_resume,
      "start over (default: resume if a matching checkpoint exists)");
  resume->excludes(no_resume);
  run_cmd->add_flag("--force", ra.force,
      "replace an existing RESULT.h5 that is not a complete result of this scene (scene text and input hash)");
  run_cmd->add_option("--input-hash", ra.input_hash, "recorded in the result (the pipeline's input hash)");
  run_cmd->footer(run_footer);

  CLI::App* keys_cmd = app.add_subcommand("keys", "list every scene key with its unit, allowed range, default and meaning");

  bool column_legs = false;
  CLI::App* columns_cmd = app.add_subcommand("columns", "list the time-series columns of a result with unit and meaning (Markdown)");
  columns_cmd->add_flag("--legs", column_legs, "the per-leg table /legs instead of /timeseries");

  TableArgs ta;
  CLI::App* table_cmd = app.add_subcommand("table", "print a result's time-series (or per-leg) columns, 'name [unit]' headers");
  table_cmd->add_option("result", ta.file, "the result file")->required();
  table_cmd->add_option("columns", ta.columns, "the columns to print (default: every column)");
  table_cmd->add_flag("--legs", ta.legs, "the per-leg table /legs instead of /timeseries");
  table_cmd->add_flag("--csv", ta.csv, "comma-separated, 17 digits, no '#' (pandas.read_csv reads it)");

  std::string state_file;
  CLI::App* state_cmd = app.add_subcommand("state", "the final particles: x y z radius (m), tab-separated");
  state_cmd->add_option("result", state_file, "the result file")->required();

  std::vector<std::string> summary_files;
  CLI::App* summary_cmd = app.add_subcommand("summary", "one line per complete result: its last time-series row, steps and wall time");
  summary_cmd->add_option("results", summary_files, "result files")->required();

  RenderArgs rda;
  CLI::App* render_cmd = app.add_subcommand(
      "render", "draw a result's last frame to a PNG with ParaView: translucent spheres coloured by radius, the cell's "
                "outline, the contact network if the result has frames with contacts");
  render_cmd->add_option("result", rda.result, "the result file (RESULT.h5)")->required();
  render_cmd->add_option("--out", rda.png, "the picture (PNG)")->required();
  render_cmd->add_option("--title", rda.title, "the caption's first line (default: the result's name)");
  render_cmd->footer(
      "Runs reports/render/render.sh (installed in share/cyclic-triax/render): pvbatch on a virtual X display (Xvfb). It "
      "installs Debian's paraview, python3-paraview and xvfb if they are missing (apt-get, with sudo when not root). "
      "Exit status: 0 drawn, 1 the render failed, 2 bad input.");

  dem::PlotArgs pa;
  std::vector<std::string> plot_positional;
  CLI::App* plot_cmd = app.add_subcommand("plot", "draw one column of results against another with gnuplot, to a PNG or the terminal");
  plot_cmd->add_option("args", plot_positional, "RESULT.h5 X Y [MORE_RESULTS.h5 ...]: the first result, the columns of the x "
                       "and y axes (dem columns lists them), more results overlaid")->required()->expected(3, -1);
  plot_cmd->add_option("--out", pa.out, "the picture (PNG); without it the plot is drawn on the terminal");
  plot_cmd->add_option("--term", pa.term, "png or dumb (text on the terminal); default png with --out, else dumb")
      ->check(CLI::IsMember({"png", "dumb"}));
  plot_cmd->add_option("--title", pa.title, "the title (default: 'Y against X')");
  plot_cmd->add_flag("--legs", pa.legs, "columns of the per-leg table /legs instead of /timeseries");
  plot_cmd->footer("A partial result (RESULT.h5.partial) is drawn as far as it goes, its key saying so. Needs gnuplot "
                   "(Debian's gnuplot-nox). Exit status: 0 drawn, 1 gnuplot failed, 2 bad input.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help, the version, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments are bad input: exit 2, as always
  }
  if (*run_cmd) {
    if (ra.threads > 1) wait_passively(argv);
    const int rc = run(ra);  // the lock is let go and the partial result marked by now
    if (rc != 0 && stop_signal != 0) {
      std::signal(stop_signal, SIG_DFL);
      std::raise(stop_signal);
    }
    return rc;
  }
  if (*keys_cmd) { std::fputs(dem::scene_key_reference().c_str(), stdout); return 0; }
  if (*columns_cmd) {
    std::fputs(dem::columns_markdown(column_legs ? dem::leg_columns() : dem::series_columns()).c_str(), stdout);
    return 0;
  }
  if (*table_cmd) return table(ta);
  if (*state_cmd) return state(state_file);
  if (*summary_cmd) return summary(summary_files);
  if (*render_cmd) return render(rda);
  if (*plot_cmd) {
    pa.results = {plot_positional[0]};
    pa.results.insert(pa.results.end(), plot_positional.begin() + 3, plot_positional.end());
    pa.x = plot_positional[1], pa.y = plot_positional[2];
    return dem::plot(pa);
  }
  std::fputs(app.help().c_str(), stderr);  // no sub-command: what there is
  return 2;
}
