#include "judge/study_results.hpp"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace validation {

namespace {

std::string key(const std::string& sample, const std::string& variant, const std::string& density) {
  return sample + '\t' + variant + '\t' + density;
}

// Whether a row needs this line's run.
bool needs(const RowRuns& runs, const ManifestLine& l) {
  if (l.variant != runs.variant || l.density != runs.density) return false;
  if (l.test == "-") return runs.preparation;
  return std::find(runs.tests.begin(), runs.tests.end(), l.test) != runs.tests.end();
}

}  // namespace

StudyResults::StudyResults(const std::string& dir, const std::vector<ManifestLine>& manifest, const std::vector<RowRuns>& needed) {
  for (const std::string& s : samples_of(manifest)) {
    std::error_code ec;
    (s.empty() || fs::is_directory(fs::path(dir) / s, ec) ? samples_ : missing_samples_).push_back(s);
  }
  for (const ManifestLine& l : manifest) {
    const std::string sample = sample_of(l);
    if (std::find(samples_.begin(), samples_.end(), sample) == samples_.end()) continue;  // its folder is gone
    if (std::none_of(needed.begin(), needed.end(), [&](const RowRuns& r) { return needs(r, l); })) continue;
    DensityResults& r = loaded_[key(sample, l.variant, l.density)];
    const std::string file = result_under(dir, l);
    try {
      if (l.test == "-") load_preparation(file, r);
      else r.tests.push_back(load_test(file, l.test));
    } catch (const std::exception&) {
      if (std::find(missing_.begin(), missing_.end(), file) == missing_.end()) missing_.push_back(file);
    }
  }
}

const DensityResults* StudyResults::of(const RowRuns& runs, const std::string& sample) const {
  const auto it = loaded_.find(key(sample, runs.variant, runs.density));
  return it == loaded_.end() ? nullptr : &it->second;
}

}  // namespace validation
