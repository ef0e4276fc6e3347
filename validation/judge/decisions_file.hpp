#pragma once
// What the validation reads back of the decisions studies' findings (decisions.json, written by
// compare-runs decisions): each row's explanation, whether the study judged the row, and the size
// it was measured at. Several files may be given (the 1,000-sphere decisions study, the readings
// measured again at 8,000 spheres); a row's cause is what every file of the largest size that
// judged it found, and what the reading that explains it does to the other rows.
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "judge/rows.hpp"

namespace validation {

struct DecisionsFile {
  std::string path;
  std::optional<long> particles;       // spheres per sample, when the file records it
  std::optional<std::size_t> samples;  // the baseline's samples, when the file records them
  struct Finding {
    std::string explanation;
    bool judged = false;  // the study judged the row (a file without `judged`: its explanation does not start "not judged")
    // The readings under which the row is consistent (`made_consistent_by`; a file without it: the
    // names explain() lists after "consistent under ").
    std::vector<std::string> explained_by;
    // Each reading's shift of the row's mean from the baseline's, in the row's units (its `mean`
    // less `baseline_mean`), and the baseline's sd: what validate applies to the full-size ensemble.
    std::map<std::string, double> mean_shift;
    double baseline_sd = 0;
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

// "dashpot" for reports/readings/dashpot/decisions.json: the folder that names the study.
std::string study_label(const DecisionsFile& f);

// The files whose findings on `row` are the cause: every file that judged it at the largest size
// any file judged it at (a file of unrecorded size after every file with one), those whose finding
// explains the row first, otherwise in the order given. If none judged it, the first file in that
// order that has the row (its explanation says why it is not judged). Empty if no file has the row.
std::vector<const DecisionsFile*> findings_for(const std::vector<DecisionsFile>& files, const std::string& row);

// "<row> (<shift_phrase>)" when `reading`'s shift of the row's mean in `file`, applied to each
// sample of `full` (the row on the full-size ensemble; shifted()), turns the row from consistent
// to inconsistent; none otherwise (not consistent to begin with, not judged by the file, or no
// mean of the reading recorded). The shift is said in max(the file's baseline sd, the row's resolution).
std::optional<std::string> turned_inconsistent(const DecisionsFile& file, const std::string& reading, const Row& row,
                                               const RowResult& full);

// The rows consistent on the full-size ensemble that `reading`'s shifts of the means in `file`
// turn inconsistent (turned_inconsistent() of each). validate gives it: it has the ensemble.
using TurnsInconsistent = std::function<std::vector<std::string>(const DecisionsFile& file, const std::string& reading)>;

// What the cause column says of `row`: with one file, its finding as it is; with several, the size
// of the findings findings_for() picks, then each ("8,000 spheres, 3 samples: consistent under
// ..."), named by study_label() when there are two or more ("8,000 spheres, 3 samples: *dashpot*:
// consistent under ... · *loose*: no reading does ..."). After a finding that explains the row,
// with `side_effects`, the rows its reading turns inconsistent ("; but contact_dashpots turns 2
// consistent rows inconsistent: ..."). No file, or none with the row: that no study has judged it.
std::string cause_text(const std::vector<DecisionsFile>& files, const std::string& row, const TurnsInconsistent& side_effects = {});

// The cause in one line (the compact verdict table's cell; causes.md has cause_text()): what the
// finding cause_text() puts first says, in short: "<reading> explains it, breaks N other rows" (the
// consistent rows it turns inconsistent, from `side_effects`; "breaks no other row"), "within
// scatter; no reading explains it", "no reading explains
// it", "not judged by the decisions study", "consistent in the decisions study", or "no decisions
// study judged it". At most `limit` code points (cut with "…" beyond).
std::string cause_line(const std::vector<DecisionsFile>& files, const std::string& row, const TurnsInconsistent& side_effects = {},
                       std::size_t limit = 58);

// `explanation` with each shift "<reading> (... X sd" re-stated from the row's own numbers in
// decisions.json, (mean - baseline_mean) / max(baseline_sd, resolution), in shift_phrase()'s
// words ("beyond +10 sd (+57)"); a reading whose numbers are not there keeps its value, rephrased.
std::string restate_shifts(const std::string& explanation, const nlohmann::json& row, double resolution);

}  // namespace validation
