// The check of a decisions study's baseline against the paper study's ensemble, drawn by the
// report from the two records (baseline_check.hpp): named by what it compares (a size, or only a
// number of samples), the difference in max(sd, resolution), the readings studies' rows once.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "report/baseline_check.hpp"

using validation::DecisionsFile;
using validation::Verdict;

namespace {

validation::Row row_of(const std::string& name, double resolution) {
  validation::Row r;
  r.name = name, r.check = "within", r.reference = 1.2, r.tolerance = 0.25, r.resolution = resolution;
  return r;
}

// The paper study's ensemble: 1.0, 1.1, 1.2, 1.3, 1.4 (mean 1.2, sd 0.1581), 8,000 spheres.
validation::PaperEnsemble paper(double resolution) {
  validation::PaperEnsemble e;
  const validation::Row r = row_of("slope", resolution);
  std::vector<validation::RowResult::PerSample> samples;
  for (double v : {1.0, 1.1, 1.2, 1.3, 1.4}) samples.push_back({"s", {v, "", ""}});
  e.rows.push_back({r, "dense", validation::judge_values(r, samples)});
  e.samples = 5, e.spheres = 8000;
  return e;
}

DecisionsFile study(const std::string& name, long particles, double mean, double sd) {
  DecisionsFile f;
  f.path = "reports/readings/" + name + "/decisions.json";
  f.particles = particles, f.samples = 3;
  if (particles == 8000) f.baseline_results = "results/study/paper";
  DecisionsFile::Finding row;
  row.baseline_mean = mean, row.baseline_sd = sd, row.baseline_verdict = Verdict::Consistent;
  f.order = {"slope"};
  f.rows["slope"] = row;
  return f;
}

}  // namespace

TEST_CASE("baseline check: a study of the paper's size is a sample-count check, its rows once", "[report][decisions]") {
  // Two readings studies whose baseline is the same 3 samples (the same values): one line naming
  // both; a third with other values: its own line.
  const DecisionsFile a = study("dashpot", 8000, 1.5, 0.05), b = study("loose", 8000, 1.5, 0.05), c = study("medium", 8000, 1.4, 0.05);
  const std::string text = validation::baseline_check_section({&a, &b, &c}, paper(0));
  INFO(text);
  CHECK(text.rfind("### Sample-count check: this study's baseline (3 samples) against the paper study's ensemble (5 samples), both of "
                   "8,000 spheres\n",
                   0) == 0);
  CHECK(text.find("Size check") == std::string::npos);
  // What differs is said from the records: the t of 3 and 5 samples, t(0.975, 2) = 4.30, t(0.975, 4) = 2.78.
  CHECK(text.find("the baseline is 3 samples of the paper study's own, `results/study/paper`") != std::string::npos);
  CHECK(text.find("with t = 4.30 for 3 samples and 2.78 for 5") != std::string::npos);
  // (1.5 - 1.2) / 0.1581 = +1.90; (1.4 - 1.2) / 0.1581 = +1.26.
  CHECK(text.find("| slope | 1.20 ± 0.16 | 1.500 ± 0.050 | +1.90 | ✅ / ✅ | dashpot, loose |") != std::string::npos);
  CHECK(text.find("| slope | 1.20 ± 0.16 | 1.400 ± 0.050 | +1.26 | ✅ / ✅ | medium |") != std::string::npos);
  CHECK(text.find("Each row once") != std::string::npos);
}

TEST_CASE("baseline check: another size is a size check; a resolution above the sd is the unit; a weak verdict marked",
          "[report][decisions]") {
  // 1,000 spheres: 1.40 ± 0.15 on 3 samples, an interval 2 x 4.303 x 0.15 x sqrt(4/3) = 1.49 wide,
  // 5.96 times the tolerance 0.25: marked ⚠ and the legend says why. The resolution 0.2 above the
  // paper's sd 0.158: (1.40 - 1.2) / 0.2 = +1.00.
  const DecisionsFile small = study("decisions", 1000, 1.40, 0.15);
  const std::string text = validation::baseline_check_section({&small}, paper(0.2));
  INFO(text);
  CHECK(text.rfind("### Size check: this study's baseline (1,000 spheres, 3 samples) against the paper study's ensemble (8,000 spheres, "
                   "5 samples)\n",
                   0) == 0);
  CHECK(text.find("| slope | 1.20 ± 0.16 | 1.40 ± 0.15 | +1.00 | ✅ / ✅ ⚠ |") != std::string::npos);
  CHECK(text.find("samples too few: the interval of one sample is more than 4 times the row's tolerance") != std::string::npos);
  CHECK(text.find("studies |") == std::string::npos);  // one study: no column naming it
  // No row in common: no check.
  DecisionsFile other = small;
  other.order = {"another"};
  other.rows = {{"another", small.rows.at("slope")}};
  CHECK(validation::baseline_check_section({&other}, paper(0)).empty());
}
