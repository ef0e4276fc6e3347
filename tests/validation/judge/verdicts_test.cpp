// Samples that are one sample (judge/verdicts.hpp: identical_samples): the same value to the last
// bit in every row. Found by a hostile sweep: a seed set in preparation_set made seed 2 a copy of
// seed 1, and validate judged "2 samples" with sd 0 as two independent samples that agree.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "judge/verdicts.hpp"

namespace {

// A judged row of `rule` whose samples s1, s2, ... have `values` (nullopt: no value).
validation::Judged row(const std::vector<std::optional<double>>& values, const std::string& rule = "interval") {
  validation::Judged j;
  j.row.name = "r";
  j.row.rule = rule;
  for (std::size_t k = 0; k < values.size(); ++k) {
    validation::RowResult::PerSample ps;
    ps.sample = "s" + std::to_string(k + 1);
    ps.measured.value = values[k];
    j.result.samples.push_back(ps);
  }
  return j;
}

using Groups = std::vector<std::vector<std::string>>;

}  // namespace

TEST_CASE("identical samples: the same bits in every row make one sample, one bit less does not", "[validate][samples]") {
  const double e = 0.6123456789;
  // s1 and s3 agree in both rows (s3 has no value in the second, nor has s1): one sample; s2 differs.
  CHECK(validation::identical_samples({row({e, 0.63, e}), row({std::nullopt, 1.5, std::nullopt})}) == Groups{{"s1", "s3"}});
  // Three copies of one sample: one group of three.
  CHECK(validation::identical_samples({row({e, e, e}), row({0.25, 0.25, 0.25})}) == Groups{{"s1", "s2", "s3"}});
  // The nearest double to e apart in one row of two: independent samples.
  CHECK(validation::identical_samples({row({e, std::nextafter(e, 1.0)}), row({0.25, 0.25})}).empty());
  // A value in one sample and none in the other.
  CHECK(validation::identical_samples({row({e, std::nullopt})}).empty());
}

TEST_CASE("identical samples: whole numbers and rows without scatter are no evidence", "[validate][samples]") {
  // A count (cycles to liquefaction) or an ordering may agree in independent samples.
  CHECK(validation::identical_samples({row({3.0, 3.0}), row({1.0, 1.0})}).empty());
  // Rows of the rule "every" expect no scatter (a perfect lattice): left out, so only the row of
  // whole numbers is left.
  CHECK(validation::identical_samples({row({0.74, 0.74}, "every"), row({3.0, 3.0})}).empty());
  // One row with a fraction makes the whole-number rows count with it.
  CHECK(validation::identical_samples({row({0.74, 0.74}), row({3.0, 3.0})}) == Groups{{"s1", "s2"}});
  CHECK(validation::identical_samples({}).empty());
}

TEST_CASE("verdicts: † marks a bound read into the reference's words, not a value it states", "[validate][verdicts]") {
  // A stated value judged without scatter (Thornton's FCC ratio 2 (1 + μ)/(1 − μ) ± 1 %, rule
  // every), a stated value with scatter (rule interval), and a trend this project bounds (rule
  // majority, "grows": the reference gives no number).
  validation::Judged formula = row({1.9977}, "every"), value = row({0.73, 0.74}), trend = row({0.3, 0.4}, "majority");
  formula.row.name = "lattice ratio", formula.row.check = "within", formula.row.reference = 2, formula.row.tolerance = 0.02;
  value.row.name = "void ratio", value.row.check = "within", value.row.reference = 0.73, value.row.tolerance = 0.02;
  trend.row.name = "grows", trend.row.check = "at_least", trend.row.reference = 0.05;
  CHECK_FALSE(validation::bound_is_reading(formula.row));
  CHECK_FALSE(validation::bound_is_reading(value.row));
  CHECK(validation::bound_is_reading(trend.row));
  validation::VerdictsContext c;
  c.label = "literature";
  c.samples = 1;
  const std::string only_stated = validation::verdicts_text({formula, value}, c);
  CHECK(only_stated.find("†") == std::string::npos);  // neither the cells nor the legend
  const std::string with_trend = validation::verdicts_text({formula, trend}, c);
  CHECK(with_trend.find("| 2 ± 0.02 |") != std::string::npos);
  CHECK(with_trend.find("| ≥ 0.05 † |") != std::string::npos);
  CHECK(with_trend.find("\n†: a bound this project reads") != std::string::npos);
}
