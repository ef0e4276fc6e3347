#pragma once
// Running a scene: building the simulation from its particle source, then its stages in order.
#include <functional>
#include <string>

#include "config/scene_config.hpp"
#include "dynamics/simulation.hpp"

namespace dem {

// Builds the simulation of a scene. Refuses (ConfigError) a time step above
// max_time_step_fraction x the critical step, giving both numbers.
Simulation build_simulation(const SceneConfig& scene);

struct StageProgress {
  int stage = 0;
  double fraction = -1;  // of the stage, in [0, 1]; < 0 while holding for equilibrium (unknown end)
  std::string status;    // e.g. the current stress error while holding
};

struct StageHooks {
  std::function<void(const Simulation&, int stage)> row;              // at output steps and stage ends
  std::function<void(const Simulation&, const StageProgress&)> progress;  // every few hundred steps
};

// Thrown when a stage cannot reach its goal (e.g. equilibrium not reached in max_duration).
struct StageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs stage `index` of the scene to its end.
void run_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks);

struct RunSummary {
  std::int64_t steps = 0;
  double wall_time_s = 0;
};

// Runs a whole scene and writes the result file (see io/result_writer.hpp for the guarantees).
RunSummary run_scene(const SceneConfig& scene, const std::string& out_path, bool show_progress);

}  // namespace dem
