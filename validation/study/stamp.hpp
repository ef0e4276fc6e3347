#pragma once
// A stamp: which engine, on which baseline, at which size and when a study's numbers were made,
// recorded beside a section's table (validation.json, decisions.json, stamp.json) so that the
// report can say it under the section's heading and refuse to splice a section from another
// baseline in silence.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace validation {

struct Stamp {
  std::string engine;    // the results' software_version ("": not recorded): the commit of the build
  std::string baseline;  // baseline_of the study's first preparation (seed1, its first density)
  long spheres = 0;      // of that preparation (0: not recorded)
  long samples = 0;      // the samples the study's manifest lists (0: not recorded)
  std::string date;      // the day (UTC, YYYY-MM-DD) its last result was written
  std::string engine_source;      // the engine source hash every result was checked to be made by ("": not recorded)
  long other_engine_results = 0;  // results not made by engine_source from their manifest's inputs (stale)
  // Recorded: something says which engine or baseline made it (a record recovered after the fact
  // may know the engine's source alone).
  bool recorded() const { return !engine.empty() || !engine_source.empty() || !baseline.empty(); }
};

// The text a stamp field has in JSON when it is not recorded.
inline constexpr const char* not_recorded = "not recorded";

// The stamp of the study whose results are in `dir` (its runs.tsv): its first preparation (of seed1,
// or of the study's one sample; the manifest's first density; of `variant` when the study has it,
// e.g. the decisions study's baseline reading) gives the engine, the baseline and
// the spheres, the manifest the samples, the newest complete result the date. The engine source is
// the manifest's when every complete result records its line's input hash (the pipeline's plan
// for that engine and those inputs); the results that do not are counted. Throws, naming the
// folder, when it has no manifest; a field its results do not give stays not recorded.
Stamp stamp_of_results(const std::string& dir, const std::string& variant = "");
// The stamp of a study of variants: as above, but for a study of readings only, whose baseline is
// another study's samples of the same seeds (`baseline_results`), the baseline is that study's.
// A reading that changes the preparation has another baseline by design; its own would mark the
// section as made on another baseline.
Stamp stamp_of_results(const std::string& dir, const std::string& variant, const std::string& baseline_results);

// Several studies' stamps made one (a section fed by several, e.g. the liquefaction studies of
// two densities): a field on which they differ lists every value ("a, b"), so that it differs from
// the paper study's; spheres and samples are the first's, the date the latest. A stamp without
// engine or baseline (a study not run yet) is left out, unless none has them (then the first).
Stamp combined(const std::vector<Stamp>& stamps);

// {"engine", "engine_source", "baseline", "spheres", "samples", "date"}, each "not recorded" when
// it is not, and "other_engine_results" when there are any.
nlohmann::ordered_json stamp_json(const Stamp& s);
// The stamp in `j` (an object with those keys, any of them missing or "not recorded"); a `j`
// that is not an object: nothing recorded.
Stamp stamp_from_json(const nlohmann::json& j);

// OUT/stamp.json: `s`, and each part another study fed (the critical-state section's "ensemble"
// and "rates") under its name, with its own stamp.
void write_stamp_file(const std::string& out_dir, const Stamp& s, const std::vector<std::pair<std::string, Stamp>>& parts = {});

}  // namespace validation
