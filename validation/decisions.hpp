#pragma once
// What the paper's open choices change (SPEC section 7): every validation row evaluated on the
// ensemble of each reading, the shift of its mean from the baseline's in units of the baseline's
// standard deviation, and which readings, if any, make a row consistent with the paper.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rows.hpp"

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
};

struct RowDecision {
  Row row;
  RowResult baseline;
  std::optional<RowResult> full;  // the row on the full-size ensemble (the paper study), if given
  std::vector<ReadingEffect> readings;  // every reading but the baseline, in the study's order
  std::vector<std::string> made_consistent_by;  // readings with a resolved shift under which an inconsistent row is consistent
  std::vector<std::string> unresolved_by;       // readings that would make it consistent, but whose shift is within the scatter
  std::string explanation;
};

// Evaluates every row on every reading; `order` lists the readings, the baseline among them.
// With `full` (row name -> the row on the full-size ensemble of the paper study), a row's verdict
// and its causes are those of that ensemble: each reading's shift of the mean, measured here, is
// applied to its samples and the row judged again. The decisions study is smaller than the paper
// study (its scatter is larger), so "consistent here" alone would excuse misses of the full size.
std::vector<RowDecision> decide(const std::vector<Row>& rows, const std::map<std::string, ReadingResults>& readings,
                                const std::vector<std::string>& order, const std::string& baseline,
                                const std::map<std::string, RowResult>& full = {});

// The sentence that explains a row: consistent at the baseline; consistent under some readings;
// or unexplained, with the reading that moves it most towards the paper and by how much.
std::string explain(const RowDecision& d);

}  // namespace validation
