#pragma once
// What the paper's open choices change (docs/method.md#open-choices): every validation row evaluated on the
// ensemble of each reading, the shift of its mean from the baseline's in units of the baseline's
// standard deviation, and which readings, if any, make a row consistent with the paper.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "judge/rows.hpp"

namespace validation {

// The results of one reading: its ensemble of samples.
using ReadingResults = std::vector<Sample>;

struct ReadingEffect {
  std::string reading;
  RowResult result;
  std::optional<double> shift_sd;  // (mean - baseline mean) / baseline sd; none without both
  std::optional<RowResult> full;   // the full-size ensemble with this reading's shift of the mean applied
  // t = |mean - baseline mean| / sqrt(sd_b^2/n_b + sd_r^2/n_r); the shift is resolved when t
  // exceeds the one-sided 95 % quantile t(0.95, n_b + n_r - 2) (the question asked of a reading is
  // directional: does it move the row towards the paper?). A shift below that is within the
  // scatter of the two ensembles and explains nothing.
  std::optional<double> t;
  bool resolved = false;
  // The runs this row reads that are missing from some of the reading's samples ("seed2 test1"):
  // then the reading is not judged on the row (no value, no shift), whatever the other samples say.
  std::vector<std::string> missing;
};

// What a decisions study found of a row, as data (its explanation says the same in words):
// not judged; consistent without any reading; consistent under a reading (`made_consistent_by`);
// a trend no reading makes hold in most samples, though the interval of one sample reaches the
// paper's region (within scatter); or no reading makes it consistent (unexplained).
enum class Outcome { NotJudged, Consistent, Explained, WithinScatter, Unexplained };
// "not judged", "consistent", "explained", "within scatter", "unexplained": decisions.json's `outcome`.
const char* to_string(Outcome o);
// The outcome to_string names. Throws std::runtime_error naming the text and the allowed names otherwise.
Outcome outcome_from_string(const std::string& text);

struct RowDecision {
  Row row;
  RowResult baseline;
  std::optional<RowResult> full;  // the row on the full-size ensemble (the paper study), if given
  std::vector<ReadingEffect> readings;  // every reading but the baseline, in the study's order
  std::vector<std::string> made_consistent_by;  // readings with a resolved shift under which an inconsistent row is consistent
  std::vector<std::string> unresolved_by;       // readings that would make it consistent, but whose shift is within the scatter
  std::vector<std::string> baseline_missing;    // runs the row reads that some baseline sample lacks (as ReadingEffect::missing)
  // Whether the study judged the row: the baseline has every run it reads and so has at least one
  // reading. A row not judged says why in its explanation.
  bool judged = false;
  Outcome outcome = Outcome::NotJudged;  // outcome_of(): what the explanation says in words
  std::string explanation;
};

// The runs `row` reads that some sample of `samples` lacks: "seed2 test1" for each (a sample's
// DensityResults::missing_runs, or its density absent: "seed2 loose"). A row of the preparation
// reads "prepare"; a row naming a test of a quantity that reads tests, that test; any other row,
// every test of the density.
std::vector<std::string> missing_runs(const Row& row, const ReadingResults& samples);

// Evaluates every row on every reading; `order` lists the readings, the baseline among them. A
// reading (or the baseline) that lacks a run a row reads in any of its samples is not judged on
// that row (missing_runs()): its other samples alone would compare another set of seeds.
// With `full` (row name -> the row on the full-size ensemble of the paper study), a row's verdict
// and its causes are those of that ensemble: each reading's shift of the mean, measured here, is
// applied to its samples and the row judged again. The decisions study is smaller than the paper
// study (its scatter is larger), so "consistent here" alone would excuse misses of the full size.
std::vector<RowDecision> decide(const std::vector<Row>& rows, const std::map<std::string, ReadingResults>& readings,
                                const std::vector<std::string>& order, const std::string& baseline,
                                const std::map<std::string, RowResult>& full = {});

// What the study found of the row, from its verdicts (explain() words the same): not judged (the
// baseline lacks runs the row reads, no reading has them all, or fewer than 2 samples give a
// value), consistent, explained (`made_consistent_by`), within scatter (a trend whose interval of
// one sample reaches the paper's region) or unexplained.
Outcome outcome_of(const RowDecision& d);

// The sentence that explains a row: consistent at the baseline; consistent under some readings;
// or unexplained, with the reading that moves it most towards the paper and by how much; or not
// judged, and why. Shifts are written by shift_phrase() (format.hpp).
std::string explain(const RowDecision& d);

}  // namespace validation
