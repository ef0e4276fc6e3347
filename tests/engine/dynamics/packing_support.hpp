#pragma once
// A compressing packing, and exact comparison of two runs: shared by the tests that require two
// ways of computing a run (1 or 2 threads, scalar or vectorised force loop) to agree bit for bit.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "config/scene_config.hpp"
#include "run/run_scene.hpp"

namespace dem::test {

// 1,000 spheres (3.0-4.5 mm) on a 10x10x10 lattice of spacing 4.6 mm (or side^3 spheres), compressed
// to 100 kPa with the adaptive stress servo for `steps` steps: contacts form, slide and break.
// `skin`: the Verlet skin [m], or the default.
inline Simulation compressed(double friction, int threads, int steps, int side = 10, const std::string& skin = "") {
  const std::string n = std::to_string(side);
  const std::string text =
      "name: threads\n"
      "particles:\n"
      "  lattice: {n: [" + n + ", " + n + ", " + n + "], spacing: 4.6e-3, seed: 5}\n"
      "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
      "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: " + std::to_string(friction) + "}\n"
      "numerics: {time_step: 1.0e-6" + (skin.empty() ? "" : ", verlet_skin: " + skin) + "}\n"
      "stages:\n"
      "  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e8, max_strain_rate: 50,\n"
      "     hold: {stress_tolerance: 0.01, unbalanced_force_ratio: 0.01, max_duration: 1.0}}\n";
  const SceneConfig scene = scene_from_text(text, "threads.yaml");
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim = build_simulation(scene);
  CellTargets targets;
  for (auto& t : targets) t = {AxisTarget::Mode::Stress, 0, 1e5, 0};
  ServoSettings settings = scene.servo;
  settings.max_strain_rate_per_s = 50.0;
  AdaptiveServo servo(settings);
  for (int i = 0; i < steps; ++i) sim.step(targets, servo);
  omp_set_num_threads(saved);
  return sim;
}

// A contact at the current positions with its history: (i, j, spring, sliding).
using Contact = std::tuple<std::uint32_t, std::uint32_t, Vec3, int>;
// The pairs of the list in contact at the current positions, in list order, with their history.
inline std::vector<Contact> touching(const Simulation& sim) {
  std::vector<Contact> out;
  const Particles& p = sim.particles();
  const PairList& pairs = sim.pairs();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = pairs.first[k], j = pairs.second[k];
    const double rsum = p.radius[i] + p.radius[j];
    if (sim.cell().branch(p.s[i], p.s[j]).squaredNorm() >= rsum * rsum) continue;
    const ContactHistory& h = sim.history();
    out.emplace_back(i, j, h.tangential.empty() ? Vec3(Vec3::Zero()) : h.tangential[k], h.sliding.empty() ? 0 : int(h.sliding[k]));
  }
  return out;
}

// The same particles, cell, forces and sums (the pair lists may differ).
inline void require_identical_motion(const Simulation& a, const Simulation& b) {
  REQUIRE(a.sums().contacts > 500);  // the packing is in contact: the test exercises the contact law
  REQUIRE(a.sums().contacts == b.sums().contacts);
  REQUIRE(a.cell().lengths() == b.cell().lengths());
  REQUIRE(a.particles().s == b.particles().s);
  REQUIRE(a.particles().v == b.particles().v);
  REQUIRE(a.particles().omega == b.particles().omega);
  REQUIRE(a.net_force() == b.net_force());
  REQUIRE(a.sums().stress_Pa == b.sums().stress_Pa);
  REQUIRE(a.kinetic_energy() == b.kinetic_energy());
}

inline void require_identical(const Simulation& a, const Simulation& b) {
  require_identical_motion(a, b);
  REQUIRE(a.pairs().first == b.pairs().first);
  REQUIRE(a.history().tangential == b.history().tangential);
  REQUIRE(a.history().sliding == b.history().sliding);
  REQUIRE(a.history().rolling == b.history().rolling);
}


}  // namespace dem::test
