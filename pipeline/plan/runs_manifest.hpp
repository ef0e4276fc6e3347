#pragma once
// A study's manifest, OUT/runs.tsv, declared once: write_manifest (run_plan.cpp) writes it with
// manifest_text, and every reader reads it with read_runs_manifest: the pipeline's plan_cost.cpp
// (recorded_throughput_under), and validation/study/manifest.* for validation/ and calibration/ (this
// file is a library of its own, runs_manifest_lib, the one part of the pipeline they link). Its first
// line names the engine source the input hashes are planned for, its second the columns; then one
// line per run and variant it belongs to.
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

// FILE read back. Throws std::runtime_error naming the file and line when it cannot be read, a line
// has fewer than 8 fields, or a variant lists a run twice; an older manifest without the engine line
// has engine_source "".
RunsManifest read_runs_manifest(const std::filesystem::path& file);

}  // namespace pipeline
