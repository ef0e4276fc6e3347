// dem-bench: particle-steps per second of the step loop on the engine's own jammed packings.
//
// 1. Builds (once, cached in BENCH_DIR) two 8,000-sphere periodic packings, the SPEC lattice
//    compressed isotropically to 100 kPa by the engine itself: one with mu = 0.5 and one with
//    mu = 0 (a frictionless packing unjams at the mu = 0.5 packing's volume, so each friction is
//    timed on a packing jammed with it; the mu = 0 one has more contacts).
// 2. Loads each and times the step loop at constant stress (the servo holding 100 kPa) on 1 and
//    on 2 threads, and as two runs at once with one thread each (the pipeline's -j 2), median of
//    several repetitions, and checks that every way ends in the same state bit for bit.
// Prints a table and writes BENCH_DIR/bench.json. STEPS = 0 builds the packings only (timing
// right after building them in the same process was up to 27 % slower, mu = 0.5, one thread).
//   dem-bench [BENCH_DIR] [STEPS] [REPETITIONS]
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "dynamics/kernel_simd.hpp"
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

std::string timing_scene(const std::string& packing, double friction, long steps) {
  return "name: bench\nparticles: {state: " + packing + "}\nmaterial: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: " +
         std::to_string(friction) +
         "}\ndamping: {form: viscous, translational: 0.05, rotational: 0.05}\n"
         "numerics: {time_step: 1.0e-6, verlet_skin: 2.0e-4}\n"
         "stages:\n  - {name: hold, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, max_strain_rate: 1.0,\n"
         "     hold: {stress_tolerance: 1.0e-9, unbalanced_force_ratio: 1.0e-12, check_interval: 1000000000, max_duration: " +
         std::to_string(static_cast<double>(steps) * 1e-6) + "}}\n";
}

struct Result {
  double friction;
  int threads;
  double median_rate, min_rate, max_rate;
  double contacts_per_particle;
  bool same_as_one_thread;
  double speedup;  // median rate / the 1-thread median of the same friction
};

struct TwoRuns {  // two runs at once, one thread each
  double friction;
  double median_rate, min_rate, max_rate;  // both runs together
  bool same_as_one_thread;
  double speedup;  // over the 1-thread median of one run
};

// Builds the packing for `friction` once (cached) and returns its path.
std::string packing_for(const std::string& dir, double friction) {
  namespace fs = std::filesystem;
  const std::string tag = friction > 0 ? "mu05" : "mu0";
  const std::string path = fs::absolute(dir + "/packing_" + tag + ".h5").string();
  if (fs::exists(path)) return path;
  std::string text = packing_scene;
  text.replace(text.find("FRICTION"), 8, friction > 0 ? "0.5" : "0.0");
  std::fprintf(stderr, "dem-bench: building the 8,000-sphere packing (mu = %g, 100 kPa) once -> %s\n", friction,
               path.c_str());
  const auto s = dem::run_scene(dem::scene_from_text(text, dir + "/bench_packing.yaml"), path, false);
  std::fprintf(stderr, "dem-bench: packing built in %lld steps, %.1f s\n", static_cast<long long>(s.steps), s.wall_time_s);
  return path;
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const std::string dir = argc > 1 ? argv[1] : "build/bench";
  const long steps = argc > 2 ? std::stol(argv[2]) : 4000;
  const int reps = argc > 3 ? std::stoi(argv[3]) : 5;
  fs::create_directories(dir);
  if (steps == 0) {  // build the packings only: timing in a fresh process gives steadier numbers
    for (double mu : {0.5, 0.0}) packing_for(dir, mu);
    return 0;
  }
  std::vector<Result> results;
  std::vector<TwoRuns> pairs;
  for (double mu : {0.5, 0.0}) {
    const std::string packing = packing_for(dir, mu);
    const dem::SceneConfig scene = dem::scene_from_text(timing_scene(packing, mu, 1000000000L), dir + "/bench.yaml");
    std::vector<dem::Vec3> one_thread_positions;
    double one_thread_rate = 0;
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      std::vector<double> rates;
      double z = 0;
      bool same = true;
      for (int r = 0; r < reps; ++r) {
        dem::Simulation sim = dem::build_simulation(scene);
        dem::CellTargets targets;
        for (auto& t : targets) t = {dem::AxisTarget::Mode::Stress, 0, 1e5, 0};
        const dem::ServoSettings servo{scene.servo.gain, 1.0};
        for (int i = 0; i < 200; ++i) sim.step(targets, servo);  // warm-up: list built, caches filled
        const auto t0 = std::chrono::steady_clock::now();
        for (long i = 0; i < steps; ++i) sim.step(targets, servo);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rates.push_back(static_cast<double>(steps) * static_cast<double>(sim.particles().size()) / wall);
        z = 2.0 * static_cast<double>(sim.sums().contacts) / static_cast<double>(sim.particles().size());
        if (threads == 1 && r == 0) one_thread_positions = sim.particles().s;
        same = same && sim.particles().s == one_thread_positions;
      }
      std::sort(rates.begin(), rates.end());
      const double median = rates[rates.size() / 2];
      if (threads == 1) one_thread_rate = median;
      results.push_back({mu, threads, median, rates.front(), rates.back(), z, same, median / one_thread_rate});
    }
    // Two runs at once, one thread each (what the pipeline does with -j 2): the total rate.
    std::vector<double> rates;
    bool same = true;
    for (int r = 0; r < reps; ++r) {
      double wall = 0;
      std::vector<dem::Vec3> ends[2];
#pragma omp parallel num_threads(2) reduction(max : wall)
      {  // nested regions are inactive: each run's loops run on its own thread only
        dem::Simulation sim = dem::build_simulation(scene);
        dem::CellTargets targets;
        for (auto& t : targets) t = {dem::AxisTarget::Mode::Stress, 0, 1e5, 0};
        const dem::ServoSettings servo{scene.servo.gain, 1.0};
        for (int i = 0; i < 200; ++i) sim.step(targets, servo);
#pragma omp barrier
        const auto t0 = std::chrono::steady_clock::now();
        for (long i = 0; i < steps; ++i) sim.step(targets, servo);
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ends[omp_get_thread_num()] = sim.particles().s;
      }
      rates.push_back(2.0 * static_cast<double>(steps) * static_cast<double>(ends[0].size()) / wall);
      same = same && ends[0] == one_thread_positions && ends[1] == one_thread_positions;
    }
    std::sort(rates.begin(), rates.end());
    const double median = rates[rates.size() / 2];
    pairs.push_back({mu, median, rates.front(), rates.back(), same, median / one_thread_rate});
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  std::printf("dem-bench %s: 8,000 spheres, dt = 1e-6 s, %ld steps x %d repetitions, vector loops %d lanes\n",
              dem::software_version, steps, reps, dem::simd_width());
  std::printf("%-9s %-8s %-22s %-24s %-8s %-10s %s\n", "friction", "threads", "particle-steps/s (med)", "min .. max",
              "2Nc/Np", "speed-up", "same bits as 1 thread");
  for (const auto& r : results) {
    std::printf("%-9.2f %-8d %-22.3e %.3e .. %.3e  %-8.2f %-10.2f %s\n", r.friction, r.threads, r.median_rate, r.min_rate,
                r.max_rate, r.contacts_per_particle, r.speedup, r.same_as_one_thread ? "yes" : "NO");
  }
  for (const auto& r : pairs)
    std::printf("%-9.2f %-8s %-22.3e %.3e .. %.3e  %-8s %-10.2f %s\n", r.friction, "2 runs", r.median_rate, r.min_rate,
                r.max_rate, "", r.speedup, r.same_as_one_thread ? "yes" : "NO");
  std::printf("peak memory (max RSS): %.1f MB\n", peak_mb);
  std::ofstream json(dir + "/bench.json");
  json << "{\n  \"code\": \"cyclic-triax dem\",\n  \"version\": \"" << dem::software_version
       << "\",\n  \"vector_lanes\": " << dem::simd_width() << ",\n  \"particles\": 8000,\n  \"steps\": " << steps << ",\n  \"repetitions\": " << reps
       << ",\n  \"peak_rss_MB\": " << peak_mb << ",\n  \"runs\": [\n";
  for (std::size_t i = 0; i < results.size(); ++i)
    json << "    {\"friction\": " << results[i].friction << ", \"threads\": " << results[i].threads
         << ", \"particle_steps_per_s_median\": " << results[i].median_rate << ", \"min\": " << results[i].min_rate
         << ", \"max\": " << results[i].max_rate << ", \"coordination_number\": " << results[i].contacts_per_particle
         << ", \"same_bits_as_1_thread\": " << (results[i].same_as_one_thread ? "true" : "false") << "}"
         << (i + 1 < results.size() ? "," : "") << "\n";
  json << "  ],\n  \"two_runs_at_once\": [\n";
  for (std::size_t i = 0; i < pairs.size(); ++i)
    json << "    {\"friction\": " << pairs[i].friction << ", \"runs\": 2, \"threads_per_run\": 1"
         << ", \"total_particle_steps_per_s_median\": " << pairs[i].median_rate << ", \"min\": " << pairs[i].min_rate
         << ", \"max\": " << pairs[i].max_rate
         << ", \"same_bits_as_1_thread\": " << (pairs[i].same_as_one_thread ? "true" : "false") << "}"
         << (i + 1 < pairs.size() ? "," : "") << "\n";
  json << "  ]\n}\n";
  for (const auto& r : results)
    if (!r.same_as_one_thread) return 1;
  for (const auto& r : pairs)
    if (!r.same_as_one_thread) return 1;
  return 0;
}
