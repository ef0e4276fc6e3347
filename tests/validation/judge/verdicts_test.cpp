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
