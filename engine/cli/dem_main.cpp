// dem: the command-line front end of the engine.
//   dem run SCENE.yaml --out RESULT.h5     run a scene, write its result
//   dem keys                               the reference of every scene key
//   dem --help
#include <fcntl.h>
#include <omp.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
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
#include "io/hdf5.hpp"
#include "io/result_writer.hpp"  // describe_failure
#include "io/state_io.hpp"
#include "io/file_lock.hpp"
#include "run/output_path.hpp"
#include "run/run_scene.hpp"
#include "source_hash.hpp"
#include "version.hpp"

namespace {

const char* usage =
    "usage:\n"
    "  dem run SCENE.yaml --out RESULT.h5 [--set KEY=VALUE ...] [--threads N] [--quiet]\n"
    "                                   [--resume | --no-resume] [--force]\n"
    "                                                 run a scene and write its result (HDF5); --set\n"
    "                                                 overrides a key, e.g. --set particles.lattice.seed=2;\n"
    "                                                 --threads: threads inside the run (default 1; the\n"
    "                                                 result is bit for bit the same for any count);\n"
    "                                                 --input-hash H is recorded in the result (pipeline);\n"
    "                                                 --resume: continue from RESULT.h5.checkpoint, which\n"
    "                                                 must exist and match (exit 2 otherwise); --no-resume:\n"
    "                                                 start over; default: resume if a matching checkpoint\n"
    "                                                 exists (output.checkpoint_interval/_wall_time);\n"
    "                                                 --force: replace an existing RESULT.h5 that is not a\n"
    "                                                 complete result of this scene (scene text and input\n"
    "                                                 hash); without it such a file is refused (exit 2)\n"
    "  dem keys                                       list every scene key with unit, range, default\n"
    "  dem table RESULT.h5 [--legs] [COLUMN ...]      print time-series (or per-leg) columns as\n"
    "                                                 tab-separated text\n"
    "  dem state RESULT.h5                            the final particles: x y z radius (m), tab-separated\n"
    "  dem summary RESULT.h5 ...                      one line per result: its last time-series row,\n"
    "                                                 steps and wall time (tab-separated)\n"
    "  dem --version | --source-hash | --help\n"
    "\n"
    "The result is written to RESULT.h5.partial while the run goes on and renamed to RESULT.h5\n"
    "(status 'complete') only when it finishes and is on the disk; RESULT.h5.checkpoint holds the\n"
    "newest checkpoint until then. --out may not end in .partial, .checkpoint, .lock, .outcome,\n"
    ".tmp or .xdmf, nor name a non-regular file (device, folder, FIFO, link) or a file the scene\n"
    "reads. Exit status: 0 success, 1 run failed (the reason on stderr and in the status of\n"
    "RESULT.h5.partial), 2 bad input (nothing written).\n";

// The terminal's progress line of a run (`dem run` on a terminal, without --quiet): at most every
// 0.5 s, with the time left in the stage from its progress so far. Warnings and notes start on a
// line of their own.
class ProgressLine {
 public:
  void draw(const dem::RunProgress& p) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    drawn_ = true;
    std::fprintf(stderr, "\r\033[K[%s %d/%d '%s'] step %lld, t = %.4g s", p.scene.c_str(), p.stage + 1, p.stages,
                 p.stage_name.c_str(), static_cast<long long>(p.step), p.time_s);
    if (p.stage_fraction > 0) {
      if (stage_seen_ != p.stage) stage_seen_ = p.stage, stage_start_s_ = p.elapsed_s;
      const double stage_elapsed = p.elapsed_s - stage_start_s_;
      std::fprintf(stderr, ", %.0f %% of stage, ETA %.0f s", 100 * p.stage_fraction,
                   stage_elapsed * (1 - p.stage_fraction) / p.stage_fraction);
    }
    if (!p.status.empty()) std::fprintf(stderr, ", %s", p.status.c_str());
    std::fflush(stderr);
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
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  bool drawn_ = false;
  int stage_seen_ = -1;       // for the ETA: the stage being timed and when it started
  double stage_start_s_ = 0;  // [s since the run started]
};

int run(int argc, char** argv) {
  std::string scene_file, out;
  bool quiet = false;
  std::vector<std::pair<std::string, std::string>> overrides;
  std::string input_hash;
  int threads = 1;
  bool force = false;
  dem::Resume resume = dem::Resume::IfValid;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--quiet") quiet = true;
    else if (a == "--resume") resume = dem::Resume::Always;
    else if (a == "--no-resume") resume = dem::Resume::Never;
    else if (a == "--force") force = true;
    else if (a == "--input-hash" && i + 1 < argc) input_hash = argv[++i];
    else if (a == "--threads" && i + 1 < argc) {
      const std::string t = argv[++i];
      char* end = nullptr;
      const long n = std::strtol(t.c_str(), &end, 10);
      if (end == t.c_str() || *end != '\0' || n < 1 || n > 256) {
        std::fprintf(stderr, "dem run: --threads must be an integer in [1, 256], got '%s'\n", t.c_str());
        return 2;
      }
      threads = static_cast<int>(n);
    }
    else if (a == "--set" && i + 1 < argc) {
      const std::string kv = argv[++i];
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) { std::fprintf(stderr, "dem run: --set needs KEY=VALUE, got '%s'\n", kv.c_str()); return 2; }
      overrides.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    }
    else if (!a.empty() && a[0] == '-') { std::fprintf(stderr, "dem run: unknown option '%s'\n%s", a.c_str(), usage); return 2; }
    else if (scene_file.empty()) scene_file = a;
    else { std::fprintf(stderr, "dem run: more than one scene given ('%s')\n", a.c_str()); return 2; }
  }
  if (scene_file.empty() || out.empty()) {
    std::fprintf(stderr, "dem run: need a scene file and --out RESULT.h5\n%s", usage);
    return 2;
  }
  // Where the result goes (run/output_path.hpp): its name and folder first, then what the scene
  // reads, then, under the lock, what is there now.
  const auto refused = [&](const std::exception& e) {
    std::fprintf(stderr, "error: %s; nothing was run\n", e.what());
    return 2;
  };
  try {
    dem::check_output_name(out);
  } catch (const dem::OutputPathError& e) {
    return refused(e);
  }
  dem::SceneConfig scene;
  try {
    scene = dem::load_scene(scene_file, overrides);
    dem::check_output_not_input(out, scene);
  } catch (const dem::OutputPathError& e) {
    return refused(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  // One writer per result: a second `dem run` to the same --out refuses instead of writing into
  // the same partial file and checkpoint. The lock goes with the process, however it ends; names
  // another result's files use (.partial, ...) are refused above, so it covers the whole family.
  // The lock file is removed however the run ends (refused, failed or complete): io/file_lock.hpp.
  const dem::FileLock lock(out + ".lock");
  if (!lock.held()) {
    std::fprintf(stderr, "error: --out %s: %s; nothing was run\n", out.c_str(),
                 (lock.error().empty() ? "another dem run is writing this result (it holds " + out + ".lock)" : lock.error()).c_str());
    return 2;
  }
  try {
    dem::check_output_replaceable(out, scene, input_hash, force);
  } catch (const dem::OutputPathError& e) {
    return refused(e);
  }
  omp_set_num_threads(threads);
  try {
    ProgressLine line;
    dem::RunObserver observer;
    if (!quiet && isatty(STDERR_FILENO)) observer.progress = [&](const dem::RunProgress& p) { line.draw(p); };
    observer.warning = [&](const std::string& w) {
      line.new_line();
      std::fprintf(stderr, "warning: %s\n", w.c_str());
    };
    observer.note = [&](const std::string& n) {
      line.new_line();
      std::fprintf(stderr, "%s\n", n.c_str());
    };
    dem::RunSummary s;
    try {
      s = dem::run_scene(scene, out, observer, input_hash, resume);
    } catch (...) {
      line.new_line();
      throw;
    }
    line.clear();
    std::fprintf(stderr, "%s: %lld steps in %.1f s (%.3g steps/s) -> %s\n", scene.name.c_str(),
                 static_cast<long long>(s.steps), s.wall_time_s, static_cast<double>(s.steps) / s.wall_time_s, out.c_str());
    return 0;
  } catch (const dem::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s: %s\n", scene_file.c_str(), dem::describe_failure(e).c_str());
    if (std::filesystem::exists(out + ".partial")) std::fprintf(stderr, "(partial result kept in %s.partial)\n", out.c_str());
    return 1;
  }
}

// Prints time-series columns of a result (all of them if none are named) as tab-separated text.
int table(int argc, char** argv) {
  if (argc < 3) { std::fprintf(stderr, "dem table: need a result file\n%s", usage); return 2; }
  try {
    dem::h5::Handle f = dem::h5::open_file_read(argv[2]);
    const bool legs = argc > 3 && std::string(argv[3]) == "--legs";
    dem::h5::Handle g = dem::h5::open_group(f, legs ? "legs" : "timeseries");
    std::vector<std::string> names;
    for (int i = legs ? 4 : 3; i < argc; ++i) names.push_back(argv[i]);
    if (names.empty())
      for (const auto& c : legs ? dem::leg_columns() : dem::series_columns()) names.push_back(c.name);
    std::vector<std::vector<double>> cols;
    std::size_t width = 0;
    for (const auto& n : names) {
      if (!dem::h5::exists(g, n)) { std::fprintf(stderr, "dem table: %s has no column '%s'\n", argv[2], n.c_str()); return 2; }
      cols.push_back(dem::h5::read<double>(g, n, width));
    }
    std::printf("#");
    for (const auto& n : names) std::printf(" %s", n.c_str());
    std::printf("\n");
    for (std::size_t r = 0; r < cols[0].size(); ++r) {
      for (std::size_t c = 0; c < cols.size(); ++c) std::printf(c ? "\t%.10g" : "%.10g", cols[c][r]);
      std::printf("\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}

// The final particles of a result: real position and radius, one tab-separated line each.
int state(int argc, char** argv) {
  if (argc < 3) { std::fprintf(stderr, "dem state: need a result file\n%s", usage); return 2; }
  try {
    const dem::SavedState st = dem::read_state(argv[2]);
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

// One tab-separated line per complete result: file, wall time, then the last time-series row.
int summary(int argc, char** argv) {
  if (argc < 3) { std::fprintf(stderr, "dem summary: need result files\n%s", usage); return 2; }
  std::printf("# file\twall_time_s");
  for (const auto& c : dem::series_columns()) std::printf("\t%s", c.name.c_str());
  std::printf("\n");
  int status = 0;
  for (int i = 2; i < argc; ++i) {
    try {
      dem::h5::Handle f = dem::h5::open_file_read(argv[i]);
      if (dem::h5::get_string_attribute(f, "status") != "complete") throw std::runtime_error("not a complete result");
      dem::h5::Handle g = dem::h5::open_group(f, "timeseries");
      std::printf("%s\t%.6g", argv[i], dem::h5::get_double_attribute(f, "wall_time_s"));
      for (const auto& c : dem::series_columns()) {  // columns a result's schema lacks print as nan
        std::size_t width = 0;
        const auto v = dem::h5::exists(g, c.name) ? dem::h5::read<double>(g, c.name, width) : std::vector<double>{};
        std::printf("\t%.10g", v.empty() ? std::nan("") : v.back());
      }
      std::printf("\n");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "dem summary: %s: %s\n", argv[i], e.what());
      status = 1;
    }
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // HDF5 must not close files itself at exit: one whose close failed (a full disk) would crash
  // the library there (HDF5 1.10), after the error was reported. Every file dem opens is closed
  // by its handle before main returns.
  H5dont_atexit();
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(usage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  if (cmd == "--version") {
    std::printf("dem %s (result schema %d, engine source %s)\n", dem::software_version, dem::schema_version,
                dem::engine_source_hash);
    return 0;
  }
  if (cmd == "--source-hash") {  // what the pipeline keys its reuse of results on
    std::printf("%s schema %d\n", dem::engine_source_hash, dem::schema_version);
    return 0;
  }
  if (cmd == "keys") { std::fputs(dem::scene_key_reference().c_str(), stdout); return 0; }
  if (cmd == "run") return run(argc, argv);
  if (cmd == "table") return table(argc, argv);
  if (cmd == "summary") return summary(argc, argv);
  if (cmd == "state") return state(argc, argv);
  std::fprintf(stderr, "dem: unknown command '%s'\n%s", cmd.c_str(), usage);
  return 2;
}
