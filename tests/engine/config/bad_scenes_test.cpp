// A catalogue of bad scenes. Every one must be refused before a run starts, with a message that
// names the file, the key path and what is allowed (engine/config/yaml_section.hpp promises
// exactly that: "every error names the file, the full key path, the line, what is allowed and
// what was found"). The expected texts are the engine's wording from yaml_section.cpp and
// scene_config.cpp; the `why` of each case says why the scene is bad.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

// A scene assembled from one line per part, so that every case knows its line numbers:
//   1 name, 2 particles:, 3 lattice, 4 grading, 5 material, 6 numerics, 7 stages, 8... stage items,
//   then `extra` lines.
struct Yaml {
  std::string lattice = "{n: [3, 3, 3], spacing: 5.0e-3, seed: 1}";
  std::string grading = "{diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}";
  std::string material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}";
  std::string numerics = "{time_step: 1.0e-6}";
  std::string stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-4}";
  std::string extra = "";
  std::string text() const {
    return "name: bad\nparticles:\n  lattice: " + lattice + "\n  grading: " + grading + "\nmaterial: " + material +
           "\nnumerics: " + numerics + "\nstages:" + stages + "\n" + extra;
  }
};

const std::string stress_stage = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1}}";

// Every bad scene must give a ConfigError (`dem run` exits 2 for it); an std::invalid_argument
// escaping build_simulation would be a regression (it used to, for grading and lattice errors).
enum class Kind { Config, InvalidArgument };

struct BadScene {
  std::string what;                   // the mistake
  std::string yaml;
  Kind kind;                          // the exception type the engine documents for it
  std::vector<std::string> expected;  // substrings of the message
};

struct Outcome {
  bool threw = false;
  Kind kind = Kind::Config;
  std::string message;
};

// Parses the scene and builds its simulation (some checks, e.g. the grading curve and the
// critical time step, happen only when the particles exist).
Outcome refuse(const std::string& yaml, const std::string& file = "bad.yaml") {
  Outcome o;
  try {
    const SceneConfig scene = scene_from_text(yaml, file);
    build_simulation(scene);
  } catch (const ConfigError& e) {
    o = {true, Kind::Config, e.what()};
  } catch (const std::invalid_argument& e) {
    o = {true, Kind::InvalidArgument, e.what()};
  } catch (const std::exception& e) {
    o = {true, Kind::Config, std::string("UNEXPECTED exception type: ") + e.what()};
    FAIL(o.message);
  }
  return o;
}

std::vector<BadScene> catalogue() {
  const Kind C = Kind::Config;
  return {
      // --- unknown and duplicate keys ---------------------------------------------------------
      // An unread key is an error (Section::finish); a key within edit distance 2 of a declared
      // key of the same mapping is suggested. 'densty' is one deletion from 'density'.
      {"misspelt optional key 'densty' in material", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, densty: 2000}"}.text(), C,
       {"bad.yaml: material: unknown key 'densty' (line 5)", "did you mean 'density'?"}},
      // The same in a nested mapping: hold's 'max_duraton' is one deletion from 'max_duration'.
      {"misspelt key 'max_duraton' in a stage's hold",
       Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duraton: 1}}"}.text(), C,
       {"bad.yaml: stages[0].hold: unknown key 'max_duraton' (line 8)", "did you mean 'max_duration'?"}},
      // A misspelt damping key: 'translatonal' is one deletion from 'translational'.
      {"misspelt key 'translatonal' in damping", Yaml{.extra = "damping: {form: viscous, translatonal: 0.1}\n"}.text(), C,
       {"bad.yaml: damping: unknown key 'translatonal' (line 9)", "did you mean 'translational'?"}},
      // A required key that is misspelt is reported as missing (it is read before the unknown-key
      // check), naming material.friction and its range, and the present, unread key within edit
      // distance 2 ('fricton': one deletion) is suggested with its line.
      {"'fricton' instead of the required 'friction'", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, fricton: 0.5}"}.text(), C,
       {"bad.yaml: material.friction: missing (a number in [0, 10]); found 'fricton' (line 5): did you mean 'friction'?"}},
      // The same for a required mapping: 'numerix' is one substitution from 'numerics'.
      {"'numerix' instead of the required section 'numerics'", Yaml{}.text().replace(Yaml{}.text().find("numerics:"), 9, "numerix:"), C,
       {"bad.yaml: numerics: missing (a mapping); found 'numerix' (line 6): did you mean 'numerics'?"}},
      // A key far from the missing one (edit distance > 2) is not suggested: the plain "missing".
      {"required key missing, an unrelated unknown key present", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, colour: red}"}.text(), C,
       {"bad.yaml: material.friction: missing (a number in [0, 10])"}},
      // Optional sections (damping, servo, output) are always declared, so a misspelt one is an
      // unknown key with a suggestion: 'dampign' is a transposition (distance 2) of 'damping'.
      {"misspelt optional section 'dampign'", Yaml{.extra = "dampign: {form: local}\n"}.text(), C,
       {"bad.yaml: top level: unknown key 'dampign' (line 9)", "did you mean 'damping'?"}},
      {"misspelt optional section 'outptu'", Yaml{.extra = "outptu: {interval: 10}\n"}.text(), C,
       {"bad.yaml: top level: unknown key 'outptu' (line 9)", "did you mean 'output'?"}},
      {"misspelt optional section 'sevro'", Yaml{.extra = "sevro: {gain: 0.01}\n"}.text(), C,
       {"bad.yaml: top level: unknown key 'sevro' (line 9)", "did you mean 'servo'?"}},
      // 'colour' is no scene key and is far from every top-level key: no suggestion, but the line.
      {"unknown top-level key", Yaml{.extra = "colour: red\n"}.text(), C, {"bad.yaml: top level: unknown key 'colour' (line 9)"}},
      // A key used in the wrong kind of stage is unknown there: strain_rate stages have no target.
      {"stress key in a strain_rate stage",
       Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-4, target: [1, 1, 1]}"}.text(), C,
       {"bad.yaml: stages[0]: unknown key 'target' (line 8)"}},
      // YAML leaves duplicate keys undefined; the Section constructor refuses them with the line
      // of the second one.
      {"duplicate key material.kn", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, kn: 2.0e6}"}.text(), C,
       {"bad.yaml: material.kn: duplicate key (line 5)"}},
      {"duplicate top-level section numerics", Yaml{.extra = "numerics: {time_step: 2.0e-6}\n"}.text(), C,
       {"bad.yaml: numerics: duplicate key (line 9)"}},
      // Found by fuzz_scene (tests/fuzz/findings/scene_nonscalar_key.yaml): YAML allows any node as
      // a key; yaml-cpp's conversion error used to escape without the file or the line.
      {"non-scalar key (a list)", Yaml{.extra = "? [a, b]\n: 1\n"}.text(), C,
       {"bad.yaml: top level: a key must be a plain name, got a list (line 9)"}},
      {"null key in material", Yaml{.material = "{? , kn: 1.0e6}"}.text(), C,
       {"bad.yaml: material: a key must be a plain name, got nothing (line 5)"}},
      // --- missing required keys (declared without default) ------------------------------------
      {"missing material.kn", Yaml{.material = "{ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: missing (a number in (0, 1e+12] N/m)"}},
      {"missing numerics.time_step", Yaml{.numerics = "{verlet_skin: 2.0e-4}"}.text(), C,
       {"bad.yaml: numerics.time_step: missing (a number in (0, 1] s)"}},
      {"missing stages", "name: bad\nparticles:\n  lattice: {n: [3, 3, 3], spacing: 5.0e-3}\n"
                         "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                         "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\nnumerics: {time_step: 1.0e-6}\n", C,
       {"bad.yaml: stages: must be a non-empty list of mappings, got nothing"}},
      {"empty stages list", Yaml{.stages = " []"}.text(), C, {"bad.yaml: stages: must be a non-empty list of mappings"}},
      {"missing material section", "name: bad\nparticles:\n  lattice: {n: [3, 3, 3], spacing: 5.0e-3}\n"
                                   "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                                   "numerics: {time_step: 1.0e-6}\nstages: [{name: a, type: strain_rate, strain_rate: [0, 0, 0], duration: 1}]\n", C,
       {"bad.yaml: material: missing (a mapping)"}},
      // A stress stage must say when it has reached its target (hold), even if only to accept the defaults.
      {"stress stage without hold", Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6}"}.text(), C,
       {"bad.yaml: stages[0].hold: missing (a mapping)"}},
      // --- wrong types ---------------------------------------------------------------------------
      {"text where a number is expected", Yaml{.material = "{kn: stiff, ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: must be a number [N/m], got 'stiff' (line 5)"}},
      {"a list where a scalar is expected", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: [0.5]}"}.text(), C,
       {"bad.yaml: material.friction: must be a number, got a list (line 5)"}},
      {"a mapping where a list is expected",
       Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: {x: 0.1}, duration: 1.0e-4}"}.text(), C,
       {"bad.yaml: stages[0].strain_rate: must be a list of 3 numbers in [-1000, 1000], got a mapping (line 8)"}},
      {"a scalar where a mapping is expected", Yaml{.material = "1.0e6"}.text(), C,
       {"bad.yaml: material must be a mapping of keys, got '1.0e6'"}},
      {"not true/false for a boolean",
       Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-4, reset_strain: maybe}"}.text(), C,
       {"bad.yaml: stages[0].reset_strain: must be true or false, got 'maybe' (line 8)"}},
      {"a fraction where an integer is expected", Yaml{.extra = "output: {interval: 0.5}\n"}.text(), C,
       {"bad.yaml: output.interval: must be an integer in [1, 1000000000], got '0.5' (line 9)"}},
      // --- values out of range -------------------------------------------------------------------
      // Friction is a Coulomb coefficient mu in [0, 10].
      {"negative friction", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: -0.1}"}.text(), C,
       {"bad.yaml: material.friction: must be in [0, 10], got -0.1 (line 5)"}},
      // kn must be > 0 (open lower bound "(0,"): a zero spring has no critical time step.
      {"zero kn", Yaml{.material = "{kn: 0, ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: must be in (0, 1e+12] N/m, got 0 (line 5)"}},
      {"negative kn", Yaml{.material = "{kn: -1.0e6, ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: must be in (0, 1e+12] N/m, got -1.0e6"}},
      {"zero time step", Yaml{.numerics = "{time_step: 0}"}.text(), C,
       {"bad.yaml: numerics.time_step: must be in (0, 1] s, got 0 (line 6)"}},
      {"negative time step", Yaml{.numerics = "{time_step: -1.0e-6}"}.text(), C,
       {"bad.yaml: numerics.time_step: must be in (0, 1] s, got -1.0e-6"}},
      // docs/method.md#damping has two damping forms only.
      {"damping form not viscous/local", Yaml{.extra = "damping: {form: coulomb}\n"}.text(), C,
       {"bad.yaml: damping.form: must be one of: viscous, local, got 'coulomb' (line 9)"}},
      // Lattice site counts are whole numbers in [1, 200].
      {"lattice n not whole", Yaml{.lattice = "{n: [3, 3.5, 3], spacing: 5.0e-3}"}.text(), C,
       {"bad.yaml: particles.lattice.n: must be whole numbers"}},
      {"lattice n zero", Yaml{.lattice = "{n: [0, 3, 3], spacing: 5.0e-3}"}.text(), C,
       {"bad.yaml: particles.lattice.n[0]: must be in [1, 200], got 0 (line 3)"}},
      {"grading percent_finer shorter than diameters",
       Yaml{.grading = "{diameters: [3.0e-3, 4.0e-3, 4.5e-3], percent_finer: [0, 100]}"}.text(), C,
       {"bad.yaml: particles.grading.percent_finer: must have as many items as 'diameters' (3)"}},
      // The curve's end points are checked by GradingCurve when the lattice is generated
      // (engine/generate/grading.cpp, std::invalid_argument); build_simulation rethrows any error
      // in making the particles as a ConfigError "<scene>: particles.lattice/grading: <message>".
      {"grading not starting at 0 %", Yaml{.grading = "{diameters: [3.0e-3, 4.5e-3], percent_finer: [10, 100]}"}.text(), C,
       {"bad.yaml: particles.lattice/grading: grading: diameters must be positive, percent_finer must start at 0 and end at 100"}},
      {"grading not ending at 100 %", Yaml{.grading = "{diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 90]}"}.text(), C,
       {"bad.yaml: particles.lattice/grading: grading: diameters must be positive, percent_finer must start at 0 and end at 100"}},
      {"grading diameters decreasing", Yaml{.grading = "{diameters: [4.5e-3, 3.0e-3], percent_finer: [0, 100]}"}.text(), C,
       {"bad.yaml: particles.lattice/grading: grading: diameters must increase strictly and percent_finer must not decrease"}},
      // The lattice generator refuses spheres larger than the spacing (they would overlap).
      {"lattice spacing below the largest diameter", Yaml{.lattice = "{n: [3, 3, 3], spacing: 4.0e-3}"}.text(), C,
       {"bad.yaml: particles.lattice/grading: lattice spacing 0.004 m is smaller than the largest diameter 0.0045 m"}},
      // Targets are compressive stresses, > 0.
      {"negative stress target",
       Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, -1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1}}"}.text(), C,
       {"bad.yaml: stages[0].target[1]: must be in (0, 1e+10] Pa, got -1.0e5 (line 8)"}},
      {"zero hold.max_duration",
       Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 0}}"}.text(), C,
       {"bad.yaml: stages[0].hold.max_duration: must be in (0, 1e+06] s, got 0"}},
      {"negative hold.creep_rate",
       Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1, creep_rate: -1.0e-5}}"}.text(), C,
       {"bad.yaml: stages[0].hold.creep_rate: must be in [0, 1000] 1/s, got -1.0e-5"}},
      {"zero hold.creep_window",
       Yaml{.stages = "\n  - {name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1, creep_rate: 1.0e-5, creep_window: 0}}"}.text(), C,
       {"bad.yaml: stages[0].hold.creep_window: must be in (0, 1e+06] s, got 0"}},
      {"unknown stage type", Yaml{.stages = "\n  - {name: a, type: cyclic, duration: 1}"}.text(), C,
       {"bad.yaml: stages[0].type: must be one of: strain_rate, stress, stress_path, control, got 'cyclic' (line 8)"}},
      // The control stage: every new key.
      {"two controls", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0.1, stress: 1.0e5}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}}"}.text(), C,
       {"bad.yaml: stages[0].control.xx.stress: a component takes one control, not both strain_rate and stress"}},
      {"missing axis", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0.1}, yy: {strain_rate: 0}}}"}.text(), C,
       {"bad.yaml: stages[0].control.zz: missing (a mapping)"}},
      {"follow without constraint", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: follow, yy: {strain_rate: 0}, zz: {strain_rate: 0.1}}}"}.text(), C,
       {"bad.yaml: stages[0].control: a component is set to follow, but no constraint (constant_volume or constant_mean_stress) is given"}},
      {"shear follows", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: follow, yy: {strain_rate: 0}, zz: {strain_rate: 0.1}, xy: follow}, constraint: {type: constant_volume}}"}.text(), C,
       {"bad.yaml: stages[0].control: xy cannot follow a constraint: only the axes xx, yy, zz can"}},
      {"volume leaves all free", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: follow, yy: follow, zz: follow}, constraint: {type: constant_volume}}"}.text(), C,
       {"bad.yaml: stages[0].control: constant_volume with all three axes following leaves the split between them free: control one axis"}},
      {"mean stress one follower", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: follow, yy: {strain_rate: 0}, zz: {strain_rate: 0.1}}, constraint: {type: constant_mean_stress, mean_stress: 1.0e5}}"}.text(), C,
       {"bad.yaml: stages[0].control: constant_mean_stress needs exactly two axes that follow it (one axis leads at a strain rate); 1 follow"}},
      {"mean stress b out of range", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: follow, yy: follow, zz: {strain_rate: 0.1}}, constraint: {type: constant_mean_stress, mean_stress: 1.0e5, b: 1.5}}"}.text(), C,
       {"bad.yaml: stages[0].constraint.b: must be in [0, 1], got 1.5 (line 8)"}},
      {"cyclic stress on a strain component", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}, cyclic: {component: xy, amplitude: 1.0e4, period: 0.02}}"}.text(), C,
       {"bad.yaml: stages[0].cyclic.component: xy must be stress-controlled in control to cycle its stress"}},
      {"deviator of a shear", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0}, xy: {stress: 0}}, cyclic: {component: xy, quantity: deviator, amplitude: 1.0e4, period: 0.02}}"}.text(), C,
       {"bad.yaml: stages[0].cyclic.quantity: deviator cycles an axis (xx, yy or zz), not xy"}},
      {"double amplitude without cycles", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0.1}}, until: {double_amplitude_strain: 0.05}}"}.text(), C,
       {"bad.yaml: stages[0].until.double_amplitude_strain: needs a cyclic loading (the stage's cyclic key)"}},
      {"unknown component", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {strain_rate: 0}, yy: {strain_rate: 0}, zz: {strain_rate: 0.1}, yx: {stress: 0}}}"}.text(), C,
       {"bad.yaml: stages[0].control: unknown key 'yx' (line 8) (did you mean 'xx'?)"}},
      {"strain_rate with 2 items", Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1], duration: 1.0e-4}"}.text(), C,
       {"bad.yaml: stages[0].strain_rate: must be a list of 3 numbers in [-1000, 1000], got 2 items (line 8)"}},
      // Stage names identify stages in the results, so they must be unique; the second one is named.
      {"duplicate stage names", Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 1.0e-4}" + stress_stage}.text(), C,
       {"bad.yaml: stages[1].name: duplicate stage name 'a'"}},
      // Coulomb friction needs a tangential spring.
      {"friction > 0 with ks = 0", Yaml{.material = "{kn: 1.0e6, ks: 0, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.ks: must be > 0 when friction > 0"}},
      // --- contact laws (engine/config/contact_keys.cpp) --------------------------------------
      // Each law reads its own stiffness keys; another law's key is refused, naming the law it
      // belongs to and the keys this one reads (not silently ignored). The lists of laws are
      // matched up to their ends: a law added to AnyContactLaw is named after these.
      {"hertz_mindlin with kn", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, kn: 1.0e6, friction: 0.5}",
                                     .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.kn: belongs to material.law: linear", "; law hertz_mindlin reads material.young_modulus and material.poisson_ratio"}},
      {"hertz_mindlin with ks", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, ks: 1.0e6, friction: 0.5}",
                                     .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.ks: belongs to material.law: linear", "; law hertz_mindlin reads material.young_modulus and material.poisson_ratio"}},
      {"linear with young_modulus", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, young_modulus: 1.0e9, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.young_modulus: belongs to material.law: hertz_mindlin; law linear reads material.kn"}},
      {"an unknown law", Yaml{.material = "{law: hertz, young_modulus: 1.0e9, poisson_ratio: 0.3, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.law: must be one of: linear, hertz_mindlin", ", got 'hertz' (line 5)"}},
      // Rolling resistance is an elastic-plastic spring: its cap mu_r R* f_n needs its stiffness.
      // rolling_stiffness is optional otherwise, so the message says why it is needed here.
      {"rolling_friction > 0 without rolling_stiffness", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, rolling_friction: 0.1}"}.text(), C,
       {"bad.yaml: material.rolling_stiffness: missing (a number in (0, 1e+12] N/m); needed because material.rolling_friction = 0.1 > 0"}},
      // The same, misspelt: the look-alike is still pointed at.
      {"rolling_friction > 0 with 'rolling_stifness'",
       Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, rolling_friction: 0.1, rolling_stifness: 1.0e5}"}.text(), C,
       {"bad.yaml: material.rolling_stiffness: missing (a number in (0, 1e+12] N/m); found 'rolling_stifness' (line 5): "
        "did you mean 'rolling_stiffness'?; needed because material.rolling_friction = 0.1 > 0"}},
      {"rolling_stiffness without rolling_friction", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, rolling_stiffness: 1.0e5}"}.text(), C,
       {"bad.yaml: material.rolling_stiffness: is read only when rolling_friction > 0; give both or neither"}},
      // Rolling resistance acts through the contact's spins, which a frictionless kernel does not integrate.
      {"rolling_friction with friction 0",
       Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0, rolling_friction: 0.1, rolling_stiffness: 1.0e5}"}.text(), C,
       {"bad.yaml: material.rolling_friction: no law linear combines material.rolling_friction = 0.1 with material.contact_damping = 0 "
        "and material.friction = 0 (the engine is compiled for the laws of AnyContactLaw, contact/contact_law.hpp)"}},
      // Contact dashpots (contact/contact_dashpot.hpp): zeta < 1, and not with rolling resistance (no such law).
      {"contact_damping 1", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, contact_damping: 1}"}.text(), C,
       {"bad.yaml: material.contact_damping: must be in [0, 1), got 1 (line 5)"}},
      {"contact_damping with rolling_friction",
       Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, rolling_friction: 0.1, rolling_stiffness: 1.0e5, contact_damping: 0.05}"}.text(), C,
       {"bad.yaml: material.contact_damping: no law linear combines material.contact_damping = 0.05 and material.friction = 0.5 and "
        "material.rolling_friction = 0.1 (the engine is compiled for the laws of AnyContactLaw, contact/contact_law.hpp)"}},
      {"negative rolling_friction", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5, rolling_friction: -0.1}"}.text(), C,
       {"bad.yaml: material.rolling_friction: must be in [0, 10], got -0.1 (line 5)"}},
      // nu = 0.5 is the incompressible limit; the range is open there (it printed "(-1, 0.5]" and
      // then refused 0.5 by a second check, "must be below 0.5, got 0.500000").
      {"poisson_ratio 0.5", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.5, friction: 0.5}",
                                 .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.poisson_ratio: must be in (-1, 0.5), got 0.5 (line 5)"}},
      {"poisson_ratio -1", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: -1, friction: 0.5}",
                                .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.poisson_ratio: must be in (-1, 0.5), got -1 (line 5)"}},
      {"hertz_mindlin without poisson_ratio", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, friction: 0.5}",
                                                   .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.poisson_ratio: missing (a number in (-1, 0.5))"}},
      {"zero young_modulus", Yaml{.material = "{law: hertz_mindlin, young_modulus: 0, poisson_ratio: 0.3, friction: 0.5}",
                                  .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: material.young_modulus: must be in (0, 1e+13] Pa, got 0 (line 5)"}},
      // Viscous damping is a fraction of the critical damping 2 sqrt(k m) of a constant stiffness k,
      // which Hertz does not have; explicitly and by default (the default form is viscous).
      {"viscous damping with hertz_mindlin", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, friction: 0.5}",
                                                  .extra = "damping: {form: viscous}\n"}.text(), C,
       {"bad.yaml: damping.form: viscous (the default) scales the damping with a contact stiffness, and material.law hertz_mindlin has none: "
        "use damping: {form: local}"}},
      {"hertz_mindlin with the default damping", Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, friction: 0.5}"}.text(), C,
       {"bad.yaml: damping.form: viscous (the default)", "use damping: {form: local}"}},
      // A time step above 0.2 x the Rayleigh step: E = 1e11 Pa with 3 mm spheres gives ~1.3 us.
      {"time step above 0.2 x the Rayleigh step",
       Yaml{.material = "{law: hertz_mindlin, young_modulus: 1.0e11, poisson_ratio: 0.3, friction: 0.5}", .numerics = "{time_step: 1.0e-6}",
            .extra = "damping: {form: local}\n"}.text(), C,
       {"bad.yaml: numerics.time_step = 1e-06 s", "the Rayleigh time pi r_min sqrt(rho/G) / (0.1631 nu + 0.8766)"}},
      // --- particle sources ----------------------------------------------------------------------
      {"particles with both lattice and csv", Yaml{.grading = "{diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n  csv: p.csv"}.text(), C,
       {"bad.yaml: particles: give exactly one of 'lattice', 'csv' or 'state'"}},
      {"particles with no source", "name: bad\nparticles: {}\nmaterial: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                   "numerics: {time_step: 1.0e-6}\nstages: [{name: a, type: strain_rate, strain_rate: [0, 0, 0], duration: 1}]\n", C,
       {"bad.yaml: particles: give exactly one of 'lattice', 'csv' or 'state'"}},
      // --- not a scene at all -------------------------------------------------------------------
      {"empty text", "", C, {"bad.yaml: the file is empty"}},
      {"only a comment", "# nothing here\n", C, {"bad.yaml: the file is empty"}},
      {"a scalar document", "hello\n", C, {"bad.yaml: the file must be a mapping of keys, got 'hello'"}},
      {"a list document", "- a\n- b\n", C, {"bad.yaml: the file must be a mapping of keys, got a list"}},
      // An unclosed flow mapping on line 5: yaml-cpp reports where it noticed (line 6).
      {"invalid YAML syntax", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5"}.text(), C,
       {"bad.yaml: not valid YAML:", "line 6"}},
      // --- numbers that are not finite ---------------------------------------------------------
      // 1e400 overflows a double: yaml-cpp refuses to convert it, so it is "not a number".
      {"huge number 1e400", Yaml{.material = "{kn: 1e400, ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: must be a number [N/m], got '1e400' (line 5)"}},
      {"huge number 1e400 in a list", Yaml{.stages = "\n  - {name: a, type: stress, target: [1e400, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1}}"}.text(), C,
       {"bad.yaml: stages[0].target[0]: must be a number, got '1e400' (line 8)"}},
      // .nan is a valid YAML float, but NaN compares false with every bound: out of range.
      {"NaN as a number", Yaml{.material = "{kn: .nan, ks: 1.0e6, friction: 0.5}"}.text(), C,
       {"bad.yaml: material.kn: must be in (0, 1e+12] N/m, got .nan (line 5)"}},
      {".inf time step", Yaml{.numerics = "{time_step: .inf}"}.text(), C,
       {"bad.yaml: numerics.time_step: must be in (0, 1] s, got .inf (line 6)"}},
      {"NaN in a list", Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, .nan, 0.1], duration: 1.0e-4}"}.text(), C,
       {"bad.yaml: stages[0].strain_rate[1]: must be in [-1000, 1000] 1/s, got .nan (line 8)"}},
      // --- numbers read one way: decimal; no leading zeros, no other bases, no underflow --
      // `010` was octal 8 where yaml-cpp read an integer (seeds, --set) and 10 in a list of numbers.
      {"a leading zero in an integer", Yaml{.lattice = "{n: [3, 3, 3], spacing: 5.0e-3, seed: 010}"}.text(), C,
       {"bad.yaml: particles.lattice.seed: must be an integer", "got '010' (line 3): a leading zero is refused", "write 10"}},
      {"a leading zero in a list of numbers", Yaml{.lattice = "{n: [010, 3, 3], spacing: 5.0e-3, seed: 1}"}.text(), C,
       {"bad.yaml: particles.lattice.n[0]: must be a number, got '010' (line 3): a leading zero is refused", "write 10"}},
      {"a leading zero in a number", Yaml{.numerics = "{time_step: 01.0e-6}"}.text(), C,
       {"bad.yaml: numerics.time_step: must be a number [s], got '01.0e-6' (line 6): a leading zero is refused", "write 1.0e-6"}},
      {"a hexadecimal integer", Yaml{.lattice = "{n: [3, 3, 3], spacing: 5.0e-3, seed: 0x10}"}.text(), C,
       {"bad.yaml: particles.lattice.seed: must be an integer", "got '0x10' (line 3): hexadecimal and octal forms are refused"}},
      // 1e-400 read as 0 turned the damping off without a word.
      {"a number that underflows to 0", Yaml{.extra = "damping: {form: viscous, translational: 1e-400}\n"}.text(), C,
       {"bad.yaml: damping.translational: must be a number, got '1e-400' (line 9): below the smallest positive double"}},
      {"a leading zero in a path state", Yaml{.stages = "\n  - {name: a, type: stress_path, rate: 2.0e6, path: [[0120000, 90000, 90000]]}"}.text(), C,
       {"bad.yaml: stages[0].path[0]: stresses must be positive numbers (Pa)", "'0120000': a leading zero is refused"}},
      {"a leading zero in a repeat count", Yaml{.stages = "\n  - {name: a, type: stress_path, rate: 2.0e6, path: [TC1, {repeat: 010, path: [TC2, TC1]}]}"}.text(), C,
       {"bad.yaml: stages[0].path[1].repeat: must be an integer in [1, 100000]", "'010': a leading zero is refused"}},
      // --- control stages: targets a packing can reach --------------------------------
      {"a tensile axial stress target", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {stress: -5.0e4}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}}"}.text(), C,
       {"bad.yaml: stages[0].control.xx.stress: is tensile (compression is positive), got -50000 Pa", "allowed: >= 0 Pa"}},
      {"a cyclic stress that swings into tension", Yaml{.stages = "\n  - {name: a, type: control, duration: 1, control: {xx: {stress: 1.0e5}, yy: {strain_rate: 0}, zz: {strain_rate: 0}}, cyclic: {component: xx, amplitude: 1.5e5, period: 0.1}}"}.text(), C,
       {"bad.yaml: stages[0].cyclic.amplitude: takes xx's stress target 100000 Pa to -50000 Pa, a tension", "allowed: at most 100000 Pa"}},
      // --- checkpoints every step: 33 steps/s, 30 MB after 1,877 steps ----------------------
      {"a checkpoint every step", Yaml{.extra = "output: {checkpoint_interval: 1}\n"}.text(), C,
       {"bad.yaml: output.checkpoint_interval: must be 0 (none by steps) or at least 10, got 1", "each checkpoint copies the whole result"}},
      {"a checkpoint every 9 steps", Yaml{.extra = "output: {checkpoint_interval: 9}\n"}.text(), C,
       {"bad.yaml: output.checkpoint_interval: must be 0 (none by steps) or at least 10, got 9"}},
      // --- step counts: every duration a stage turns into steps gives 1 ... 1e12 ---------
      // numerics.time_step = 1e-21 with a 0.01 s stage overflowed the count: 0 steps, exit 0.
      {"a time step so small that the steps overflow", Yaml{.numerics = "{time_step: 1.0e-21}",
       .stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 0.01}"}.text(), C,
       {"bad.yaml: stages[0].duration: 0.01 s at numerics.time_step = 1e-21 s is 1e+19 steps, more than the 1e+12 a run may take"}},
      {"a stage shorter than half a time step", Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 4.0e-7}"}.text(), C,
       {"bad.yaml: stages[0].duration: 4e-07 s is less than half of numerics.time_step = 1e-06 s: the stage would get 0 steps"}},
      // The smallest positive double: duration / time_step is infinite.
      {"a denormal time step", Yaml{.numerics = "{time_step: 4.9e-324}"}.text(), C,
       {"bad.yaml: stages[0].duration: 0.0001 s at numerics.time_step = 4.94066e-324 s is inf steps"}},
      // Stages of 6e11 steps each are allowed one by one, not together.
      {"stages that together take more than 1e12 steps",
       Yaml{.stages = "\n  - {name: a, type: strain_rate, strain_rate: [0, 0, 0], duration: 6.0e5}"
                      "\n  - {name: b, type: strain_rate, strain_rate: [0, 0, 0], duration: 6.0e5}"}.text(), C,
       {"bad.yaml: stages: together up to 1.2e+12 steps at numerics.time_step = 1e-06 s, more than the 1e+12 a run may take"}},
      // --- what YAML would read in silence, or only with a bare message ------------------------
      // A merge key: yaml-cpp does not merge, it reads a key named "<<".
      {"a merge key", "base: &b {kn: 1.0e6, ks: 1.0e6}\n" + Yaml{.material = "{<<: *b, friction: 0.5}"}.text(), C,
       {"bad.yaml: material: a merge key '<<' (line 6) is not supported: write the keys it would merge out in full"}},
      // A second document after '---' would be ignored.
      {"a second YAML document", Yaml{}.text() + "---\nname: other\n", C,
       {"bad.yaml: holds 2 YAML documents (separated by '---'); a scene or study is one"}},
      // A control character (an escape sequence pasted into a name) and a byte that is not UTF-8.
      {"a control character in a name", "name: bad\x1b[31m\n" + Yaml{}.text().substr(Yaml{}.text().find('\n') + 1), C,
       {"bad.yaml: line 1: the control character 0x1b (not allowed in a scene or study)"}},
      {"a name that is not UTF-8", Yaml{}.text() + "# caf\xe9\n", C,
       {"bad.yaml: line 9: the byte 0xe9, not UTF-8 text (save the file as UTF-8)"}},
      {"a NUL byte", Yaml{}.text() + std::string("# x\0y\n", 6), C, {"bad.yaml: line 9: a NUL byte (a binary file?)"}},
      // Deep nesting: 40 levels of flow sequences (a scene nests a few).
      {"nesting 40 levels deep", Yaml{.extra = "x: " + std::string(40, '[') + std::string(40, ']') + "\n"}.text(), C,
       {"bad.yaml: nested more than 32 levels deep"}},
      // Deeper than yaml-cpp's own recursion guard: the parser's events are measured as they come
      // (config/yaml_section.cpp), so the 33rd level is refused before the guard is reached.
      {"nesting 5000 levels deep", Yaml{.extra = "x: " + std::string(5000, '[') + std::string(5000, ']') + "\n"}.text(), C,
       {"bad.yaml: nested more than 32 levels deep (line 9"}},
      // A key of 17 MiB: refused by its size before YAML allocates for it.
      {"a 17 MiB key", Yaml{.extra = std::string(17u << 20, 'k') + ": 1\n"}.text(), C,
       {"bad.yaml: 17 MiB, more than the 16 MiB a scene or study file may hold"}},
  };
}

}  // namespace

TEST_CASE("the base of the bad-scene catalogue is a valid scene", "[config]") {
  // Each bad scene differs from this one in one part only, so the error must come from that part.
  const SceneConfig scene = scene_from_text(Yaml{}.text(), "bad.yaml");
  CHECK(scene.name == "bad");
  CHECK(build_simulation(scene).particles().size() == 27);
}

TEST_CASE("bad scenes are refused with a message naming file, key path and what is allowed", "[config]") {
  const auto cases = catalogue();
  REQUIRE(cases.size() >= 20);
  for (const BadScene& c : cases) {
    INFO("case: " << c.what << "\n--- yaml ---\n" << c.yaml << "------------");
    const Outcome o = refuse(c.yaml);
    INFO("message: " << o.message);
    CHECK(o.threw);
    if (!o.threw) continue;
    CHECK((o.kind == c.kind));
    // Every ConfigError starts with the file name, so a user with many scenes knows which one.
    if (c.kind == Kind::Config) CHECK(o.message.rfind("bad.yaml: ", 0) == 0);
    for (const std::string& e : c.expected) CHECK_THAT(o.message, Catch::Matchers::Contains(e));
  }
}

TEST_CASE("every stage type's step counts are range-checked, naming the keys", "[config][steps]") {
  // Each duration a stage turns into a step count (engine/run/run_scene.cpp: steps_in): a
  // strain-rate stage's duration, a stress stage's hold.max_duration, a stress path's legs (from
  // rate and the path's states). Each must give at least one step and at most max_scene_steps, at
  // any time step: a stage type added without its check fails here. Refused by scene_from_text,
  // before any particle exists.
  struct Stage {
    std::string yaml, key;  // one stage; the key the message names for it
    bool can_be_empty;      // a duration can be below one step (path legs run at least one step)
  };
  const std::vector<Stage> stages = {
      {"{name: a, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 0.01}", "stages[0].duration", true},
      {"{name: a, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 0.01}}", "stages[0].hold.max_duration", true},
      {"{name: a, type: stress_path, rate: 2.0e6, path: [TC1, {repeat: 3, path: [TC2, TC1]}]}", "stages[0].path", false},
  };
  REQUIRE(stages.size() == 3);  // StageConfig::Type has three values
  for (const Stage& st : stages) {
    INFO(st.yaml);
    CHECK_NOTHROW(scene_from_text(Yaml{.stages = "\n  - " + st.yaml}.text(), "bad.yaml"));
    for (const char* dt : {"1.0e-21", "1.0e-100", "4.9e-324"}) {  // 1e19 steps and more, up to infinity
      INFO("time_step " << dt);
      const Outcome o = refuse(Yaml{.numerics = std::string("{time_step: ") + dt + "}", .stages = "\n  - " + st.yaml}.text());
      CHECK(o.threw);
      CHECK_THAT(o.message, Catch::Matchers::StartsWith("bad.yaml: " + st.key + ": ") &&
                                Catch::Matchers::Contains("at numerics.time_step = ") &&
                                Catch::Matchers::Contains("more than the 1e+12 a run may take"));
    }
    if (!st.can_be_empty) continue;
    // A duration of 0.4 time steps rounds to 0 steps.
    std::string shortened = st.yaml;
    shortened.replace(shortened.find("0.01}"), 4, "4.0e-7");
    const Outcome o = refuse(Yaml{.stages = "\n  - " + shortened}.text());
    CHECK(o.threw);
    CHECK_THAT(o.message, Catch::Matchers::StartsWith("bad.yaml: " + st.key + ": 4e-07 s is less than half of numerics.time_step") &&
                              Catch::Matchers::Contains("the stage would get 0 steps"));
  }
  // The bound itself: exactly 1e12 steps are allowed, 1e12 + 1 are not (integer-valued doubles).
  CHECK(max_scene_steps == 1'000'000'000'000);
  CHECK_NOTHROW(scene_from_text(Yaml{.numerics = "{time_step: 1.0e-6}",
                                     .stages = "\n  - {name: a, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0e6}"}.text(), "bad.yaml"));
  CHECK_THROWS_AS(scene_from_text(Yaml{.numerics = "{time_step: 0.999999999999e-6}",
                                       .stages = "\n  - {name: a, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0e6}"}.text(), "bad.yaml"),
                  ConfigError);
  // The count the run uses is the one checked (nearest whole step).
  CHECK(steps_in(1.0e-4, 1.0e-6) == 100);
  CHECK(steps_in(5.0e-7, 1.0e-6) == 1);
}

TEST_CASE("scene files that cannot be read are refused naming the file", "[config]") {
  const std::string dir = test::scratch_dir("bad_scene_files");
  SECTION("an empty file") {
    // A zero-byte file parses to a null YAML document.
    test::write_text(dir + "/empty.yaml", "");
    REQUIRE_THROWS_MATCHES(load_scene(dir + "/empty.yaml"), ConfigError,
                           Catch::Matchers::Message(dir + "/empty.yaml: the file is empty"));
  }
  SECTION("a directory") {
    REQUIRE_THROWS_MATCHES(load_scene(dir), ConfigError,
                           Catch::Matchers::Message(dir + ": is a directory, expected a YAML file"));
  }
  SECTION("a nonexistent file") {
    REQUIRE_THROWS_MATCHES(load_scene(dir + "/missing.yaml"), ConfigError,
                           Catch::Matchers::Message(dir + "/missing.yaml: no such file"));
  }
  SECTION("a file with a YAML error names the file and the line") {
    test::write_text(dir + "/broken.yaml", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: 0.5"}.text());
    REQUIRE_THROWS_WITH(load_scene(dir + "/broken.yaml"),
                        Catch::Matchers::StartsWith(dir + "/broken.yaml: not valid YAML") && Catch::Matchers::Contains("line 6"));
  }
  SECTION("a bad value in a file names the file and the key") {
    test::write_text(dir + "/bad.yaml", Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, friction: -1}"}.text());
    REQUIRE_THROWS_WITH(load_scene(dir + "/bad.yaml"),
                        Catch::Matchers::Contains(dir + "/bad.yaml: material.friction: must be in [0, 10], got -1 (line 5)"));
  }
}

TEST_CASE("a time step above the allowed fraction of the critical step is refused with both numbers", "[config]") {
  // The paper's material (kn = 1e6 N/m, density 2650) with 3 ... 4.5 mm spheres: the critical step
  // 2 sqrt(m_min/kn) lies between the values of a 3 mm sphere (1.224e-5 s) and a 4.5 mm sphere,
  // so dt = 1e-4 s is far above 0.2 x critical (~2.5e-6 s).
  const double pi = 3.14159265358979323846;
  const auto step_of = [&](double d) { return 2 * std::sqrt(2650 * pi / 6 * d * d * d / 1e6); };
  const SceneConfig ok = scene_from_text(Yaml{.numerics = "{time_step: 1.0e-7}"}.text(), "crit.yaml");
  const double dt_crit = critical_time_step(ok.material.law, build_simulation(ok).particles(), 2650);
  REQUIRE(dt_crit >= step_of(3e-3));
  REQUIRE(dt_crit <= step_of(4.5e-3));

  std::ostringstream crit_text, allowed_text;
  crit_text << dt_crit;             // the engine prints with the default stream format
  allowed_text << 0.2 * dt_crit;
  const SceneConfig bad = scene_from_text(Yaml{.numerics = "{time_step: 1.0e-4}"}.text(), "crit.yaml");
  REQUIRE_THROWS_MATCHES(build_simulation(bad), ConfigError,
                         Catch::Matchers::Predicate<std::exception>(
                             [&](const std::exception& e) {
                               const std::string m = e.what();
                               return m.find("crit.yaml: numerics.time_step = 0.0001 s") != std::string::npos &&
                                      m.find("critical step 2 sqrt(m_min/kn) = " + crit_text.str() + " s") != std::string::npos &&
                                      m.find("0.2 x critical time step = " + allowed_text.str() + " s") != std::string::npos &&
                                      m.find("max_time_step_fraction") != std::string::npos;
                             },
                             "names the time step, the critical step and the allowed step"));

  // The rule is exactly dt <= fraction x dt_crit: just below is accepted, just above refused,
  // and raising max_time_step_fraction on purpose accepts dt = 1e-4 (< 10 x 1.2e-5).
  const auto scene_with = [&](const std::string& numerics) {
    return scene_from_text(Yaml{.numerics = numerics}.text(), "crit.yaml");
  };
  std::ostringstream below, above;
  below.precision(17);
  above.precision(17);
  below << "{time_step: " << 0.2 * dt_crit * (1 - 1e-9) << "}";
  above << "{time_step: " << 0.2 * dt_crit * (1 + 1e-9) << "}";
  CHECK_NOTHROW(build_simulation(scene_with(below.str())));
  CHECK_THROWS_AS(build_simulation(scene_with(above.str())), ConfigError);
  CHECK_NOTHROW(build_simulation(scene_with("{time_step: 1.0e-4, max_time_step_fraction: 10}")));
}

TEST_CASE("a misspelt required key gets a did-you-mean suggestion", "[config]") {
  // 'fricton' is one letter from 'friction'. material.friction is required and read before the
  // unknown-key check, so the error is "missing"; it must point at the present, unread
  // look-alike with its line (line 5 of the catalogue's scene).
  const Outcome o = refuse(Yaml{.material = "{kn: 1.0e6, ks: 1.0e6, fricton: 0.5}"}.text());
  INFO(o.message);
  CHECK((o.kind == Kind::Config));
  CHECK(o.message == "bad.yaml: material.friction: missing (a number in [0, 10]); found 'fricton' (line 5): did you mean 'friction'?");
  // A key that is read (declared) is never offered as the look-alike of another: 'kn' and 'ks'
  // are one substitution apart, and with ks missing the present kn is not suggested.
  const Outcome ks = refuse(Yaml{.material = "{kn: 1.0e6, friction: 0.5}"}.text());
  CHECK(ks.message == "bad.yaml: material.ks: missing (a number in [0, 1e+12] N/m); needed because material.friction = 0.5 > 0");
}

TEST_CASE("a misspelt optional section gets a did-you-mean suggestion", "[config]") {
  // 'dampign' is a transposition of 'damping'. damping, servo and output are declared even when
  // absent (Section::optional_child), so finish() can suggest them.
  const Outcome o = refuse(Yaml{.extra = "dampign: {form: local}\n"}.text());
  INFO(o.message);
  CHECK((o.kind == Kind::Config));
  CHECK_THAT(o.message, Catch::Matchers::StartsWith("bad.yaml: top level: unknown key 'dampign' (line 9)"));
  CHECK_THAT(o.message, Catch::Matchers::Contains("did you mean 'damping'?"));
  // Absent optional sections take every default; present but empty ones too.
  const SceneConfig absent = scene_from_text(Yaml{}.text(), "bad.yaml");
  const SceneConfig empty = scene_from_text(Yaml{.extra = "damping: {}\nservo: {}\noutput: {}\n"}.text(), "bad.yaml");
  CHECK((absent.damping.form == Damping::Form::Viscous));
  CHECK(absent.damping.translational == 0.05);
  CHECK(absent.servo.gain == 1e-3);
  CHECK(absent.output.interval_steps == 1000);
  CHECK(empty.resolved_yaml == absent.resolved_yaml);
}

TEST_CASE("a particle-making error names the scene file and the particle source", "[config]") {
  // The grading end points are checked only by GradingCurve when the particles are made; the
  // message is the generator's, prefixed by the scene file and "particles.lattice/grading" (the
  // engine cannot tell which of the two keys is at fault, so it names both).
  const Outcome o = refuse(Yaml{.grading = "{diameters: [3.0e-3, 4.5e-3], percent_finer: [10, 100]}"}.text());
  INFO(o.message);
  CHECK((o.kind == Kind::Config));
  CHECK(o.message ==
        "bad.yaml: particles.lattice/grading: grading: diameters must be positive, percent_finer must start at 0 and end at 100");
  // A CSV source: the key is particles.csv, then the CSV reader's message naming its file and line.
  const std::string folder = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene";
  const SceneConfig bad_csv = load_scene(folder + "/bad_csv_scene.yaml");
  REQUIRE_THROWS_MATCHES(build_simulation(bad_csv), ConfigError,
                         Catch::Matchers::Message(folder + "/bad_csv_scene.yaml: particles.csv: " + bad_csv.particles.path +
                                                  ": line 3: radius must be > 0 m, got -0.002"));
}
