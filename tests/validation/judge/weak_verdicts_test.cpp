// A weak verdict is marked the same way wherever a verdict is shown, and the legend names every
// kind of warning a table shows (weak_verdicts.hpp).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "judge/weak_verdicts.hpp"

using validation::Verdict;
using validation::Weakness;

namespace {

validation::Row within(double reference, double tolerance) {
  validation::Row r;
  r.name = "x", r.check = "within", r.reference = reference, r.tolerance = tolerance;
  return r;
}

validation::RowResult judged(const validation::Row& row, const std::vector<double>& values) {
  std::vector<validation::RowResult::PerSample> samples;
  for (double v : values) samples.push_back({"s", {v, "", ""}});
  return validation::judge_values(row, samples);
}

}  // namespace

TEST_CASE("weak verdicts: each kind found, marked and named in the legend", "[verdicts][warnings]") {
  // 0 of 5 samples in the region, the interval reaching it: consistent by width only. 6.10..6.14
  // against 5.94 +/- 0.15 (the dense coordination number): the region ends at 6.09; mean 6.112, sd
  // 0.0179, the interval of one sample 6.112 +/- 2.776 x 0.0179 x sqrt(1.2) = [6.058, 6.166].
  const validation::RowResult width = judged(within(5.94, 0.15), {6.1, 6.1, 6.1, 6.12, 6.14});
  REQUIRE(width.verdict == Verdict::Consistent);
  CHECK(width.holds == 0);
  CHECK(validation::weaknesses(width) == std::vector<Weakness>{Weakness::WidthOnly});
  CHECK(validation::verdict_mark(width) == "✅ ⚠");
  CHECK(validation::verdict_words(width.verdict, !width.warnings.empty()) == "✅ consistent ⚠");
  // Three samples with an interval 5.8 times the tolerance: 1.40 +/- 0.15 against 1 +/- 0.25 (the
  // dense slope at 1,000 spheres): width 2 x 4.303 x 0.15 x sqrt(4/3) = 1.491 = 5.96 x 0.25.
  const auto few = validation::too_few_warning(within(1, 0.25), validation::summary_spread(1.40, 0.15, 3));
  REQUIRE(few);
  CHECK(validation::weakness_of(*few) == Weakness::TooFewSamples);
  CHECK(few->find("(1.49 wide, 3 samples) is 5.96 times the tolerance 0.25 (more than 4)") != std::string::npos);
  // 3.9 times: no warning (2 x 4.303 x 0.098 x 1.1547 = 0.974 = 3.90 x 0.25).
  CHECK_FALSE(validation::too_few_warning(within(1, 0.25), validation::summary_spread(1.40, 0.098, 3)));
  // A plain verdict carries no mark.
  const validation::RowResult plain = judged(within(10, 1), {9.9, 10, 10.1});
  CHECK(plain.warnings.empty());
  CHECK(validation::verdict_mark(plain) == "✅");
  CHECK(validation::verdict_mark(Verdict::Inconsistent, true) == "❌ ⚠");
  // The legend names each kind asked for, and only those; with none asked, every kind.
  const std::string one = validation::weak_legend({Weakness::WidthOnly});
  CHECK(one.find("by width only") != std::string::npos);
  CHECK(one.find("more than 4 times") == std::string::npos);
  const std::string all = validation::weak_legend();
  for (const char* words : {"does not fit the runs", "quasi-static limit", "by width only", "more than 4 times the row's tolerance"})
    CHECK(all.find(words) != std::string::npos);
}
