// Valid scenes: defaults, path resolution, the resolved YAML recorded in results, the key
// reference (`dem keys`) and the shipped example scenes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {
const std::string lattice_particles =
    "particles:\n"
    "  lattice: {n: [3, 3, 3], spacing: 5.0e-3}\n"
    "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n";
const std::string minimal_rest =
    "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
    "numerics: {time_step: 1.0e-6}\n"
    "stages:\n"
    "  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-3}\n"
    "  - {name: hold, type: stress, target: [1.0e5, 2.0e5, 3.0e5], rate: 1.0e6, hold: {}}\n";
}  // namespace

TEST_CASE("a minimal scene gets the documented defaults", "[config]") {
  // The defaults below are those declared in scene_config.cpp (and shown by `dem keys`).
  const SceneConfig c = scene_from_text(lattice_particles + minimal_rest, "some/folder/my_scene.yaml");
  CHECK(c.name == "my_scene");  // default name: the file's stem
  CHECK(c.particles.kind == ParticleSource::Kind::Lattice);
  CHECK(c.particles.lattice.seed == 1);
  CHECK(c.material.density_kg_per_m3 == 2650);
  CHECK((c.damping.form == Damping::Form::Viscous));
  CHECK(c.damping.translational == 0.05);
  CHECK(c.damping.rotational == 0.05);
  CHECK(c.max_time_step_fraction == 0.2);
  CHECK(c.verlet_skin_m == 2e-4);
  CHECK(c.servo.gain == 1e-3);
  CHECK(c.output.interval_steps == 1000);
  CHECK(c.output.flush_rows == 20);
  REQUIRE(c.stages.size() == 2);
  CHECK(c.stages[0].name == "squeeze");
  CHECK((c.stages[0].type == StageConfig::Type::StrainRate));
  CHECK(c.stages[0].strain_rate_per_s == Vec3(0.1, 0.1, 0.1));
  CHECK(c.stages[0].duration_s == 1e-3);
  CHECK_FALSE(c.stages[0].reset_strain);
  CHECK((c.stages[1].type == StageConfig::Type::Stress));
  CHECK(c.stages[1].target_Pa == Vec3(1e5, 2e5, 3e5));
  CHECK(c.stages[1].max_strain_rate_per_s == 1.0);
  CHECK(c.stages[1].hold.stress_tolerance == 0.005);
  CHECK(c.stages[1].hold.unbalanced_force_ratio == 1e-3);
  CHECK(c.stages[1].hold.check_interval_steps == 100);
  CHECK(c.stages[1].hold.max_duration_s == 10.0);
}

TEST_CASE("csv and state paths are resolved against the scene's folder", "[config]") {
  // A scene refers to its inputs relative to itself, so that it can be run from any folder.
  const std::string rest = minimal_rest;
  SECTION("relative csv path") {
    const SceneConfig c = scene_from_text("particles: {csv: ../data/p.csv, cell: [0.02, 0.02, 0.02]}\n" + rest,
                                          "/runs/scenes/a.yaml");
    CHECK(c.particles.kind == ParticleSource::Kind::Csv);
    CHECK(c.particles.path == "/runs/data/p.csv");
    CHECK(c.particles.cell_m == Vec3(0.02, 0.02, 0.02));
  }
  SECTION("relative state path") {
    const SceneConfig c = scene_from_text("particles: {state: prepared.h5}\n" + rest, "/runs/scenes/a.yaml");
    CHECK(c.particles.kind == ParticleSource::Kind::State);
    CHECK(c.particles.path == "/runs/scenes/prepared.h5");
  }
  SECTION("absolute path kept") {
    const SceneConfig c = scene_from_text("particles: {state: /elsewhere/prepared.h5}\n" + rest, "/runs/scenes/a.yaml");
    CHECK(c.particles.path == "/elsewhere/prepared.h5");
  }
}

TEST_CASE("the resolved YAML is a complete scene that parses back to the same values", "[config]") {
  // The result file records resolved_yaml so that a run can be repeated from it alone: parsing it
  // must give the same scene, every double bit for bit (yaml-cpp emits enough digits), and
  // resolving it again must give the same text (a fixed point).
  const std::string text =
      "name: exact\n"
      "particles:\n"
      "  lattice: {n: [4, 3, 2], spacing: 5.123456789012345e-3, seed: 7}\n"
      "  grading: {diameters: [3.1e-3, 3.7e-3, 4.4999999999999997e-3], percent_finer: [0, 33.333333333333336, 100]}\n"
      "material: {density: 2650.5, kn: 1.234567890123e6, ks: 0.7e6, friction: 0.1}\n"
      "damping: {form: local, translational: 0.7, rotational: 0.3}\n"
      "numerics: {time_step: 1.2345678901234567e-7, max_time_step_fraction: 0.15, verlet_skin: 1.0e-4}\n"
      "servo: {gain: 2.0e-3}\n"
      "output: {interval: 50, flush_rows: 3}\n"
      "stages:\n"
      "  - {name: a, type: strain_rate, strain_rate: [0.1, -0.05, 1.0e-3], duration: 0.3, reset_strain: true}\n"
      "  - {name: b, type: stress, target: [1.0e5, 2.0e5, 3.0e5], rate: 1.0e6, max_strain_rate: 0.5,\n"
      "     hold: {stress_tolerance: 0.01, unbalanced_force_ratio: 2.0e-3, check_interval: 10, max_duration: 2}}\n";
  const SceneConfig a = scene_from_text(text, "exact.yaml");
  const SceneConfig b = scene_from_text(a.resolved_yaml, "exact.yaml");
  INFO(a.resolved_yaml);
  CHECK(b.resolved_yaml == a.resolved_yaml);
  CHECK(b.name == "exact");
  CHECK(b.particles.lattice.n[0] == 4);
  CHECK(b.particles.lattice.n[1] == 3);
  CHECK(b.particles.lattice.n[2] == 2);
  CHECK(b.particles.lattice.spacing_m == a.particles.lattice.spacing_m);
  CHECK(b.particles.lattice.seed == 7);
  CHECK(b.particles.grading_diameters_m == a.particles.grading_diameters_m);
  CHECK(b.particles.grading_percent_finer == a.particles.grading_percent_finer);
  CHECK(b.material.density_kg_per_m3 == a.material.density_kg_per_m3);
  const auto& la = std::get<LinearFrictionLaw>(a.material.law);
  const auto& lb = std::get<LinearFrictionLaw>(b.material.law);
  CHECK(lb.normal.kn == la.normal.kn);
  CHECK(lb.tangential.ks == la.tangential.ks);
  CHECK(lb.tangential.mu == la.tangential.mu);
  CHECK((b.damping.form == Damping::Form::Local));
  CHECK(b.damping.translational == 0.7);
  CHECK(b.damping.rotational == 0.3);
  CHECK(b.time_step_s == a.time_step_s);
  CHECK(b.time_step_s == 1.2345678901234567e-7);
  CHECK(b.max_time_step_fraction == 0.15);
  CHECK(b.verlet_skin_m == 1e-4);
  CHECK(b.servo.gain == 2e-3);
  CHECK(b.output.interval_steps == 50);
  CHECK(b.output.flush_rows == 3);
  REQUIRE(b.stages.size() == 2);
  CHECK(b.stages[0].reset_strain);
  CHECK(b.stages[0].strain_rate_per_s == a.stages[0].strain_rate_per_s);
  CHECK(b.stages[0].duration_s == 0.3);
  CHECK(b.stages[1].target_Pa == a.stages[1].target_Pa);
  CHECK(b.stages[1].stress_rate_Pa_per_s == 1e6);
  CHECK(b.stages[1].max_strain_rate_per_s == 0.5);
  CHECK(b.stages[1].hold.stress_tolerance == 0.01);
  CHECK(b.stages[1].hold.unbalanced_force_ratio == 2e-3);
  CHECK(b.stages[1].hold.check_interval_steps == 10);
  CHECK(b.stages[1].hold.max_duration_s == 2);
}

TEST_CASE("the key reference lists every key with unit, range and default", "[config]") {
  // `dem keys` prints this; a key missing here would be undocumented for users.
  const std::string ref = scene_key_reference();
  for (const char* key : {"name;", "particles.lattice.n;", "particles.lattice.spacing [m]", "particles.lattice.seed;",
                          "particles.grading.diameters [m]", "particles.grading.percent_finer [%]", "particles.csv;",
                          "particles.cell [m]", "particles.state;", "material.density [kg/m^3]", "material.kn [N/m]",
                          "material.ks [N/m]", "material.friction;", "damping.form;", "damping.translational;",
                          "damping.rotational;", "numerics.time_step [s]", "numerics.max_time_step_fraction;",
                          "numerics.verlet_skin [m]", "servo.gain;", "output.interval;", "output.flush_rows;",
                          "stages[].name;", "stages[].type;", "stages[].reset_strain;", "stages[].strain_rate [1/s]",
                          "stages[].duration [s]", "stages[].target [Pa]", "stages[].rate [Pa/s]",
                          "stages[].max_strain_rate [1/s]", "stages[].hold.stress_tolerance;",
                          "stages[].hold.unbalanced_force_ratio;", "stages[].hold.check_interval;",
                          "stages[].hold.max_duration [s]", "stages[].mean_stress [Pa]", "stages[].stress_ratio;",
                          "stages[].path;"}) {
    INFO(key);
    CHECK_THAT(ref, Catch::Matchers::Contains("  " + std::string(key)));
  }
  // Ranges and defaults as declared: friction in [0, 10], required; time_step in (0, 1] s, required.
  CHECK_THAT(ref, Catch::Matchers::Contains("material.friction; [0, 10]; required;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("numerics.time_step [s]; (0, 1]; required;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("damping.form; one of: viscous, local; viscous;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("stages[].type; one of: strain_rate, stress, stress_path, control; required;"));
  // The stress-path defaults: p = 100 kPa and R = 1.24 (docs/method.md#stress-paths).
  CHECK_THAT(ref, Catch::Matchers::Contains("stages[].mean_stress [Pa]; (0, 1e+10]; 100000;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("stages[].stress_ratio; [1, 100]; 1.24;"));
}

TEST_CASE("the shipped example scenes load and build", "[config]") {
  // The scenes/ folder is what users start from; each must pass every input check, including
  // the critical time step refusal (dt = 1e-6 s vs 0.2 x ~1.2e-5 s).
  for (const char* name : {"prepare_dense", "prepare_loose", "prepare_medium"}) {
    INFO(name);
    const std::string file = std::string(DEM_SOURCE_DIR) + "/scenes/" + name + ".yaml";
    if (!std::filesystem::exists(file)) {
      WARN(file << " not found: skipped");
      continue;
    }
    const SceneConfig c = load_scene(file);
    CHECK(c.name == name);
    CHECK(build_simulation(c).particles().size() == 8000);
  }
}

TEST_CASE("the key reference shows optional sections as optional, with their keys' defaults", "[config]") {
  // damping, servo and output may be left out (Section::optional_child): then every key in them
  // takes its default, and `dem keys` says so instead of "required".
  const std::string ref = scene_key_reference();
  for (const char* section : {"damping", "servo", "output"}) {
    INFO(section);
    CHECK_THAT(ref, Catch::Matchers::Contains(std::string("\n  ") + section + "; mapping; optional (every key at its default);"));
    CHECK_THAT(ref, !Catch::Matchers::Contains(std::string("\n  ") + section + "; mapping; required;"));
  }
  // Their keys with the defaults of "a minimal scene gets the documented defaults" above.
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  damping.translational; [0, 1]; 0.05;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  damping.rotational; [0, 1]; 0.05;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  servo.gain; (0, 1]; 0.001;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  output.interval; integer in [1, 1000000000]; 1000;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  output.flush_rows; integer in [1, 1000000]; 20;"));
  // Frames are off unless asked for: their section is optional, its interval needed only with it.
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  output.frames; mapping; optional (absent: frames at the start, each checkpoint and the end only);"));
  CHECK_THAT(ref, !Catch::Matchers::Contains("\n  output.frames; mapping; required;"));
  // The sections that must be given stay required.
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  material; mapping; required;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  numerics; mapping; required;"));
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  particles; mapping; required;"));
}

TEST_CASE("the key reference shows the default scene name as the file's stem", "[config]") {
  // The default of `name` is the scene file's stem. The reference is built by parsing example
  // texts named "example", whose stem must not leak into it, and parsing another scene first
  // must not change it.
  scene_from_text(lattice_particles + minimal_rest, "some/folder/other_scene.yaml");
  const std::string ref = scene_key_reference();
  CHECK_THAT(ref, Catch::Matchers::Contains("\n  name; text; the scene file's name without extension;"));
  CHECK_THAT(ref, !Catch::Matchers::Contains("'example'"));
  CHECK_THAT(ref, !Catch::Matchers::Contains("other_scene"));
}
