#pragma once
// A study's manifest, DIR/runs.tsv (written by the pipeline, pipeline/plan/run_plan.cpp): one line
// per run and variant, and the names the study gives its variants, densities, tests and samples.
#include <string>
#include <vector>

#include "plan/runs_manifest.hpp"  // the pipeline's declaration of runs.tsv, the one pipeline header used here

namespace validation {

using ManifestLine = pipeline::ManifestEntry;

// DIR/runs.tsv's lines; throws std::runtime_error if it is missing, a line has fewer than 8 fields
// or a variant lists a run twice.
std::vector<ManifestLine> read_manifest(const std::string& dir);

// The engine DIR/runs.tsv's input hashes are planned for (its first line, "# engine source
// HASH schema N", written by the pipeline); "" when the manifest does not say (an older one).
std::string manifest_engine_source(const std::string& dir);

// Where a line's result is under `dir`, wherever the study ran: DIR/[seed<N>/]<file name> (the
// manifest records the path the pipeline wrote, which moves with a copied or moved folder).
std::string result_under(const std::string& dir, const ManifestLine& line);

// The sample folder of a line: "seed<N>", or "" for a study of one sample.
std::string sample_of(const ManifestLine& line);

// The distinct values of a column, in the order the manifest meets them ("-" left out): the
// study's variants, densities and tests.
std::vector<std::string> variants_of(const std::vector<ManifestLine>& manifest);
std::vector<std::string> densities_of(const std::vector<ManifestLine>& manifest);
std::vector<std::string> tests_of(const std::vector<ManifestLine>& manifest);

// The paper's densities in its order: loose, medium, dense.
const std::vector<std::string>& paper_densities();
// The densities of the study whose results are in DIR, in the manifest's order; the paper's when
// DIR has no manifest (a folder of results copied by hand).
std::vector<std::string> study_densities(const std::string& dir);

// The samples the manifest lists, seed<N> in increasing N, or {""} for a study of one sample.
std::vector<std::string> samples_of(const std::vector<ManifestLine>& manifest);

}  // namespace validation
