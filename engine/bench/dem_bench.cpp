// dem-bench: particle-steps per second of the step loop on the engine's own jammed packings.
//
// 1. Builds (once, cached in BENCH_DIR) two 8,000-sphere periodic packings, the paper's lattice
//    compressed isotropically to 100 kPa by the engine itself: one with mu = 0.5 and one with
//    mu = 0 (a frictionless packing unjams at the mu = 0.5 packing's volume, so each friction is
//    timed on a packing jammed with it; the mu = 0 one has more contacts).
// 2. Loads each and times the step loop at constant stress (the servo holding 100 kPa) on 1 and
//    on 2 threads, and as two runs at once with one thread each (the pipeline's -j 2), median of
//    several repetitions of the three ways interleaved, and checks that every way ends in the
//    same state bit for bit. Three cases: mu = 0.5 on its own packing, mu = 0 on its own, and
//    mu = 0.5 on the mu = 0 packing.
//    The last is the like-for-like comparison with LAMMPS (reports/bench/run_bench.sh): that
//    packing is in equilibrium without tangential forces, so starting without tangential springs,
//    as LAMMPS must (it reads bare positions), loses nothing and both codes time a jammed packing
//    with friction; the mu = 0.5 packing, read without its springs, unjams in LAMMPS's fixed box.
// Prints a table and writes BENCH_DIR/bench.json. STEPS = 0 builds the packings only (timing
// right after building them in the same process was up to 27 % slower, mu = 0.5, one thread).
// The Verlet skin of the timed runs is SKIN (default 2.5e-5 m, the skin of the study's cyclic
// tests; the packings are built with 2e-4 m).
//   dem-bench [BENCH_DIR] [STEPS] [REPETITIONS] [SKIN]
//
// Cost against size: `dem-bench size` times the mu = 0 packing tiled TILES x TILES x TILES
// (bench/tiling.hpp: 8,000 TILES^3 spheres, the same contacts and stress) with mu = 0.5 and
// mu = 0, on 1 and 2 threads (the four ways interleaved repetition by repetition, each run from
// the tiled packing again), and writes BENCH_DIR/size_<N>_<ORDER>.json with the medians, the
// spread and the process's peak memory (VmHWM; run one size per process). ORDER: `tiled` (copy by
// copy), `sorted` (one Morton curve over the whole packing, bench/tiling.hpp) or `random`.
//   dem-bench size BENCH_DIR TILES STEPS REPETITIONS [SKIN] [ORDER]
//
// The sheared cell's price: `dem-bench shear` times mu = 0.5 on the mu = 0 packing, one thread,
// with the axes at 100 kPa and the cell orthorhombic, against the same with the cell shearing
// (xy at 1/s: the sheared kernels), interleaved, per CPU second; writes BENCH_DIR/shear.json.
//   dem-bench shear BENCH_DIR STEPS REPETITIONS [SKIN]
//
// The contact laws' price: `dem-bench laws` runs the same test on the same sample with each law
// (run_scene, one thread, the laws interleaved repetition by repetition): linear (the scene's own
// law), linear with contact dashpots (0.05 of critical, no body damping, as the studies' dashpot
// reading), Hertz-Mindlin (E = 5 GPa, nu = 0.3: the dt is 0.17 of its critical step; local body
// damping, as viscous needs a constant stiffness) and linear with rolling resistance (mu_r = 0.1,
// k_r = 5e5 N/m), per CPU second of the run per step; each law's cost over linear's is taken
// repetition by repetition. Default: Test 1 on the shipped 1,000-sphere loose sample, cut to its
// first 2 cycles. Writes BENCH_DIR/laws.json.
//   dem-bench laws BENCH_DIR REPETITIONS [SCENE] [PATH]
//
#include <omp.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/tiling.hpp"
#include "config/scene_config.hpp"
#include "dynamics/kernel_simd.hpp"
#include "io/state_io.hpp"
#include "run/run_scene.hpp"
#include "version.hpp"

namespace {

const char* packing_scene = R"(
name: bench_packing
particles:
  lattice: {n: [20, 20, 20], spacing: 5.0e-3, seed: 7}
  grading: {diameters: [3.0e-3, 3.7e-3, 4.5e-3], percent_finer: [0, 50, 100]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: FRICTION}
damping: {form: viscous, translational: 0.05, rotational: 0.05}
numerics: {time_step: 1.0e-6, verlet_skin: 2.0e-4}
output: {interval: 10000}
stages:
  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, max_strain_rate: 2.0,
     hold: {stress_tolerance: 0.01, unbalanced_force_ratio: 1.0e-2, check_interval: 100, max_duration: 3.0}}
)";

std::string timing_scene(const std::string& packing, double friction, double skin, long steps) {
  return "name: bench\nparticles: {state: " + packing + "}\nmaterial: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: " +
         std::to_string(friction) +
         "}\ndamping: {form: viscous, translational: 0.05, rotational: 0.05}\n"
         "numerics: {time_step: 1.0e-6, verlet_skin: " + std::to_string(skin) + "}\n"
         "stages:\n  - {name: hold, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, max_strain_rate: 1.0,\n"
         "     hold: {stress_tolerance: 1.0e-9, unbalanced_force_ratio: 1.0e-12, check_interval: 1000000000, max_duration: " +
         std::to_string(static_cast<double>(steps) * 1e-6) + "}}\n";
}

struct Result {
  std::string packing;  // "mu05" or "mu0": the friction the packing was jammed with
  double friction;
  int threads;  // threads in one run; 0: two runs at once, one thread each
  double median_rate, min_rate, max_rate;  // particle-steps/s (two runs at once: both together)
  double contacts_per_particle;
  bool same_as_one_thread;
  double speedup;  // median rate / the 1-thread median of the same friction
};

// CPU time of the calling thread [s]: with one thread, the run's CPU time, which a busy machine
// inflates less than the wall time.
double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// One timed run: the scene's simulation, 200 warm-up steps (list built, caches filled), then
// `steps` timed steps at constant stress. Inside a parallel region every thread starts timing
// together.
struct Timed {
  double wall_s;
  std::vector<dem::Vec3> positions;  // at the end
  double contacts_per_particle;
  std::size_t rebuilds;  // Verlet list builds during the timed steps
  double cpu_s;          // CPU time of the calling thread in the timed steps (all of it with one thread)
};
Timed time_steps(dem::Simulation& sim, const dem::SceneConfig& scene, long steps) {
  dem::CellTargets targets;
  for (auto& t : targets) t = {dem::AxisTarget::Mode::Stress, 0, 1e5, 0};
  const dem::ServoSettings servo{scene.servo.gain, 1.0};
  for (int i = 0; i < 200; ++i) sim.step(targets, servo);
  const std::size_t builds = sim.verlet_list().builds();
#pragma omp barrier
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_s();
  for (long i = 0; i < steps; ++i) sim.step(targets, servo);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = thread_cpu_s() - cpu0;
  const auto n = static_cast<double>(sim.particles().size());
  return {wall, sim.particles().s, 2.0 * static_cast<double>(sim.sums().contacts) / n, sim.verlet_list().builds() - builds,
          cpu};
}
Timed time_run(const dem::SceneConfig& scene, long steps) {
  dem::Simulation sim = dem::build_simulation(scene);
  return time_steps(sim, scene, steps);
}

std::string packing_tag(double friction) { return friction > 0 ? "mu05" : "mu0"; }

// Builds the packing jammed with `friction` once (cached) and returns its path.
std::string packing_for(const std::string& dir, double friction) {
  namespace fs = std::filesystem;
  const std::string tag = packing_tag(friction);
  const std::string path = fs::absolute(dir + "/packing_" + tag + ".h5").string();
  if (fs::exists(path)) return path;
  std::string text = packing_scene;
  text.replace(text.find("FRICTION"), 8, friction > 0 ? "0.5" : "0.0");
  std::fprintf(stderr, "dem-bench: building the 8,000-sphere packing (mu = %g, 100 kPa) once -> %s\n", friction,
               path.c_str());
  const auto s = dem::run_scene(dem::scene_from_text(text, dir + "/bench_packing.yaml"), path);
  std::fprintf(stderr, "dem-bench: packing built in %lld steps, %.1f s\n", static_cast<long long>(s.steps), s.wall_time_s);
  return path;
}

// Writes `json` (nlohmann-json; build/bin/bench-report reads it back).
void write_json(const std::string& file, const nlohmann::ordered_json& json) {
  std::ofstream out(file);
  out << json.dump(2) << "\n";
  if (!out.flush()) throw std::runtime_error(file + ": cannot be written");
}

// Memory of this process from /proc/self/status [MB]: "VmRSS" (now) or "VmHWM" (peak); 0 if unknown.
double status_MB(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1)) / 1024.0;  // kB
  return 0;
}

// The simulation of `scene` (its material, damping, time step and skin) started from `state`, as
// build_simulation does for `particles: {state: ...}`.
dem::Simulation simulation_from(dem::SavedState state, const dem::SceneConfig& scene) {
  dem::Simulation sim(std::move(state.particles), state.cell, scene.material, scene.damping, scene.time_step_s,
                      scene.verlet_skin_m);
  sim.restore(0, state.rates, std::move(state.contacts), state.history);
  return sim;
}

// `dem-bench size`: see the top of the file.
int run_size(const std::string& dir, int tiles, long steps, int reps, double skin, const std::string& order) {
  if (order != "tiled" && order != "sorted" && order != "random") {
    std::fprintf(stderr, "dem-bench size: ORDER must be tiled, sorted or random, got '%s'\n", order.c_str());
    return 2;
  }
  const std::string packing = packing_for(dir, 0.0);
  const dem::SavedState base = dem::read_state(packing);
  const double baseline_MB = status_MB("VmRSS");  // the process with the 8,000-sphere packing loaded
  // The packing of this size in the chosen order, made again for every run so that the process
  // holds one copy only while a simulation runs.
  const auto make_state = [&] {
    dem::SavedState st = dem::bench::tile(base, tiles);
    if (order == "sorted") st = dem::bench::reordered(st, dem::bench::spatial_order(st.particles, st.cell));
    if (order == "random") {
      std::vector<std::uint32_t> perm(st.particles.size());
      for (std::size_t k = 0; k < perm.size(); ++k) perm[k] = static_cast<std::uint32_t>(k);
      std::shuffle(perm.begin(), perm.end(), std::mt19937_64(7));
      st = dem::bench::reordered(st, perm);
    }
    return st;
  };
  const auto n = static_cast<double>(base.particles.size()) * tiles * tiles * tiles;
  // BENCH_FRICTIONS and BENCH_THREADS (space-separated) time fewer ways, e.g. under perf.
  const auto list_from_env = [](const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    std::istringstream in(v && *v ? v : fallback);
    std::vector<double> out;
    for (double x; in >> x;) out.push_back(x);
    return out;
  };
  const std::vector<double> frictions = list_from_env("BENCH_FRICTIONS", "0.5 0");
  const std::vector<double> threads = list_from_env("BENCH_THREADS", "1 2");
  struct Way {
    double friction;
    int threads;
    std::vector<double> rates, cpu_rates;
    std::vector<double> setup_s;  // making the packing and the simulation (the first list is built in the warm-up)
    double z = 0;
    std::size_t rebuilds = 0;  // Verlet list builds in the timed steps, summed over repetitions
    bool same = true;
  };
  std::vector<Way> ways;
  for (double mu : frictions)
    for (double t : threads) ways.push_back({mu, static_cast<int>(t), {}, {}, {}});
  std::vector<dem::Vec3> reference[2];  // the end positions of each friction's first run
  for (int r = 0; r < reps; ++r)
    for (Way& w : ways) {
      const dem::SceneConfig scene =
          dem::scene_from_text(timing_scene(packing, w.friction, skin, 1000000000L), dir + "/bench.yaml");
      omp_set_num_threads(w.threads);
      const auto t0 = std::chrono::steady_clock::now();
      dem::Simulation sim = simulation_from(make_state(), scene);
      w.setup_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      const Timed t = time_steps(sim, scene, steps);
      w.rebuilds += t.rebuilds;
      w.rates.push_back(n * static_cast<double>(steps) / t.wall_s);
      w.cpu_rates.push_back(n * static_cast<double>(steps) / t.cpu_s);
      w.z = t.contacts_per_particle;
      auto& ref = reference[w.friction > 0 ? 0 : 1];
      if (ref.empty()) ref = t.positions;
      w.same = w.same && t.positions == ref;
    }
  const double peak_MB = status_MB("VmHWM");
  std::printf("dem-bench size: %.0f spheres (8,000 x %d^3), %s order, %ld steps x %d repetitions, skin %g m\n", n, tiles,
              order.c_str(), steps, reps, skin);
  std::printf("%-9s %-8s %-22s %-24s %-14s %-8s %s\n", "friction", "threads", "particle-steps/s (med)", "min .. max",
              "per CPU-s (1)", "2Nc/Np", "same bits as 1 thread");
  // reports/bench/run_bench.sh reads it with build/bin/bench-report.
  nlohmann::ordered_json json = {{"code", "cyclic-triax dem"},
                                 {"version", dem::software_version},
                                 {"particles", static_cast<long long>(n)},
                                 {"tiles", tiles},
                                 {"order", order},
                                 {"steps", steps},
                                 {"warmup_steps", 200},
                                 {"repetitions", reps},
                                 {"verlet_skin_m", skin},
                                 {"vector_lanes", dem::simd_width()},
                                 {"baseline_rss_MB", baseline_MB},
                                 {"peak_rss_MB", peak_MB},
                                 {"peak_bytes_per_particle", (peak_MB - baseline_MB) * 1048576.0 / n},
                                 {"runs", nlohmann::ordered_json::array()}};
  bool all_same = true;
  for (Way& w : ways) {
    std::sort(w.rates.begin(), w.rates.end());
    std::sort(w.setup_s.begin(), w.setup_s.end());
    std::sort(w.cpu_rates.begin(), w.cpu_rates.end());
    const double median = w.rates[w.rates.size() / 2];
    std::printf("%-9.2f %-8d %-22.3e %.3e .. %.3e  %-14.3e %-8.2f %s\n", w.friction, w.threads, median, w.rates.front(),
                w.rates.back(), w.cpu_rates[w.cpu_rates.size() / 2], w.z, w.same ? "yes" : "NO");
    json["runs"].push_back({{"friction", w.friction},
                            {"threads", w.threads},
                            {"particle_steps_per_s_median", median},
                            {"min", w.rates.front()},
                            {"max", w.rates.back()},
                            {"cpu_rate_median", w.cpu_rates[w.cpu_rates.size() / 2]},
                            {"setup_s_median", w.setup_s[w.setup_s.size() / 2]},
                            {"coordination_number", w.z},
                            {"timed_rebuilds", w.rebuilds},
                            {"same_bits_as_1_thread", w.same}});
    all_same = all_same && w.same;
  }
  write_json(dir + "/size_" + std::to_string(static_cast<long long>(n)) + "_" + order + ".json", json);
  std::printf("peak memory (VmHWM) %.1f MB, %.1f MB before tiling: %.0f bytes per particle\n", peak_MB, baseline_MB,
              (peak_MB - baseline_MB) * 1048576.0 / n);
  return all_same ? 0 : 1;
}


// `dem-bench shear`: see the top of the file.
int run_shear(const std::string& dir, long steps, int reps, double skin) {
  const std::string packing = packing_for(dir, 0.0);
  const dem::SceneConfig scene = dem::scene_from_text(timing_scene(packing, 0.5, skin, 1000000000L), dir + "/bench.yaml");
  const dem::SavedState base = dem::read_state(packing);
  const auto n = static_cast<double>(base.particles.size());
  omp_set_num_threads(1);
  // Both ways hold the axes at 100 kPa with the scene's servo; the sheared one also shears xy at
  // 1/s, so its cell tilts from the first step and every step takes the sheared kernels.
  dem::CellControl orthorhombic;
  for (std::size_t k = 0; k < 3; ++k) orthorhombic.component[k] = {dem::AxisTarget::Mode::Stress, 0, 1e5, 0};
  dem::CellControl sheared = orthorhombic;
  sheared.component[3] = {dem::AxisTarget::Mode::StrainRate, 1.0, 0, 0};
  struct Way {
    const char* name;
    dem::CellControl control;
    std::vector<double> rates;
    std::size_t rebuilds = 0;
  };
  std::vector<Way> ways{{"orthorhombic", orthorhombic, {}}, {"sheared", sheared, {}}};
  const dem::ServoSettings servo{scene.servo.gain, 1.0};
  for (int r = 0; r < reps; ++r)
    for (Way& w : ways) {
      dem::Simulation sim = simulation_from(base, scene);
      for (int i = 0; i < 200; ++i) sim.step(w.control, servo);
      const std::size_t builds = sim.verlet_list().builds();
      const double cpu0 = thread_cpu_s();
      for (long i = 0; i < steps; ++i) sim.step(w.control, servo);
      w.rates.push_back(n * static_cast<double>(steps) / (thread_cpu_s() - cpu0));
      w.rebuilds += sim.verlet_list().builds() - builds;
    }
  std::printf("dem-bench shear: %.0f spheres, mu = 0.5, one thread, %ld steps x %d repetitions, skin %g m\n", n, steps, reps, skin);
  nlohmann::ordered_json json = {{"code", "cyclic-triax dem"},
                                 {"version", dem::software_version},
                                 {"particles", static_cast<long long>(n)},
                                 {"friction", 0.5},
                                 {"steps", steps},
                                 {"repetitions", reps},
                                 {"verlet_skin_m", skin},
                                 {"runs", nlohmann::ordered_json::array()}};
  for (Way& w : ways) {
    std::sort(w.rates.begin(), w.rates.end());
    const double median = w.rates[w.rates.size() / 2];
    std::printf("%-13s %.3e particle-steps per CPU-s (median; %.3e .. %.3e), %zu list builds\n", w.name, median,
                w.rates.front(), w.rates.back(), w.rebuilds);
    json["runs"].push_back(
        {{"cell", w.name}, {"cpu_rate_median", median}, {"min", w.rates.front()}, {"max", w.rates.back()}, {"timed_rebuilds", w.rebuilds}});
  }
  write_json(dir + "/shear.json", json);
  return 0;
}


// `dem-bench laws`: see the top of the file.
int run_laws(const std::string& dir, int reps, const std::string& scene_file, const std::string& path) {
  using Overrides = std::vector<std::pair<std::string, std::string>>;
  struct Law {
    const char* name;
    Overrides set;
    std::vector<double> cpu_per_step, ratio;  // [s]; over linear's in the same repetition
    std::int64_t steps = 0;
  };
  std::vector<Law> laws{
      {"linear", {}, {}, {}},
      {"linear, contact dashpots",
       {{"material.contact_damping", "0.05"}, {"damping.translational", "0"}, {"damping.rotational", "0"}},
       {},
       {}},
      {"Hertz-Mindlin",
       {{"material", "{density: 2650, law: hertz_mindlin, young_modulus: 5.0e9, poisson_ratio: 0.3, friction: 0.5}"},
        {"damping", "{form: local, translational: 0.05, rotational: 0.05}"}},
       {},
       {}},
      {"linear, rolling resistance", {{"material.rolling_friction", "0.1"}, {"material.rolling_stiffness", "5.0e5"}}, {}, {}},
  };
  omp_set_num_threads(1);
  const std::string out = dir + "/laws_run.h5";
  for (int r = 0; r < reps; ++r)
    for (Law& law : laws) {
      Overrides set = law.set;
      set.emplace_back("stages[0].path", path);
      const dem::SceneConfig scene = dem::load_scene(scene_file, set);
      const double cpu0 = thread_cpu_s();
      const dem::RunSummary run = dem::run_scene(scene, out, {}, "", dem::Resume::Never);
      law.cpu_per_step.push_back((thread_cpu_s() - cpu0) / static_cast<double>(run.steps));
      law.ratio.push_back(law.cpu_per_step.back() / laws[0].cpu_per_step.back());
      law.steps = run.steps;
    }
  std::filesystem::remove(out);
  std::printf("dem-bench laws: %s, path %s, one thread, %d repetitions\n", scene_file.c_str(), path.c_str(), reps);
  std::printf("%-28s %-8s %-30s %s\n", "law", "steps", "CPU us per step (median; min .. max)", "over linear (median; min .. max)");
  nlohmann::ordered_json json = {{"code", "cyclic-triax dem"},
                                 {"version", dem::software_version},
                                 {"vector_lanes", dem::simd_width()},
                                 {"scene", scene_file},
                                 {"path", path},
                                 {"repetitions", reps},
                                 {"runs", nlohmann::ordered_json::array()}};
  for (Law& law : laws) {
    std::sort(law.cpu_per_step.begin(), law.cpu_per_step.end());
    std::sort(law.ratio.begin(), law.ratio.end());
    const double median = law.cpu_per_step[law.cpu_per_step.size() / 2], ratio = law.ratio[law.ratio.size() / 2];
    std::printf("%-28s %-8lld %8.3f (%.3f .. %.3f)          %.3f (%.3f .. %.3f)\n", law.name, static_cast<long long>(law.steps),
                1e6 * median, 1e6 * law.cpu_per_step.front(), 1e6 * law.cpu_per_step.back(), ratio, law.ratio.front(),
                law.ratio.back());
    std::string keys;
    for (const auto& [key, value] : law.set) keys += (keys.empty() ? "" : ", ") + key + ": " + value;
    json["runs"].push_back({{"law", law.name},
                            {"set", keys},
                            {"steps", law.steps},
                            {"cpu_s_per_step_median", median},
                            {"min", law.cpu_per_step.front()},
                            {"max", law.cpu_per_step.back()},
                            {"over_linear_median", ratio},
                            {"over_linear_min", law.ratio.front()},
                            {"over_linear_max", law.ratio.back()}});
  }
  write_json(dir + "/laws.json", json);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dem-bench: particle-steps per second of the step loop on the engine's own jammed 8,000-sphere packings "
               "(built once, cached in BENCH_DIR), on 1 and 2 threads and as two runs at once; writes BENCH_DIR/bench.json"};
  app.name("dem-bench");
  std::string dir = "build/bench", order = "tiled";
  long steps = 4000;
  int reps = 5, tiles = 0;
  double skin = 2.5e-5;  // the study's shearing scenes' skin
  app.add_option("BENCH_DIR", dir, "where the packings are cached and bench.json goes")->capture_default_str();
  app.add_option("STEPS", steps, "timed steps of each repetition; 0 builds the packings only")->capture_default_str();
  app.add_option("REPETITIONS", reps, "repetitions (the median is reported)")->capture_default_str();
  app.add_option("SKIN", skin, "the Verlet skin of the timed runs [m]")->capture_default_str();
  const auto timing = [&](CLI::App* cmd) {
    cmd->add_option("BENCH_DIR", dir, "where the packings are cached and the JSON goes")->required();
    cmd->add_option("STEPS", steps, "timed steps of each repetition")->required();
    cmd->add_option("REPETITIONS", reps, "repetitions (the median is reported)")->required();
  };
  CLI::App* size = app.add_subcommand("size", "cost against size: the mu = 0 packing tiled TILES^3 times, mu = 0.5 and 0 on 1 and "
                                              "2 threads; writes BENCH_DIR/size_<N>_<ORDER>.json");
  size->add_option("BENCH_DIR", dir, "where the packings are cached and the JSON goes")->required();
  size->add_option("TILES", tiles, "copies along each axis (8,000 TILES^3 spheres)")->required();
  size->add_option("STEPS", steps, "timed steps of each repetition")->required();
  size->add_option("REPETITIONS", reps, "repetitions (the median is reported)")->required();
  size->add_option("SKIN", skin, "the Verlet skin of the timed runs [m]")->capture_default_str();
  size->add_option("ORDER", order, "the particles' order: tiled, sorted (one Morton curve) or random")
      ->check(CLI::IsMember({"tiled", "sorted", "random"}))
      ->capture_default_str();
  CLI::App* shear = app.add_subcommand("shear", "the sheared cell's price: mu = 0.5 on the mu = 0 packing, one thread, orthorhombic "
                                                "against shearing (xy at 1/s); writes BENCH_DIR/shear.json");
  timing(shear);
  shear->add_option("SKIN", skin, "the Verlet skin of the timed runs [m]")->capture_default_str();
  std::string scene_file = "scenes/tests/test1.yaml", path = "[TC1, {repeat: 2, path: [TC2, TC3, TC1]}]";
  CLI::App* laws = app.add_subcommand("laws", "the contact laws' price: the same test on the same sample with each law (linear, "
                                              "contact dashpots, Hertz-Mindlin, rolling resistance), one thread, per CPU second "
                                              "per step; writes BENCH_DIR/laws.json");
  laws->add_option("BENCH_DIR", dir, "where laws.json goes")->required();
  laws->add_option("REPETITIONS", reps, "repetitions (the median is reported)")->required()->check(CLI::PositiveNumber);
  laws->add_option("SCENE", scene_file, "the test's scene")->capture_default_str();
  laws->add_option("PATH", path, "its stress path (the first stage's `path`)")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2
  }
  if (*laws) {
    std::filesystem::create_directories(dir);
    try {
      return run_laws(dir, reps, scene_file, path);
    } catch (const std::exception& e) {  // a scene that does not load or a run that fails
      std::fprintf(stderr, "dem-bench laws: %s\n", e.what());
      return 1;
    }
  }
  if (*shear) {
    std::filesystem::create_directories(dir);
    return run_shear(dir, steps, reps, skin);
  }
  if (*size) {
    std::filesystem::create_directories(dir);
    return run_size(dir, tiles, steps, reps, skin, order);
  }
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  if (steps == 0) {  // build the packings only: timing in a fresh process gives steadier numbers
    for (double mu : {0.5, 0.0}) packing_for(dir, mu);
    return 0;
  }
  std::vector<Result> results;
  const std::pair<double, double> cases[] = {{0.5, 0.5}, {0.0, 0.0}, {0.0, 0.5}};  // (packing's friction, friction)
  for (const auto& [packing_mu, mu] : cases) {
    const std::string packing = packing_for(dir, packing_mu);
    const dem::SceneConfig scene = dem::scene_from_text(timing_scene(packing, mu, skin, 1000000000L), dir + "/bench.yaml");
    std::vector<dem::Vec3> one_thread_positions;
    const auto particle_steps = static_cast<double>(steps) * 8000.0;
    // The three ways, interleaved repetition by repetition (so that a slow spell of the machine
    // falls on all of them, not on the repetitions of one): 1 and 2 threads in one run, then two
    // runs at once with one thread each (the pipeline's -j 2).
    const int ways[] = {1, 2, 0};
    std::vector<double> rates[3];
    double z[3] = {0, 0, 0};
    bool same[3] = {true, true, true};
    for (int r = 0; r < reps; ++r)
      for (int w = 0; w < 3; ++w) {
        const int threads = ways[w];
        std::vector<Timed> runs(threads > 0 ? 1 : 2);
        if (threads > 0) {
          omp_set_num_threads(threads);
          runs[0] = time_run(scene, steps);
        } else {
#pragma omp parallel num_threads(2)
          runs[static_cast<std::size_t>(omp_get_thread_num())] = time_run(scene, steps);  // nested regions are inactive
        }
        if (threads == 1 && r == 0) one_thread_positions = runs[0].positions;
        double wall = 0;
        for (const Timed& t : runs) {
          wall = std::max(wall, t.wall_s);
          same[w] = same[w] && t.positions == one_thread_positions;
        }
        rates[w].push_back(static_cast<double>(runs.size()) * particle_steps / wall);
        z[w] = runs[0].contacts_per_particle;
      }
    double one_thread_rate = 0;
    for (int w = 0; w < 3; ++w) {
      std::sort(rates[w].begin(), rates[w].end());
      const double median = rates[w][rates[w].size() / 2];
      if (ways[w] == 1) one_thread_rate = median;
      results.push_back({packing_tag(packing_mu), mu, ways[w], median, rates[w].front(), rates[w].back(), z[w], same[w],
                         median / one_thread_rate});
    }
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  std::printf("dem-bench %s: 8,000 spheres, dt = 1e-6 s, skin %g m, %ld steps x %d repetitions, vector loops %d lanes\n",
              dem::software_version, skin, steps, reps, dem::simd_width());
  std::printf("%-8s %-9s %-8s %-22s %-24s %-8s %-10s %s\n", "packing", "friction", "threads", "particle-steps/s (med)", "min .. max",
              "2Nc/Np", "speed-up", "same bits as 1 thread");
  for (const auto& r : results) {
    const bool two_runs = r.threads == 0;
    std::printf("%-8s %-9.2f %-8s %-22.3e %.3e .. %.3e  ", r.packing.c_str(), r.friction, two_runs ? "2 runs" : std::to_string(r.threads).c_str(),
                r.median_rate, r.min_rate, r.max_rate);
    if (two_runs)
      std::printf("%-8s ", "");
    else
      std::printf("%-8.2f ", r.contacts_per_particle);
    std::printf("%-10.2f %s\n", r.speedup, r.same_as_one_thread ? "yes" : "NO");
  }
  std::printf("peak memory (max RSS): %.1f MB\n", peak_mb);
  // One list for the runs of one process, one for two runs at once (their rate is both runs').
  nlohmann::ordered_json json = {{"code", "cyclic-triax dem"},
                                 {"version", dem::software_version},
                                 {"vector_lanes", dem::simd_width()},
                                 {"particles", 8000},
                                 {"verlet_skin_m", skin},
                                 {"steps", steps},
                                 {"repetitions", reps},
                                 {"peak_rss_MB", peak_mb},
                                 {"runs", nlohmann::ordered_json::array()},
                                 {"two_runs_at_once", nlohmann::ordered_json::array()}};
  for (const auto& r : results)
    if (r.threads > 0)
      json["runs"].push_back({{"packing", r.packing},
                              {"friction", r.friction},
                              {"threads", r.threads},
                              {"particle_steps_per_s_median", r.median_rate},
                              {"min", r.min_rate},
                              {"max", r.max_rate},
                              {"coordination_number", r.contacts_per_particle},
                              {"same_bits_as_1_thread", r.same_as_one_thread}});
    else
      json["two_runs_at_once"].push_back({{"packing", r.packing},
                                          {"friction", r.friction},
                                          {"runs", 2},
                                          {"threads_per_run", 1},
                                          {"total_particle_steps_per_s_median", r.median_rate},
                                          {"min", r.min_rate},
                                          {"max", r.max_rate},
                                          {"same_bits_as_1_thread", r.same_as_one_thread}});
  write_json(dir + "/bench.json", json);
  for (const auto& r : results)
    if (!r.same_as_one_thread) return 1;
  return 0;
}
