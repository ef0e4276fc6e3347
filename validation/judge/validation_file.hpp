#pragma once
// A validation.json read back (what validate wrote: validation/README.md), for `validate
// --from-json`: every row's per-sample values, judged again by the rows of a reference file
// (judge_values, rows.hpp) without the study's results.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "judge/rows.hpp"
#include "study/stamp.hpp"

namespace validation {

struct RecordedValidation {
  std::string profile;                      // the profile it was judged at
  std::optional<std::string> references;    // the reference file it judged (none: not recorded)
  std::vector<std::string> samples;         // the ensemble's samples (seed<N>), in order
  std::vector<std::string> missing_samples; // samples runs.tsv listed without a folder
  std::vector<std::string> missing_results; // result files missing or not complete
  std::vector<std::string> densities;       // judged_from.densities: only these densities' rows were judged (empty: every row)
  std::vector<std::string> variants;        // judged_from.variants: the study variants the rows read (empty: the baseline)
  // judged_from.borrowed: a density the study does not run because its runs would be another
  // study's, whose reading `reading` in `decisions` (a decisions.json) stands for it.
  struct Borrowed {
    std::string density, reading, decisions;
  };
  std::vector<Borrowed> borrowed;
  Stamp stamp;                              // the stamp of its numbers (fields not recorded: a record made before stamps)
  struct RecordedRow {
    std::string name, density;
    std::vector<RowResult::PerSample> samples;  // value (null: none), note, misfit
  };
  std::vector<RecordedRow> rows;
};

// `rows` without those of a density `densities` does not list (nothing left out when it is empty);
// a row that names no density reads the study's only one and is kept (reference rows or recorded ones).
template <class R>
void erase_other_densities(std::vector<R>& rows, const std::vector<std::string>& densities) {
  if (densities.empty()) return;
  std::erase_if(rows, [&](const R& r) { return !r.density.empty() && std::find(densities.begin(), densities.end(), r.density) == densities.end(); });
}
// The reference rows of `densities` (erase_other_densities). An error naming a density no row
// has, else "" (validate --densities, and a record judged with them).
std::string keep_densities(std::vector<Row>& rows, const std::vector<std::string>& densities);

// A --borrow argument, DENSITY:READING:FILE, checked: DENSITY one that `judged` (validate
// --densities) leaves out, FILE a decisions.json with READING on a row of `rows` (the reference
// file's, `references`) of that density. Throws std::runtime_error naming what is wrong.
RecordedValidation::Borrowed borrowed_density(const std::string& argument, const std::vector<std::string>& judged,
                                              const std::vector<Row>& rows, const std::string& references);

// FILE's record. Throws std::runtime_error naming FILE and what is wrong: cannot be read, not
// JSON, not a validation.json (a key missing or of the wrong type, named by its path: "rows[3].per_sample[1].value").
RecordedValidation read_validation_file(const std::string& file);

// Each of `rows` (the reference file's, in its order) with its recorded values, judged again
// (judge_values). Throws std::runtime_error naming FILE when a row of the reference file is not in
// the record, or the record has a row the reference file does not.
struct RejudgedRow {
  Row row;
  std::string density;
  RowResult result;
};
std::vector<RejudgedRow> judge_recorded(const RecordedValidation& record, const std::vector<Row>& rows, const std::string& file,
                                        const std::string& references);

}  // namespace validation
