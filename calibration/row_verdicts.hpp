#pragma once
// The joint answer of a calibration against a validate reference file, in the paper's own terms:
// every scored set's scalar rows judged as validate judges a study, on the set's samples
// (RowMisfit::consistent), counted set by set and row by row. It says how many rows the best set
// makes consistent, the most any set does and how many sets make every row consistent; and, row by
// row, in how many sets the row is consistent and the most rows such a set keeps. A row consistent
// in no set, or only in sets that lose others, is the evidence that no set run reconciles them all.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sets.hpp"

namespace calibration {

struct SetCount {
  std::size_t set = 0;  // index into the sets
  int consistent = 0, judged = 0;
};

struct RowTally {
  std::string name;
  std::size_t row = 0;      // its index in every set's misfit rows
  int consistent_sets = 0;  // scored sets in which the row is consistent
  int judged_sets = 0;      // scored sets in which it is judged
  int most_with = -1;       // the most rows consistent in one of those sets (-1: none)
  std::size_t most_with_set = 0;  // that set (the first of them), an index into the sets
  std::optional<bool> at_best;
  // The rows consistent in some set but in none of those where this one is: what it is traded
  // against (empty when it is consistent in no set).
  std::vector<std::string> never_with;
};

struct RowVerdicts {
  int rows = 0;                        // scalar rows of the reference file
  std::vector<SetCount> sets;          // the scored sets
  std::optional<SetCount> best, most;  // the best set's; the set with the most consistent rows (ties: the first)
  int all_consistent = 0;              // sets with every row judged and consistent
  std::vector<RowTally> per_row;
};

// Empty (rows == 0) when the references have no scalar rows. `best`: the best set's index.
RowVerdicts tally_rows(const std::vector<ParameterSet>& sets, std::size_t best);

nlohmann::json rows_json(const RowVerdicts& v, const std::vector<ParameterSet>& sets);

// A paragraph and a table of the rows for the report's section (empty when rows == 0).
std::string rows_markdown(const RowVerdicts& v, const std::vector<ParameterSet>& sets);

}  // namespace calibration
