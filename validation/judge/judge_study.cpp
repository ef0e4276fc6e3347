#include "judge/judge_study.hpp"

#include <filesystem>
#include <utility>

#include "study/manifest.hpp"

namespace validation {

std::vector<Judged> judge_study(const std::string& results_dir, const std::vector<Row>& rows,
                                std::optional<StudyResults>& results) {
  const std::vector<ManifestLine> manifest = read_manifest(results_dir);
  const std::string study = (std::filesystem::path(results_dir) / "runs.tsv").string();
  std::vector<Judged> judged;
  for (const Row& r : rows) judged.push_back({r, resolve_runs(r, manifest, study), {}});
  std::vector<RowRuns> needed;
  for (const Judged& j : judged) needed.push_back(j.runs);
  results.emplace(results_dir, manifest, needed);
  for (Judged& j : judged) {
    std::vector<std::pair<std::string, const DensityResults*>> of_samples;
    for (const std::string& s : results->samples()) of_samples.emplace_back(s, results->of(j.runs, s));
    j.result = evaluate(j.row, of_samples);
  }
  return judged;
}

}  // namespace validation
