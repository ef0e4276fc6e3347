#pragma once
// Running a scene: building the simulation from its particle source, then its stages in order.
#include <array>
#include <csignal>
#include <functional>
#include <string>

#include "analysis/legs.hpp"  // LegRecord
#include "analysis/time_series.hpp"
#include "config/scene_config.hpp"
#include "dynamics/simulation.hpp"

namespace dem {

// The bytes of the scene's particle file (particles.csv or particles.state; "" for a lattice),
// read once: a run parses and hashes these same bytes, so a FIFO as the CSV file works and a file
// changed between the two cannot give a run the identity of other particles. Throws ConfigError
// naming the scene key (a directory, an unreadable file, a state file that is not a regular file:
// HDF5 seeks in it). A FIFO is waited for without blocking (io/particle_csv.hpp): when `stop` is
// given and becomes non-zero meanwhile, it throws RunInterrupted naming the signal and the file.
std::string read_particle_source(const SceneConfig& scene, const volatile std::sig_atomic_t* stop = nullptr);

// Builds the simulation of a scene. Refuses (ConfigError) a time step above
// max_time_step_fraction x the critical step, giving both numbers. The first form reads the
// particle file itself; the second parses `source_bytes` from read_particle_source.
Simulation build_simulation(const SceneConfig& scene);
Simulation build_simulation(const SceneConfig& scene, const std::string& source_bytes);

struct StageProgress {
  int stage = 0;
  double fraction = -1;  // of the stage, in [0, 1]; < 0 while holding for equilibrium (unknown end)
  std::string status;    // e.g. the current stress error while holding
};

// Where a run is inside a stage, with what the stage's loop carries from one step to the next:
// enough to continue the stage from the middle, bit for bit (run/checkpoint.hpp saves it).
struct StageCursor {
  int stage = 0;
  std::int64_t i = 0;  // the next iteration of the stage's loop (of the leg's loop on a stress path)
  // stress stages
  Vec3 from_Pa = Vec3::Zero();  // each axis' stress at the stage start, where its ramp begins
  double stress_error = 0, unbalanced = 1;
  std::int64_t creep_window_start = -1;  // the step count where the hold's creep window began (-1: none yet)
  double creep_volume_at_start = 0;      // the cell volume then [m^3]
  double creep_rate = -1;                // of the last whole window [1/s] (-1: none measured yet)
  AdaptiveServo::State servo;  // stress stages and paths
  // stress paths
  int leg = 0;
  std::int64_t done_steps = 0;
  Vec3 sum_sq = Vec3::Zero();  // of the leg so far
  double max_inertial_number = 0;
  Vec3 strain_at_leg_start = Vec3::Zero();
  // control stages
  double mean_stress_at_start = 0, deviator_at_start = 0;  // p0 of r_u, q0 of a cyclic deviator
  std::array<double, 6> strain_at_start{};                 // every component's strain at the stage start
  double cycle_low = 0, cycle_high = 0;                    // the cyclic strain's range in the current cycle
};

struct StageHooks {
  std::function<void(const Simulation&, const RowContext&)> row;          // at output steps and stage/leg ends
  std::function<void(const Simulation&)> frame;                           // every output.frames.interval steps (if set)
  std::function<void(const Simulation&, const StageProgress&)> progress;  // every few hundred steps
  std::function<void(const LegRecord&)> leg;                              // at each leg end of a stress path
  std::function<void(const std::string&)> warning;                        // e.g. inertial number above 1e-3
  std::function<void(const std::string&, const std::string&)> attribute;  // a result attribute, e.g. why a stage ended
  // Asked between two steps of a stage (never at its first step; not at all if checkpoint_due is
  // unset): if checkpoint_due says yes, checkpoint gets where the stage is. The next thing the
  // stage does is a step.
  std::function<bool(const Simulation&)> checkpoint_due;
  std::function<void(const Simulation&, const StageCursor&)> checkpoint;
  // Read before every step when set: non-zero (a signal number) stops the stage with RunInterrupted.
  const volatile std::sig_atomic_t* stop = nullptr;
  // After every pace_every-th step of a stage's loop when set: where a run on several threads
  // measures its step rate and picks its thread count for the next steps (run/thread_choice.hpp).
  std::function<void(const Simulation&)> pace;
  std::int64_t pace_every = 1;
};

// Thrown between two steps when StageHooks::stop (RunObserver::stop) became non-zero: the run was
// asked to stop (SIGTERM, SIGINT); its reason names the signal.
struct RunInterrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when a stage cannot reach its goal (e.g. equilibrium not reached in max_duration).
struct StageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The equilibrium criteria of a stress stage's hold (docs/method.md#preparation), from the last force
// evaluation: every principal stress within `hold.stress_tolerance` of its target, and the
// unbalanced force ratio at most `hold.unbalanced_force_ratio`. The stage checks them every
// `hold.check_interval` steps once the ramp is over and ends at the first check where they hold.
struct HoldStatus {
  double stress_error = 0;            // largest |sigma_kk - target_k| / target_k
  double unbalanced_force_ratio = 0;
  bool met = false;
};
HoldStatus hold_status(const Simulation& sim, const StageConfig& stage);

// Runs stage `index` of the scene to its end; with `resume`, from the middle where a checkpoint
// left it (sim restored from the same checkpoint).
void run_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks,
               const StageCursor* resume = nullptr);

// Why a run's energy balance no longer closes, as the energy guard's message ends (after "; "):
// the most likely cause from the state it stopped in, naming the key to change. In this order:
//  - contact dashpots past their explicit limit: dashpot_step_number (analysis/measurements.hpp)
//    at 0.5 or above (unstable from about 1; the springs take the rest of the margin);
//  - a time step above the default numerics.max_time_step_fraction x the law's critical step
//    (allowed on purpose);
//  - Hertz-Mindlin with friction: its incremental tangential spring is not conservative, and the
//    balance stays open by a term that does not fall with the time step (hertz_mindlin.hpp);
//  - otherwise the time step, with its fraction of the critical step.
std::string energy_error_cause(const Simulation& sim);

struct RunSummary {
  std::string scene;  // its name
  std::int64_t steps = 0;
  double wall_time_s = 0;
  // Threads (run/thread_choice.hpp): the count the run could use (those asked, at most one per
  // chunk of 512 particles), and with more than one, the steps this run made on one thread and
  // the trials of the other count that it made and kept.
  int threads = 1;
  std::int64_t steps_on_one_thread = 0;
  int thread_trials = 0, thread_switches = 0;
};

// What run_scene does with a checkpoint left at <out>.checkpoint by an earlier, killed run of
// the same scene (run/checkpoint.hpp).
enum class Resume {
  IfValid,  // resume from it if it is whole and has this run's identity; otherwise say why and start over
  Always,   // resume from it; no checkpoint, a damaged one or one of other inputs is an error (ConfigError)
  Never,    // start over (the checkpoint is replaced by this run's first one)
};

// What a run reports while it goes on. The library prints nothing: the `dem` command (cli/) draws
// the terminal progress line and prints the warnings and notes. Any member may be empty.
struct RunProgress {
  std::string scene, stage_name;
  int stage = 0, stages = 0;     // stage index (from 0) and the scene's number of stages
  std::int64_t step = 0;
  double time_s = 0;             // simulated time
  double elapsed_s = 0;          // wall time since the run started (a resumed run counts its earlier time)
  double stage_fraction = -1;    // of the stage, in [0, 1]; < 0 while holding for equilibrium (unknown end)
  std::string status;            // e.g. the current stress error while holding
};
struct RunObserver {
  std::function<void(const RunProgress&)> progress;  // every 256 steps
  std::function<void(const std::string&)> warning;   // e.g. inertial number above 1e-3 (also kept in the result)
  std::function<void(const std::string&)> note;      // about the checkpoint: resuming from it, or why not
  // When set, read before every step: a non-zero value (the number of the signal a handler caught)
  // stops the run between two steps with RunInterrupted; the partial result's status then says
  // "failed: interrupted by SIG...".
  const volatile std::sig_atomic_t* stop = nullptr;
};

// Runs a whole scene and writes the result file (see io/result_writer.hpp for the guarantees),
// with checkpoints as output.checkpoint_* ask. `input_hash` (if not empty) is recorded in the
// result's `input_hash` attribute and is part of the checkpoint identity. Progress, warnings and
// notes about the checkpoint go to `observer`. On success the checkpoint is removed.
// Any failure after the result file exists is written into <out>.partial's status as
// "failed: " + describe_failure(e) (io/result_writer.hpp) before the exception goes on.
RunSummary run_scene(const SceneConfig& scene, const std::string& out_path, const RunObserver& observer = {},
                     const std::string& input_hash = "", Resume resume = Resume::IfValid);

}  // namespace dem
