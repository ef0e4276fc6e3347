#pragma once
// Checkpoints: a run's whole state at a moment between two steps, so that a killed run resumes
// and ends with exactly the result of an uninterrupted one (everything needed to continue
// bit for bit).
//
// The checkpoint of RESULT.h5 is RESULT.h5.checkpoint: a copy of RESULT.h5.partial at that moment
// (time series, legs, particle frames and warnings so far, all flushed) plus one group:
//
//   /checkpoint             attributes identity, step, time, wall_time_s (of the run so far),
//                           checksum (of the whole file but this attribute)
//     state/                particles, cell and strain rate as in a result's /state, plus the
//                           whole Verlet list (verlet_*) and the energy balance (energy_*)
//     cursor/               where the stage loop is (run/run_scene.hpp, StageCursor)
//
// It is written to RESULT.h5.checkpoint.tmp, every write, flush and close checked, flushed to disk
// (fsync) and renamed over the previous one (fsync of the folder), so RESULT.h5.checkpoint is
// always one whole checkpoint: one that fails (a full disk) throws with its reason, removes the
// .tmp and leaves the previous checkpoint as it was. Resuming copies it back
// to RESULT.h5.partial without /checkpoint and goes on: rows the killed run wrote after the
// checkpoint are dropped and written again, with the same values.
//
// A checkpoint resumes only the run that wrote it: its identity hashes the engine source, the
// resolved scene, the pipeline's input hash and the bytes of the particle source file. And only as
// written: /checkpoint@checksum is a digest of everything else in the file (h5::digest), so one
// value changed afterwards makes read_checkpoint refuse it (dem run then starts over with a
// warning, or, with --resume, stops with exit 2 naming the checkpoint).

#include <string>

#include "io/state_io.hpp"
#include "run/run_scene.hpp"

namespace dem {

struct Checkpoint {
  std::string identity;
  double wall_time_s = 0;  // of the run up to the checkpoint, over all its lives
  StageCursor cursor;
  SavedState state;  // particles, cell, strain rate, step
  VerletList::Saved list;
  ContactHistory list_history;  // the history of every pair of `list`
  EnergyBalance energy;
};

std::string checkpoint_path(const std::string& out_path);  // out_path + ".checkpoint"
// `source_bytes`: the particle file's bytes (read_particle_source), read once by the run.
std::string run_identity(const SceneConfig& scene, const std::string& input_hash, const std::string& source_bytes);

// Writes the checkpoint of `out_path` from its partial file (which the caller has flushed); throws
// std::runtime_error "checkpoint at step N not written: <reason>" (see above).
void write_checkpoint(const std::string& partial_path, const std::string& out_path, const std::string& identity,
                      double wall_time_s, const Simulation& sim, const StageCursor& cursor);

// Reads and checks a checkpoint; throws h5::Error naming the file (truncated, not a checkpoint,
// a value out of range).
Checkpoint read_checkpoint(const std::string& file);

// The simulation of a checkpoint of `scene` (one read_checkpoint accepted for this run's identity):
// its particles, cell, list and energy balance.
Simulation restore_simulation(const SceneConfig& scene, Checkpoint& checkpoint);

}  // namespace dem
