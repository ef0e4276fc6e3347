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

#include "judge/decisions.hpp"
#include "judge/rows.hpp"
#include "study/stamp.hpp"

namespace validation {

// decisions.json, declared once: compare-runs decisions writes it (write_decisions_file), and
// validate --decisions, compare-runs decisions --from-json and the report read it
// (read_decisions_file). A value the file does not record is absent (std::nullopt), never a
// placeholder.
struct DecisionsFile {
  std::string path;                    // where it was read from ("" for one being written)
  int schema = 2;                      // the only one read (an older file named its readings in prose alone)
  std::string baseline = "baseline";   // the baseline reading's name
  std::string baseline_results;        // the study whose samples are the baseline ("": this study's own)
  std::optional<long> particles;       // spheres per sample, when the file records it
  std::optional<std::size_t> samples;  // the baseline's samples, when the file records them
  Stamp stamp;                         // the engine and baseline its numbers come from
  std::size_t missing_results = 0;     // result files missing or not complete
  // Each reading's settings as runs.tsv gives them, the baseline first ("as written"); empty in a
  // file written before they were recorded.
  std::vector<std::pair<std::string, std::string>> settings;
  // What a reading did to a row, on this study's own samples.
  struct Reading {
    std::optional<double> mean;             // the reading's ensemble mean (none: no value)
    std::optional<double> shift_sd;         // as written: (mean - baseline mean) / max(baseline sd, resolution)
    Verdict verdict = Verdict::NotJudged;
    std::vector<std::string> missing_runs;  // runs the row reads that a sample of the reading lacks ("seed3 prepare")
  };
  struct Finding {
    std::string group;
    std::optional<double> baseline_mean, baseline_sd;  // the baseline's ensemble (sd: two samples or more)
    Verdict baseline_verdict = Verdict::NotJudged;     // on this study's own samples
    std::vector<std::pair<std::string, Reading>> readings;  // every reading but the baseline, in the study's order
    std::string explanation;
    Outcome outcome = Outcome::NotJudged;
    bool judged = false;  // the study judged the row
    // The readings under which the row is consistent (`made_consistent_by`; a file without it: the
    // names explain() lists after "consistent under ").
    std::vector<std::string> explained_by;
    // A reading's shift of the row's mean from the baseline's, in the row's units (its `mean` less
    // `baseline_mean`): what validate applies to the full-size ensemble. None without both means.
    std::optional<double> mean_shift(const std::string& reading) const;
    const Reading* reading(const std::string& name) const;
  };
  std::vector<std::string> order;       // the rows' names, in the file's order
  std::map<std::string, Finding> rows;  // by row name
};

// FILE's findings. Throws std::runtime_error naming what is wrong (a key missing or of the wrong
// type, a schema other than 2) on a file that cannot be read or parsed.
DecisionsFile read_decisions_file(const std::string& file);

// One row of decisions.json's `rows`. Throws std::runtime_error naming a key missing or of the wrong type.
DecisionsFile::Finding finding_from_json(const nlohmann::json& row);

// `f` as decisions.json holds it (schema 2; the values as given: the writer rounds them).
nlohmann::ordered_json decisions_file_json(const DecisionsFile& f);

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

// The cause in one line (the compact verdict table's cell; causes.md has cause_text()): the outcome
// of the finding cause_text() puts first, in short: "<reading> explains it, breaks N other rows"
// (the consistent rows it turns inconsistent, from `side_effects`; "breaks no other row"), "within
// scatter; no reading explains it", "no reading explains it", "not judged by the decisions study",
// "consistent in the decisions study", or "no decisions study judged it". At most `limit` code
// points (cut with "…" beyond).
std::string cause_line(const std::vector<DecisionsFile>& files, const std::string& row, const TurnsInconsistent& side_effects = {},
                       std::size_t limit = 58);


}  // namespace validation
