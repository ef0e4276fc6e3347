#pragma once
// A scene, parsed once from YAML into typed, validated structs. The engine never sees YAML.
#include <optional>
#include <string>
#include <vector>

#include "control/stress_path.hpp"
#include "control/stress_servo.hpp"
#include "core/types.hpp"
#include "dynamics/simulation.hpp"
#include "generate/grading.hpp"

namespace dem {

struct ParticleSource {
  enum class Kind { Lattice, Csv, State };
  Kind kind = Kind::Lattice;
  LatticeLayout lattice;
  std::vector<double> grading_diameters_m, grading_percent_finer;
  GradingCurve::Basis grading_basis = GradingCurve::Basis::Mass;
  std::string path;           // CSV file (x,y,z,radius per row) or saved state (HDF5), resolved against the scene folder
  Vec3 cell_m = Vec3::Zero(); // cell lengths for a CSV file
};

struct HoldCriteria {
  double stress_tolerance = 0.005;          // |sigma_kk - target_k| <= tolerance * |target_k| on every axis [-]
  double unbalanced_force_ratio = 1e-3;     // [-]
  std::int64_t check_interval_steps = 100;
  double max_duration_s = 10;               // the stage fails if the criteria do not hold by then
  // Creep: |ln(V_end / V_start)| / creep_window over the last whole window of the hold at most
  // this [1/s] (0: not checked). A loose packing that meets the force criteria can still creep
  // at constant stress for tenths of a second; an undrained test started then measures the creep.
  double creep_rate_per_s = 0;
  double creep_window_s = 0.01;
};

// A control stage's loading that oscillates: one component's stress (from its value in
// `control`), the deviator q = s_kk - (other two axes)/2 of an axis (from q at the stage start),
// or its strain (a sine of the strain, on top of its strain rate in `control`).
struct CyclicLoading {
  enum class Quantity { Stress, Deviator, Strain };
  int component = -1;  // index into CellControl::component; -1: no cyclic loading
  Quantity quantity = Quantity::Stress;
  double amplitude = 0;  // Pa, or strain
  double period_s = 0;
};

// When a control stage ends before its duration (each criterion off at 0).
struct StopCriteria {
  int component = -1;                    // whose strain `strain` limits
  double strain = 0;                     // |axial true strain or engineering shear strain| since the stage start
  double pore_pressure_ratio = 0;        // r_u = 1 - p / p0, p0 the mean stress at the stage start
  double double_amplitude_strain = 0;    // max - min of the cyclic component's strain within a cycle
};

struct StageConfig {
  enum class Type { StrainRate, Stress, StressPath, Control };
  std::string name;
  Type type = Type::StrainRate;
  bool reset_strain = false;      // strains measured from the start of this stage
  // strain_rate stage
  Vec3 strain_rate_per_s = Vec3::Zero();
  double duration_s = 0;
  // stress stage: ramp every axis from its stress at the stage start to `target` at `rate`, then hold
  Vec3 target_Pa = Vec3::Zero();
  double stress_rate_Pa_per_s = 0;
  double max_strain_rate_per_s = 1;
  HoldCriteria hold;
  // stress_path stage: straight legs between states at constant mean stress, at `rate`
  double mean_stress_Pa = 1e5;   // p
  double stress_ratio = 1.24;    // R = sigma_max / sigma_min of the named TC/TE states
  std::vector<PathItem> path;
  std::string path_text;         // the path as written (for the resolved scene)
  bool zero_shear_stress = false; // stress and stress_path stages: the cell shears so that the shear stresses stay at zero
  // control stage: every component of the cell (control/stress_servo.hpp) for `duration`
  CellControl control;
  CyclicLoading cyclic;
  StopCriteria until;
  std::string control_text;      // its keys as written (for the resolved scene)
};

struct OutputConfig {
  std::int64_t interval_steps = 1000;  // time-series row every N steps (and at every stage end)
  std::int64_t flush_rows = 20;        // the file is flushed to disk every N rows
  // Checkpoints (run/checkpoint.hpp): every N steps (0: not by steps) and every S seconds of wall
  // time (0: not by time). They do not change the result, so they are not in resolved_yaml.
  std::int64_t checkpoint_interval_steps = 0;
  double checkpoint_wall_time_s = 600;
  // Particle frames for ParaView (io/h5md.hpp) every N steps (0: only the start, the checkpoints
  // and the end), with the contact network if `frames_contacts`.
  std::int64_t frames_interval_steps = 0;
  bool frames_contacts = false;
};

// Each checkpoint copies the whole result so far: a checkpoint every few steps costs more than the
// steps (every step: 33 steps/s and 30 MB after 1,877 steps), so an interval below this is refused.
inline constexpr std::int64_t min_checkpoint_interval_steps = 10;

// A file a run reads: `key` is the scene key naming it ("particles.csv", "particles.state") or
// "the scene file"; `path` is resolved against the scene's folder.
struct InputFile {
  std::string key, path;
};

struct SceneConfig {
  std::string file;           // the YAML file it came from
  std::string name;
  ParticleSource particles;
  Material material;
  Damping damping;
  double time_step_s = 1e-6;
  double max_time_step_fraction = 0.2;  // largest allowed dt / critical dt
  double max_energy_error = 0.05;       // a run stops when its energy closure error exceeds this
  double verlet_skin_m = 2e-4;
  ServoSettings servo;
  OutputConfig output;
  std::vector<StageConfig> stages;
  std::string resolved_yaml;  // every key with its value after defaults, recorded in the result
  std::vector<InputFile> input_files;  // the scene file and every file a key names (Section::file_path)
};

// The steps a stage runs for `duration_s` at time step `dt_s` (the nearest whole number): a
// strain-rate stage's duration, a stress stage's hold.max_duration, a stress-path leg (at least 1).
std::int64_t steps_in(double duration_s, double dt_s);
// The most steps a scene may ask for, per stage and in all: 1e12. Far more than any run can do
// (at the 2.9e5 steps/s of 64 spheres on one core, 40 days; an 8,000-sphere sample is ~100 times
// slower), and far below 2^53 (9.0e15), so every step number and step x time_step converts to a
// double exactly, and sums of counts cannot overflow an int64. load_scene refuses a scene whose
// stages would run 0 steps or more than this, naming the keys.
inline constexpr std::int64_t max_scene_steps = 1'000'000'000'000;

// Reads and validates a scene file; throws ConfigError naming file, key path and allowed values.
// `overrides`: (key path, YAML value) pairs applied before validation (`dem run --set`).
SceneConfig load_scene(const std::string& file, const std::vector<std::pair<std::string, std::string>>& overrides = {});
// The same from YAML text; `file` names it in error messages and resolves relative paths.
SceneConfig scene_from_text(const std::string& text, const std::string& file,
                            const std::vector<std::pair<std::string, std::string>>& overrides = {});

// The key reference (`dem keys`): every key with unit, allowed values, default and doc.
std::string scene_key_reference();

}  // namespace dem
