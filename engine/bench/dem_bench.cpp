// dem-bench: particle-steps per second of the step loop on the engine's own jammed packing.
//
// 1. Builds (once, cached in BENCH_DIR) an 8,000-sphere periodic packing: the SPEC lattice
//    compressed isotropically with mu = 0.5 to 100 kPa by the engine itself.
// 2. Loads it and times the step loop at constant stress (the servo holding 100 kPa), for
//    mu = 0.5 and mu = 0 (the frictionless kernel), median of several repetitions.
// Prints a table and writes BENCH_DIR/bench.json.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "run/run_scene.hpp"
#include "version.hpp"

namespace {

const char* packing_scene = R"(
name: bench_packing
particles:
  lattice: {n: [20, 20, 20], spacing: 5.0e-3, seed: 7}
  grading: {diameters: [3.0e-3, 3.7e-3, 4.5e-3], percent_finer: [0, 50, 100]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}
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
  double median_rate, min_rate, max_rate;
  double contacts_per_particle;
};

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const std::string dir = argc > 1 ? argv[1] : "build/bench";
  const long steps = argc > 2 ? std::stol(argv[2]) : 4000;
  const int reps = argc > 3 ? std::stoi(argv[3]) : 5;
  fs::create_directories(dir);
  const std::string packing = fs::absolute(dir + "/packing_mu05.h5").string();
  if (!fs::exists(packing)) {
    std::fprintf(stderr, "dem-bench: building the 8,000-sphere packing (mu = 0.5, 100 kPa) once -> %s\n", packing.c_str());
    const auto s = dem::run_scene(dem::scene_from_text(packing_scene, dir + "/bench_packing.yaml"), packing, false);
    std::fprintf(stderr, "dem-bench: packing built in %lld steps, %.1f s\n", static_cast<long long>(s.steps), s.wall_time_s);
  }
  std::vector<Result> results;
  for (double mu : {0.5, 0.0}) {
    const dem::SceneConfig scene = dem::scene_from_text(timing_scene(packing, mu, 1000000000L), dir + "/bench.yaml");
    std::vector<double> rates;
    double z = 0;
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
    }
    std::sort(rates.begin(), rates.end());
    results.push_back({mu, rates[rates.size() / 2], rates.front(), rates.back(), z});
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  std::printf("dem-bench %s: 8,000 spheres, dt = 1e-6 s, %ld steps x %d repetitions, 1 thread\n", dem::software_version,
              steps, reps);
  std::printf("%-10s %-22s %-24s %-10s\n", "friction", "particle-steps/s (med)", "min .. max", "2Nc/Np");
  for (const auto& r : results)
    std::printf("%-10.2f %-22.3e %.3e .. %.3e  %-10.2f\n", r.friction, r.median_rate, r.min_rate, r.max_rate,
                r.contacts_per_particle);
  std::printf("peak memory (max RSS): %.1f MB\n", peak_mb);
  std::ofstream json(dir + "/bench.json");
  json << "{\n  \"software_version\": \"" << dem::software_version << "\",\n  \"particles\": 8000,\n  \"steps\": " << steps
       << ",\n  \"repetitions\": " << reps << ",\n  \"threads\": 1,\n  \"peak_rss_MB\": " << peak_mb << ",\n  \"runs\": [\n";
  for (std::size_t i = 0; i < results.size(); ++i)
    json << "    {\"friction\": " << results[i].friction << ", \"particle_steps_per_s_median\": " << results[i].median_rate
         << ", \"min\": " << results[i].min_rate << ", \"max\": " << results[i].max_rate
         << ", \"coordination_number\": " << results[i].contacts_per_particle << "}" << (i + 1 < results.size() ? "," : "")
         << "\n";
  json << "  ]\n}\n";
  return 0;
}
