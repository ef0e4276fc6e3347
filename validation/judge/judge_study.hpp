#pragma once
// The rows of a reference file judged on a study's results folder: what `validate --results` and
// the Python module's Study.validate both call.
#include <optional>
#include <string>
#include <vector>

#include "judge/rows.hpp"
#include "judge/study_results.hpp"
#include "judge/verdicts.hpp"

namespace validation {

// Each of `rows` judged on the results in `results_dir` (its runs.tsv): the runs each row reads
// (resolve_runs: a row naming what the study lacks throws, naming it), read once into `results`
// (what is missing is listed there), each row evaluated on every sample.
std::vector<Judged> judge_study(const std::string& results_dir, const std::vector<Row>& rows,
                                std::optional<StudyResults>& results);

}  // namespace validation
