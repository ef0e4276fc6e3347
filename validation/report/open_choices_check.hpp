#pragma once
// The open choices' calibration, checked at the paper's size: the calibration's best set run as the
// paper study is run (`make open-choices-check`) and judged by `validate`, set beside what the same
// set scored in the calibration and what the paper study's own reading scores, row by row.
#include <filesystem>
#include <string>

namespace validation {

// Markdown for the report, from REPORT/calibration/paper_open_choices/posterior.json (the best set
// and its rows at the calibration's size), .../best/validation.json (the check) and
// REPORT/validation.json (the paper study; left out of the table when missing). "" when the check
// has not been judged. A check of another set than the calibration's best (a later iteration moved
// it) is said so, and nothing of it is set beside the calibration.
std::string open_choices_check_text(const std::filesystem::path& report);

}  // namespace validation
