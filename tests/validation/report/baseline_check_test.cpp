// The check of a decisions study's baseline against the paper study's ensemble, drawn by the
// report from the two records (baseline_check.hpp): named by what it compares (a size, or only a
// number of samples), the difference in max(sd, resolution), the readings studies' rows once.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "report/baseline_check.hpp"
#include "study/format.hpp"

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

TEST_CASE("baseline check: a baseline of the paper study's own samples carries their weak verdict", "[report][decisions][weak]") {
  // The dense coordination number: 5.94 ± 0.15 against samples 6.1182, 6.1000, 6.1110, 6.1259,
  // 6.1035, every one above 6.09. The readings study's baseline is the first 3 of them (its file
  // records their mean and sd to six digits): its interval of one sample, 6.1097 ± t(0.975, 2) ·
  // 0.00917 · √(4/3) = ± 0.0455, reaches 6.09 while 0 of 3 samples lie in the region: consistent by
  // width only, the ⚠ the paper study's verdict carries. Planted: a file whose sd is not those
  // samples' is judged from its record alone (no sample is in it), without the mark.
  validation::Row r;
  r.name = "cn dense", r.check = "within", r.reference = 5.94, r.tolerance = 0.15;
  const std::vector<double> values = {6.1182, 6.1000, 6.1110, 6.1259, 6.1035};
  std::vector<validation::RowResult::PerSample> samples;
  for (std::size_t k = 0; k < values.size(); ++k) samples.push_back({"seed" + std::to_string(k + 1), {values[k], "", ""}});
  validation::PaperEnsemble e;
  e.rows.push_back({r, "dense", validation::judge_values(r, samples)});
  e.samples = 5, e.spheres = 8000;
  REQUIRE(e.rows[0].result.verdict == Verdict::Consistent);
  REQUIRE_FALSE(e.rows[0].result.warnings.empty());
  const double mean = (values[0] + values[1] + values[2]) / 3;
  double ss = 0;
  for (int k = 0; k < 3; ++k) ss += (values[k] - mean) * (values[k] - mean);
  const double sd = std::sqrt(ss / 2);
  const auto file = [&](double recorded_sd) {
    DecisionsFile f;
    f.path = "reports/readings/medium_dense/decisions.json";
    f.particles = 8000, f.samples = 3, f.baseline_results = "results/study/paper";
    DecisionsFile::Finding row;
    row.baseline_mean = std::stod(validation::number(mean)), row.baseline_sd = std::stod(validation::number(recorded_sd));
    row.baseline_verdict = Verdict::Consistent;
    f.order = {r.name};
    f.rows[r.name] = row;
    return f;
  };
  const DecisionsFile own = file(sd), other = file(2 * sd);
  const std::string text = validation::baseline_check_section({&own}, e);
  INFO(text);
  // (6.10973 - 6.11172) / 0.01059 = -0.19.
  CHECK(text.find("| cn dense | 6.112 ± 0.011 | 6.1097 ± 0.0092 | -0.19 | ✅ ⚠ / ✅ ⚠ |") != std::string::npos);
  CHECK(text.find("Its means and sds are those of the paper study's seed1, seed2, seed3 in 1 of 1 rows") != std::string::npos);
  CHECK(text.find("consistent by width only") != std::string::npos);  // the legend names the kind shown
  const std::string planted = validation::baseline_check_section({&other}, e);
  INFO(planted);
  CHECK(planted.find("| ✅ ⚠ / ✅ |") != std::string::npos);
  CHECK(planted.find("Its means and sds are those") == std::string::npos);
}
