#pragma once
// The check of a decisions study's baseline against the paper study's ensemble, computed from the
// two records (decisions.json, judge/decisions_file.hpp; validation.json, judge/validation_file.hpp)
// and written by the report under the study's section. Its name says what it compares: a "size
// check" when the study's spheres differ from the paper study's (the 1,000-sphere decisions
// study), a "sample-count check" when they are the same (a readings study's baseline is some of the
// paper study's own samples: only the number of samples differs).
#include <filesystem>
#include <string>
#include <vector>

#include "judge/decisions_file.hpp"
#include "judge/validation_file.hpp"

namespace validation {

// The paper study's ensemble as the check reads it: each row judged again from validation.json
// (judge_recorded), its samples and its spheres (its stamp; 0: not recorded).
struct PaperEnsemble {
  std::vector<RejudgedRow> rows;
  std::size_t samples = 0;
  long spheres = 0;
};

// REPORT/validation.json's rows of `rows` (the reference file's, in its order) judged again
// (judge_recorded), its samples and its spheres (REPORT/validation.json's stamp); no rows when the
// file is not there. Throws, naming the file, when it cannot be read.
PaperEnsemble read_paper_ensemble(const std::filesystem::path& report, const std::vector<Row>& rows);

// "size check" or "sample-count check" (above) for a study of `particles` spheres per sample.
std::string baseline_check_name(const std::optional<long>& particles, const PaperEnsemble& paper);

// The check's section, "### <Name>: ..." (heading level `level`), of every file in `files` (the
// readings studies share one table: each row once, with the studies whose baseline has it, a row
// two baselines give differently a line for each): per row, the paper study's mean ± sd, the
// baseline's, their difference in units of max(the paper ensemble's sd, the row's resolution)
// and both verdicts. "" when no file shares a row with `paper`.
std::string baseline_check_section(const std::vector<const DecisionsFile*>& files, const PaperEnsemble& paper, int level = 3);

}  // namespace validation
