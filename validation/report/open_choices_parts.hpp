#pragma once
// The paper study's inconsistent rows answered by the calibration's sets at the paper's size: the
// calibration of the paper's open choices runs its largest size in parts, one per density, and
// judges each set's rows there on its own samples. Each row the paper study misses: the sets where
// it is consistent, whether one of them keeps every other row of its density consistent, and when
// none does, what the set that confirmed the posterior's best prediction gave.
#include <filesystem>
#include <string>
#include <vector>

#include "judge/rows.hpp"

namespace validation {

// Markdown for the report from REPORT/calibration/paper_open_choices/posterior.json (its parts)
// and REPORT/validation.json (the paper study, judged again by `rows`). "" when either is missing
// or the calibration has no parts.
std::string open_choices_parts_text(const std::filesystem::path& report, const std::vector<Row>& rows);

}  // namespace validation
