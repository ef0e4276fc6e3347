#pragma once
// The runs of a study: one preparation per density, then every test from that density's sample.
// Each run gets a resolved scene file (every override applied), written where `dem run` can read
// it, and an input hash over that scene, the engine version and the hashes of the runs it needs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "core/content_hash.hpp"

namespace pipeline {

struct PlannedRun {
  std::string name;         // dense_prepare, dense_test1, ... (with variants: <variant>_dense_prepare, ...)
  std::string scene_file;   // resolved scene (written by write_scenes)
  std::string scene_text;
  std::string result, log;  // result file and log of `dem run`
  std::string hash;         // input hash, recorded in the result
  int depends_on = -1;      // index of the run whose result this one starts from
  double cost = 0;          // estimated particle-steps, for the ETA
  double spheres = 0;       // of the sample
  std::string cost_basis = "model";  // what `cost` is from: model, recorded (its own result) or <a run> (its family's)
  std::string family;       // density and source scene: runs whose actual length the ETA learns from one another
  std::string density, test;  // test: empty for a preparation
  std::optional<std::int64_t> seed;  // the sample's seed in an ensemble (study key seeds)
  std::vector<std::string> variants;  // the variants whose results this run is (a shared preparation: several)
  bool may_fail = false;    // stopping with a message is an outcome (the scheduler records it)
  int copy_of = -1;         // a run that computes exactly this (see join_studies): its result is copied
};

// Plans every run; validates each resolved scene with the engine's own parser (ConfigError on
// bad input, before anything runs).
std::vector<PlannedRun> plan_study(const Study& study, const Profile& profile, const std::string& out_dir,
                                   const std::string& engine_version);

// One planned study among several run together.
struct StudyPlan {
  std::string name;
  std::vector<PlannedRun> runs;
};

// Joins the runs of several studies into one list for `execute`, so that they share its slots:
// dependencies renumbered and, with more than one study, each name prefixed with its study's
// ("paper/loose_prepare"). A run whose resolved scene is an earlier run's but for its name and
// header (the same inputs, so the same result bit for bit), neither of them may_fail, becomes a
// copy of it (copy_of, and depends_on it): the convergence study's reference sample is the
// paper's loose sample. Throws std::runtime_error if two runs would write the same result.
std::vector<PlannedRun> join_studies(const std::vector<StudyPlan>& plans);

// Writes the resolved scenes (only where the text changed, so file times stay meaningful).
void write_scenes(const std::vector<PlannedRun>& runs);

// Writes <out_dir>/runs.tsv: one line per run and variant it belongs to, with the variant's
// settings and the run's input hash (what build/bin/compare-runs reads), under a first line naming
// the engine the hashes are planned for ("# engine source ENGINE_VERSION"): a result whose
// input_hash is its line's was made by that engine from those inputs.
void write_manifest(const std::vector<PlannedRun>& runs, const Study& study, const std::string& out_dir,
                    const std::string& engine_version);

using dem::content_hash;  // core/content_hash.hpp

}  // namespace pipeline
