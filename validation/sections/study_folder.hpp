#pragma once
// What compare-runs reads of a study's results folder: the pipeline's manifest (DIR/runs.tsv), a
// run's wall time, the record of a run that stopped, a run's time series and resolved scene; and
// paths made relative so that committed tables do not carry the machine's folders.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sections/variants.hpp"
#include "study/manifest.hpp"
#include "config/scene_config.hpp"
#include "study/results.hpp"

namespace sections {

// One line of runs.tsv (validation/study/manifest.hpp).
using validation::ManifestLine;

// The manifest, and its runs grouped by variant in the order of the study.
struct Manifest {
  std::vector<ManifestLine> lines;
  std::vector<std::string> variants;  // in the order they first appear
  std::map<std::string, std::vector<ManifestLine>> by_variant;
};

// Throws std::runtime_error naming the file if there is none or a line has fewer than 8 fields.
Manifest read_manifest(const std::string& dir);

// Whether any run of the manifest has an outcome: a complete result, or the pipeline's record of
// a run that stopped. A manifest with none is a study planned (`pipeline --plan` writes runs.tsv)
// or started but with nothing finished: no section is drawn from it.
bool any_outcome(const Manifest& manifest, const std::string& dir);

// The run time recorded in a complete result (0 if there is none).
double wall_time(const std::string& result);

// The pipeline's record of a may_fail run that stopped (<result>.outcome), if any: its exit code
// and message go into `run`.
void read_stop(const std::string& result, validation::CaseRun& run);

// A result's time series, resolved scene, the stage_end_<stage> attributes that say why each
// stage ended, and its spheres' radii (H5MD /particles/all/radius; empty if it has none).
struct RunFile {
  validation::Columns series;
  std::optional<dem::SceneConfig> scene;
  std::map<std::string, std::string> stage_end;  // stage name -> stage_end_<name>
  std::vector<double> radius_m;                  // [m]
};

// A complete result; throws naming the file if it cannot be read.
RunFile read_run(const std::string& result);

// `s` without the working folder (the repository, when make runs it) or the repository the study
// ran in (the folder above `results`' `results/`) before its paths.
std::string relative_paths(std::string s, const std::string& results = "");

}  // namespace sections
