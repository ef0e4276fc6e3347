#pragma once
// A study's manifest, OUT/runs.tsv, declared once for the pipeline: write_manifest (run_plan.cpp)
// writes it with manifest_text, and what reads it back here (recorded_throughput_under, plan_cost.cpp)
// reads it with read_runs_manifest. Its first line names the engine source the input hashes are
// planned for, its second the columns; then one line per run and variant it belongs to.
// validation/study/manifest.* reads it for validation/ and calibration/ (the pipeline may not include
// them, nor they the pipeline's plan).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pipeline {

struct ManifestEntry {
  std::string variant = "-";            // "-": a study without variants
  std::string density;
  std::string test = "-";               // "-": a preparation
  std::string run;                      // the run's name
  std::string result;                   // its result file, as the pipeline wrote it
  std::string starts_from = "-";        // the run it starts from ("-": none)
  bool may_fail = false;
  std::string settings = "as written";  // the variant's settings
  std::string seed = "-";               // the sample of an ensemble ("-": a study of one sample)
  std::string input_hash;               // what its result records when made by the manifest's engine
};

struct RunsManifest {
  std::string engine_source;  // "ENGINE_VERSION" of the first line "# engine source ENGINE_VERSION"
  std::vector<ManifestEntry> entries;
};

// The text of runs.tsv.
std::string manifest_text(const RunsManifest& m);

// FILE read back. Throws std::runtime_error naming the file and line when it cannot be read or a
// line has fewer than 8 fields; an older manifest without the engine line has engine_source "".
RunsManifest read_runs_manifest(const std::filesystem::path& file);

}  // namespace pipeline
