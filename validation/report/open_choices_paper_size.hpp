#pragma once
// The paper study's inconsistent rows at the paper's size, answered by a set of readings run there
// (pipeline/studies/open_choices_paper_size.yaml, `make open-choices-paper-size`): each row's verdict
// in the set beside the paper study's, and whether the rows consistent in the paper study stay so.
#include <filesystem>
#include <string>
#include <vector>

#include "judge/rows.hpp"

namespace validation {

// Markdown for the report from REPORT/calibration/paper_open_choices/paper_size/validation.json
// (the set, judged by validate) and REPORT/validation.json (the paper study), both judged again
// by `rows` (the paper's reference file at its profile paper) from their recorded per-sample
// values; a density the set's record borrows (validate --borrow) from the decisions.json it names,
// read from the working folder. "" when either record is missing.
std::string open_choices_paper_size_text(const std::filesystem::path& report, const std::vector<Row>& rows);

}  // namespace validation
