// Control stages: the inertial number counts every rate component, a stage warns when
// it leaves the quasi-static range, and a stress target the stage never reaches fails it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/measurements.hpp"
#include "config/scene_config.hpp"
#include "engine/io/io_test_support.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

// 64 spheres of 4.0-4.5 mm compressed to 100 kPa (as stress_path_test's sample).
std::string compressed_sample(const std::string& name) {
  const std::string dir = test::scratch_dir(name);
  const std::string scene =
      "name: sample\n"
      "particles:\n"
      "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
      "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
      "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
      "numerics: {time_step: 2.0e-6}\n"
      "output: {interval: 5000}\n"
      "stages:\n"
      "  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e7, max_strain_rate: 5.0,\n"
      "     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0e-2, max_duration: 2.0}}\n";
  const std::string file = dir + "/sample.h5";
  run_scene(scene_from_text(scene, dir + "/sample.yaml"), file);
  return file;
}

SceneConfig control_scene(const std::string& sample, const std::string& stage) {
  return scene_from_text("name: c\nparticles: {state: " + sample + "}\nmaterial: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                         "numerics: {time_step: 2.0e-6}\nstages:\n  - " + stage + "\n",
                         std::filesystem::path(sample).parent_path().string() + "/c.yaml");
}

}  // namespace

TEST_CASE("the inertial number takes the largest rate of all six components", "[control][inertial]") {
  // Found in review: only the axial rates counted, so simple shear with the axes fixed reported 0.
  // The class swept: each of xx yy zz xy xz yz alone at +r and -r. Expected, from the definition
  // (GDR MiDi 2004): I = |r| d sqrt(rho / p), d the mean diameter of the spheres, computed here
  // from their radii.
  const std::string sample = compressed_sample("inertial_components");
  const SceneConfig scene = control_scene(sample, "{name: s, type: control, duration: 2.0e-6, control: {xx: {strain_rate: 0}, "
                                                  "yy: {strain_rate: 0}, zz: {strain_rate: 0}}}");
  const double p = 1.0e5;
  for (int k = 0; k < 6; ++k)
    for (const double r : {0.5, -0.5}) {
      INFO("component " << component_names[static_cast<std::size_t>(k)] << ", rate " << r);
      Simulation sim = build_simulation(scene);
      double d = 0;
      for (const double radius : sim.particles().radius) d += 2 * radius;
      d /= static_cast<double>(sim.particles().size());
      CellControl control;
      control.component[static_cast<std::size_t>(k)] = {AxisTarget::Mode::StrainRate, r, 0, 0};
      AdaptiveServo servo(scene.servo);
      sim.step(control, servo);
      const CellRates& g = sim.rates();
      REQUIRE((k < 3 ? g.axial[k] : g.shear[k - 3]) == r);
      CHECK(max_strain_rate(g) == std::abs(r));
      CHECK(inertial_number(sim, p) == Approx(std::abs(r) * d * std::sqrt(2650 / p)).epsilon(1e-12));
    }
}

TEST_CASE("a control stage warns when its inertial number leaves the quasi-static range", "[control][inertial]") {
  // Simple shear, the axes fixed: at 50/s, I = 50 x ~4.25 mm x sqrt(2650 / 1e5) ~ 0.035 > 1e-3;
  // at 0.01/s, ~7e-6. Before the fix neither warned (the shear rate did not count).
  const std::string sample = compressed_sample("inertial_control_warns");
  for (const double rate : {50.0, 0.01}) {
    INFO("xy strain rate " << rate);
    const SceneConfig scene = control_scene(sample, "{name: shear, type: control, duration: 1.0e-4, control: {xx: {strain_rate: 0}, "
                                                    "yy: {strain_rate: 0}, zz: {strain_rate: 0}, xy: {strain_rate: " +
                                                        std::to_string(rate) + "}}}");
    Simulation sim = build_simulation(scene);
    std::vector<std::string> warnings;
    StageHooks hooks;
    hooks.warning = [&](const std::string& w) { warnings.push_back(w); };
    run_stage(sim, scene, 0, hooks);
    if (rate > 1) {
      REQUIRE(warnings.size() == 1);
      CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("stage 'shear': inertial number reached ") &&
                                  Catch::Matchers::EndsWith(" > 1e-3, the loading is not quasi-static"));
    } else {
      CHECK(warnings.empty());
    }
  }
}

TEST_CASE("a control stage fails when it does not reach its stress targets", "[control][targets]") {
  // unreachable targets ran to the end with exit 0. The class swept: a stress-controlled
  // axis, a stress-controlled shear and constant_mean_stress's p, each once out of reach in the
  // stage's duration (1e-4 s at a cap of 1/s moves a strain of 1e-4: a few hundred Pa on this
  // sample) and once at the stress the sample holds (100 kPa, no shear stress): the first fails
  // naming the component, the second ends normally.
  const std::string sample = compressed_sample("control_targets");
  struct Case {
    std::string control, named;
  };
  const std::vector<Case> unreachable = {
      {"{xx: {stress: 1.0e8}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}", "stress xx reached "},
      {"{xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0}, xy: {stress: 5.0e5}}", "stress xy reached "},
      {"{xx: follow, yy: follow, zz: {strain_rate: 0}}, constraint: {type: constant_mean_stress, mean_stress: 1.0e8}",
       "the mean stress (constant_mean_stress) reached "},
  };
  const std::vector<std::string> reachable = {
      "{xx: {stress: 1.0e5}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}",
      "{xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0}, xy: {stress: 0}}",
      "{xx: follow, yy: follow, zz: {strain_rate: 0}}, constraint: {type: constant_mean_stress, mean_stress: 1.0e5}",
  };
  const auto stage = [](const std::string& control) {
    return "{name: hold, type: control, duration: 1.0e-4, control: " + control + "}";
  };
  for (const Case& c : unreachable) {
    INFO(c.control);
    const SceneConfig scene = control_scene(sample, stage(c.control));
    Simulation sim = build_simulation(scene);
    CHECK_THROWS_MATCHES(run_stage(sim, scene, 0, StageHooks{}), StageError,
                         Catch::Matchers::Predicate<std::exception>([&](const std::exception& e) {
                           const std::string m = e.what();
                           return m.rfind("stage 'hold' (duration reached): ", 0) == 0 && m.find(c.named) != std::string::npos &&
                                  m.find("the stage did not reach what it was asked") != std::string::npos;
                         }, "names the stage, the component and what it reached"));
  }
  for (const std::string& control : reachable) {
    INFO(control);
    const SceneConfig scene = control_scene(sample, stage(control));
    Simulation sim = build_simulation(scene);
    CHECK_NOTHROW(run_stage(sim, scene, 0, StageHooks{}));
  }
}
