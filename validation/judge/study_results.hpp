#pragma once
// The results a validation reads: for each sample of a study (its manifest, runs.tsv), the runs
// the reference rows select, and only those, each file read once. A file a row needs that is
// missing or not complete is listed; a sample whose folder is gone is listed apart.
#include <map>
#include <string>
#include <vector>

#include "study/manifest.hpp"
#include "study/results.hpp"
#include "judge/row_runs.hpp"

namespace validation {

class StudyResults {
 public:
  StudyResults(const std::string& dir, const std::vector<ManifestLine>& manifest, const std::vector<RowRuns>& needed);

  // The manifest's samples whose folders are there (seed<N> in increasing N; "" for a study of one
  // sample), and those whose folders are gone.
  const std::vector<std::string>& samples() const { return samples_; }
  const std::vector<std::string>& missing_samples() const { return missing_samples_; }
  // The result files the rows need that are missing or not complete, in the manifest's order.
  const std::vector<std::string>& missing() const { return missing_; }

  // The loaded runs of `runs`' variant and density in `sample`, as compute() reads them (the tests
  // of every row of that variant and density; compute() keeps the one a row names); null if no row
  // needed any. 
  const DensityResults* of(const RowRuns& runs, const std::string& sample) const;

 private:
  std::vector<std::string> samples_, missing_samples_, missing_;
  std::map<std::string, DensityResults> loaded_;  // by key(sample, variant, density)
};

}  // namespace validation
