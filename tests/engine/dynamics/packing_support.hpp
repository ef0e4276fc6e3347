#pragma once
// A compressing packing, and exact comparison of two runs: shared by the tests that require two
// ways of computing a run (1 or 2 threads, scalar or vectorised force loop) to agree bit for bit.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "config/contact_keys.hpp"
#include "config/scene_config.hpp"
#include "contact/scalar_lanes.hpp"
#include "run/run_scene.hpp"

namespace dem::test {

// The adaptive stress servo driving every axis towards 100 kPa (max strain rate 50/s), as the
// packings below are compressed.
struct Squeeze {
  CellTargets targets;
  AdaptiveServo servo;
  explicit Squeeze(const SceneConfig& scene) : servo(settings_of(scene)) {
    for (auto& t : targets) t = {AxisTarget::Mode::Stress, 0, 1e5, 0};
  }
  void step(Simulation& sim) { sim.step(targets, servo); }
  static ServoSettings settings_of(const SceneConfig& scene) {
    ServoSettings settings = scene.servo;
    settings.max_strain_rate_per_s = 50.0;
    return settings;
  }
};

// 1,000 spheres (3.0-4.5 mm) on a 10x10x10 lattice of spacing 4.6 mm (or side^3 spheres), compressed
// to 100 kPa with the adaptive stress servo for `steps` steps: contacts form, slide and break.
// `skin`: the Verlet skin [m], or the default. With `threads_at`, step i runs on threads_at(i)
// threads instead (as a run that changes its count between steps, run/thread_choice.hpp).
inline Simulation compressed(double friction, int threads, int steps, int side = 10, const std::string& skin = "",
                             const std::function<int(int)>& threads_at = {}) {
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
  Squeeze squeeze(scene);
  for (int i = 0; i < steps; ++i) {
    if (threads_at) omp_set_num_threads(threads_at(i));
    squeeze.step(sim);
  }
  omp_set_num_threads(saved);
  return sim;
}

// Example constants of each part of a law. Linear: kn = ks = 1e6 N/m, as in compressed() above.
// Hertz-Mindlin: E = 1e9 Pa, nu = 0.3, so that at 100 kPa overlaps are ~1 % of a radius; its
// Rayleigh step pi r_min sqrt(rho/G) / (0.1631 nu + 0.8766) is 17.8 us for r_min = 2 mm
// (G = E / 2.6), so dt = 1 us is 0.056 of it (the engine refuses more than 0.2). Friction 0.5.
// Rolling: mu_r = 0.1 with k_r = 5e5 N/m (linear; half of kn) and 5e4 N/m (Hertz; about half the
// normal stiffness 2 E* sqrt(R* delta) ~ 1.4e5 N/m at 100 kPa): the rolling spring's rotational
// frequency sqrt(k_r R*^2 / I) stays below the normal one. Contact dashpots: zeta = 0.05.
// A new kind of part needs nothing here either: it is built by its own `from` from these values
// and, for a key of its own, the `example` its declaration gives (contact/parameter.hpp).
template <class T>
using part = std::type_identity<T>;
inline ParameterValues example_values() {
  return {{"kn", 1e6}, {"ks", 1e6}, {"friction", 0.5}, {"young_modulus", 1e9}, {"poisson_ratio", 0.3},
          {"rolling_friction", 0.1}, {"rolling_stiffness", 5e5}, {"contact_damping", 0.05}};
}
template <class Part>
Part example_part() {
  ParameterValues v = example_values();
  for (const Parameter& p : Part::parameters)
    if (!v.count(p.name)) v[p.name] = p.example == p.example ? p.example : p.default_value;  // NaN: the scene refuses it
  return Part::from(v);
}
template <class Normal>
Normal example_normal(part<Normal>) {
  return example_part<Normal>();
}
template <class Tangential>
Tangential example_tangential(part<Tangential>, const auto&) {
  return example_part<Tangential>();
}
inline LinearNormal example_normal(part<LinearNormal>) { return {1e6}; }
inline HertzNormal example_normal(part<HertzNormal>) { return {1e9, 0.3}; }
template <class Elastic>
Dashpot<Elastic> example_normal(part<Dashpot<Elastic>>) {
  return {example_normal(part<Elastic>{}), 0.05};
}
inline NoFriction example_tangential(part<NoFriction>, const auto&) { return {}; }
inline LinearCoulomb example_tangential(part<LinearCoulomb>, const auto&) { return {1e6, 0.5}; }
inline MindlinCoulomb example_tangential(part<MindlinCoulomb>, const HertzNormal& n) { return MindlinCoulomb::of(n, 0.5); }
inline NoRolling example_rolling(part<NoRolling>, const auto&) { return {}; }
template <class Normal>
RollingSpring example_rolling(part<RollingSpring>, const Normal& n) {
  return {n.damping_stiffness() > 0 ? 5e5 : 5e4, 0.1};
}
template <class Law>
Law example_law() {
  const auto normal = example_normal(part<typename Law::NormalLaw>{});
  return Law{normal, example_tangential(part<typename Law::TangentialLaw>{}, normal),
             example_rolling(part<typename Law::RollingLaw>{}, normal)};
}

// A contact law as a scene writes it, with the damping it allows.
struct LawScene {
  std::string name;
  std::string material;  // YAML flow mapping
  std::string damping;   // YAML flow mapping
  std::size_t index;     // the alternative of AnyContactLaw the scene must select
};

// A scene's material and damping for a law: its keys as the resolved scene writes them
// (config/contact_keys.hpp), viscous damping (the engine's default) where the law has a stiffness
// to scale it with, else Cundall's local damping (alpha = 0.1).
inline LawScene law_scene(const AnyContactLaw& law) {
  YAML::Emitter out;
  out << YAML::Flow << YAML::BeginMap << YAML::Key << "density" << YAML::Value << 2650;
  emit_contact_law(out, law);
  out << YAML::EndMap;
  const std::string damping =
      damping_stiffness(law) > 0 ? "{form: viscous}" : "{form: local, translational: 0.1, rotational: 0.1}";
  return {out.c_str(), out.c_str(), damping, law.index()};
}

// Every law of AnyContactLaw (contact/contact_law.hpp), one per alternative in variant order, as a
// scene writes it: enumerated from the variant, so a new alternative is tested with no change here.
inline const std::vector<LawScene>& every_law() {
  static const std::vector<LawScene> laws = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<LawScene>{law_scene(AnyContactLaw(std::in_place_index<I>,
                                                         example_law<std::variant_alternative_t<I, AnyContactLaw>>()))...};
  }(std::make_index_sequence<std::variant_size_v<AnyContactLaw>>{});
  return laws;
}

// A compressed packing of a law, and what its last force evaluation did at the caps.
struct LawRun {
  Simulation sim;
  std::size_t sliding = 0;          // contacts at the Coulomb cap (the history's sliding flags)
  std::size_t rolling_at_cap = 0;   // contacts whose rolling spring is at its cap, k_r |u_r| = mu_r f_n
};

// side^3 spheres of 4.0-4.5 mm on a lattice of spacing 4.5 mm (an 8 % strain from jamming, so
// contacts form within ~500 steps), compressed to 100 kPa with the adaptive stress servo
// (max strain rate 50/s) for `steps` steps of 1 us: contacts form, slide, roll and open.
inline LawRun compressed_law(const LawScene& law, int threads, int steps, int side = 10) {
  const std::string n = std::to_string(side);
  const std::string text =
      "name: law\n"
      "particles:\n"
      "  lattice: {n: [" + n + ", " + n + ", " + n + "], spacing: 4.5e-3, seed: 5}\n"
      "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
      "material: " + law.material + "\n"
      "damping: " + law.damping + "\n"
      "numerics: {time_step: 1.0e-6}\n"
      "stages:\n"
      "  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e8, max_strain_rate: 50,\n"
      "     hold: {stress_tolerance: 0.01, unbalanced_force_ratio: 0.01, max_duration: 1.0}}\n";
  const SceneConfig scene = scene_from_text(text, "law.yaml");
  REQUIRE(scene.material.law.index() == law.index);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  LawRun run{build_simulation(scene)};
  Squeeze squeeze(scene);
  for (int i = 0; i + 1 < steps; ++i) squeeze.step(run.sim);
  // The last step's force evaluation sees these positions and this cell.
  const std::vector<Vec3> s_before = run.sim.particles().s;
  const PeriodicCell cell_before = run.sim.cell();
  squeeze.step(run.sim);
  omp_set_num_threads(saved);

  const ContactHistory& h = run.sim.history();
  for (auto f : h.sliding) run.sliding += f;
  std::visit(
      [&](const auto& l) {
        if constexpr (std::decay_t<decltype(l)>::has_rolling) {
          using O = scalar_lanes::Ops;
          const Particles& p = run.sim.particles();
          const PairList& pairs = run.sim.pairs();  // the list of the last force evaluation
          for (std::size_t k = 0; k < pairs.size(); ++k) {
            const auto i = pairs.first[k], j = pairs.second[k];
            const double rsum = p.radius[i] + p.radius[j];
            const double dist = cell_before.branch(s_before[i], s_before[j]).norm();
            if (dist >= rsum) continue;
            const double fn = l.normal.template force<O>(rsum - dist, p.radius[i] * p.radius[j] / rsum);
            // The cap leaves k_r |u_r| = mu_r f_n up to a few roundings; below it the spring is elastic.
            if (l.rolling.kr * h.rolling[k].norm() >= (1 - 1e-9) * l.rolling.mu_r * fn) ++run.rolling_at_cap;
          }
        }
      },
      run.sim.material().law);
  return run;
}

// A contact at the current positions with its history: (i, j, tangential history, sliding, rolling spring).
using Contact = std::tuple<std::uint32_t, std::uint32_t, Vec3, int, Vec3>;
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
    out.emplace_back(i, j, h.tangential.empty() ? Vec3(Vec3::Zero()) : h.tangential[k], h.sliding.empty() ? 0 : int(h.sliding[k]),
                     h.rolling.empty() ? Vec3(Vec3::Zero()) : h.rolling[k]);
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
