#pragma once
// What the validation reads back of the decisions studies' findings (decisions.json, written by
// compare-runs decisions): each row's explanation, whether the study judged the row, and the size
// it was measured at. Several files may be given (the 1,000-sphere decisions study, the readings
// measured again at 8,000 spheres); a row's cause is the finding of the largest size that judged it.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rows.hpp"

namespace validation {

struct DecisionsFile {
  std::string path;
  std::optional<long> particles;       // spheres per sample, when the file records it
  std::optional<std::size_t> samples;  // the baseline's samples, when the file records them
  struct Finding {
    std::string explanation;
    bool judged = false;  // the study judged the row (a file without `judged`: its explanation does not start "not judged")
  };
  std::map<std::string, Finding> rows;  // by row name
};

// FILE's findings. A file written before shifts were counted in max(sd, resolution) and phrased by
// shift_phrase() (no `schema`: the committed 1,000-sphere file) has its explanations' shifts
// restated (restate_shifts) with each row's resolution from `rows`. Throws on a file that cannot
// be read or parsed.
DecisionsFile read_decisions_file(const std::string& file, const std::vector<Row>& rows);

// "8,000 spheres, 3 samples" from the file's own fields, or "size not recorded" without `particles`.
std::string size_label(const DecisionsFile& f);

// The file whose finding on `row` is the cause: of those that judged it, the one of most spheres (a
// file of unrecorded size after every file with one; the first given on a tie). If none judged it,
// the first in that order that has the row (its explanation says why it is not judged). Null if
// no file has the row.
const DecisionsFile* finding_for(const std::vector<DecisionsFile>& files, const std::string& row);

// What the cause column says of `row`: with one file, its finding as it is; with several, the
// finding finding_for() picks after its size ("8,000 spheres, 3 samples: consistent under ...").
// No file, or none with the row: that no decisions study has judged it.
std::string cause_text(const std::vector<DecisionsFile>& files, const std::string& row);

// `explanation` with each shift "<reading> (... X sd" re-stated from the row's own numbers in
// decisions.json, (mean - baseline_mean) / max(baseline_sd, resolution), in shift_phrase()'s
// words ("beyond +10 sd (+57)"); a reading whose numbers are not there keeps its value, rephrased.
std::string restate_shifts(const std::string& explanation, const nlohmann::json& row, double resolution);

}  // namespace validation
