// The ensemble statistics behind every verdict: Student t quantiles against printed tables, the
// prediction interval of a known ensemble worked by hand, its coverage of new samples in a Monte
// Carlo experiment, and rows that must come out consistent, inconsistent or not judged.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "study/ensemble.hpp"
#include "judge/decisions.hpp"
#include "judge/rows.hpp"

using validation::Verdict;

TEST_CASE("Student t quantiles match the printed table", "[ensemble]") {
  // Two-sided 95 % critical values, e.g. NIST/SEMATECH e-Handbook, Table 1.3.6.7.2 (to 3 decimals
  // there; these are the exact values to 12 digits, agreeing with the table's rounding).
  CHECK(validation::t_quantile(0.975, 1) == Approx(12.7062047362).epsilon(1e-9));
  CHECK(validation::t_quantile(0.975, 2) == Approx(4.30265272975).epsilon(1e-9));
  CHECK(validation::t_quantile(0.975, 4) == Approx(2.77644510520).epsilon(1e-9));
  CHECK(validation::t_quantile(0.975, 29) == Approx(2.04522964213).epsilon(1e-9));
  // Symmetric; for many degrees of freedom the normal quantile z = 1.959963985 plus the first term
  // of its expansion in 1/dof, (z^3 + z) / (4 dof) (the next term is of order 1/dof^2, 1e-10 here).
  CHECK(validation::t_quantile(0.025, 4) == Approx(-2.77644510520).epsilon(1e-9));
  const double z = 1.959963985;
  CHECK(validation::t_quantile(0.975, 100000) == Approx(z + (z * z * z + z) / 4e5).epsilon(1e-9));
}

TEST_CASE("the prediction interval of a known ensemble, worked by hand", "[ensemble]") {
  // 1..5: mean 3, sd sqrt(2.5); half width t(0.975, 4) sqrt(2.5) sqrt(1 + 1/5) = 2.7764451052 sqrt(3).
  const validation::Spread s = validation::spread({1, 2, 3, 4, 5});
  CHECK(s.n == 5);
  CHECK(s.mean == Approx(3));
  CHECK(s.sd == Approx(std::sqrt(2.5)));
  REQUIRE(s.low);
  REQUIRE(s.high);
  const double half = 2.7764451052 * std::sqrt(3.0);
  CHECK(*s.low == Approx(3 - half).epsilon(1e-9));
  CHECK(*s.high == Approx(3 + half).epsilon(1e-9));
  // One sample: a mean, no spread and no interval.
  const validation::Spread one = validation::spread({0.7});
  CHECK(one.n == 1);
  CHECK(one.mean == 0.7);
  CHECK_FALSE(one.low);
}

TEST_CASE("the 95 % prediction interval covers 95 % of new samples", "[ensemble]") {
  // 20,000 ensembles of 5 normal samples, each with one more sample from the same distribution:
  // the binomial standard deviation of the covered fraction is sqrt(0.95 x 0.05 / 20,000) =
  // 0.0015, so 0.95 +/- 0.006 is four of them (a fixed seed: the same numbers on every run).
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> normal(0.73, 0.01);
  int covered = 0;
  const int trials = 20000;
  for (int i = 0; i < trials; ++i) {
    std::vector<double> v(5);
    for (double& x : v) x = normal(rng);
    const validation::Spread s = validation::spread(v);
    const double next = normal(rng);
    covered += next >= *s.low && next <= *s.high;
  }
  CHECK(static_cast<double>(covered) / trials == Approx(0.95).margin(0.006));
  // A 90 % interval of the same construction covers 90 %.
  covered = 0;
  for (int i = 0; i < trials; ++i) {
    std::vector<double> v(3);
    for (double& x : v) x = normal(rng);
    const validation::Spread s = validation::spread(v, 0.90);
    const double next = normal(rng);
    covered += next >= *s.low && next <= *s.high;
  }
  CHECK(static_cast<double>(covered) / trials == Approx(0.90).margin(0.009));
}

TEST_CASE("verdicts: the paper's region against the interval of one sample", "[ensemble]") {
  const validation::Spread s = validation::spread({1, 2, 3, 4, 5});  // interval [-1.809, 7.809]
  // The paper's value with its tolerance overlaps the interval: consistent, even outside it.
  CHECK(validation::judge(s, validation::paper_region("within", 8.0, 0.2)) == Verdict::Consistent);
  CHECK(validation::judge(s, validation::paper_region("within", 3.0, 0.0)) == Verdict::Consistent);
  // Beyond it: inconsistent.
  CHECK(validation::judge(s, validation::paper_region("within", 8.1, 0.2)) == Verdict::Inconsistent);
  CHECK(validation::judge(s, validation::paper_region("within", -2.1, 0.2)) == Verdict::Inconsistent);
  // Statements "at least" and "at most".
  CHECK(validation::judge(s, validation::paper_region("at_least", 7.8, 0)) == Verdict::Consistent);
  CHECK(validation::judge(s, validation::paper_region("at_least", 7.9, 0)) == Verdict::Inconsistent);
  CHECK(validation::judge(s, validation::paper_region("at_most", -1.9, 0)) == Verdict::Inconsistent);
  CHECK(validation::judge(s, validation::paper_region("at_most", -1.8, 0)) == Verdict::Consistent);
  // No verdict rests on one sample.
  CHECK(validation::judge(validation::spread({3}), validation::paper_region("within", 3, 1)) == Verdict::NotJudged);
  CHECK(validation::judge(validation::spread({}), validation::paper_region("within", 3, 1)) == Verdict::NotJudged);
  CHECK_THROWS(validation::paper_region("near", 1, 1));
}

TEST_CASE("a row evaluated on an ensemble of samples", "[ensemble]") {
  // Three samples whose prepared void ratio is 0.70, 0.71 and 0.72: interval 0.71 -/+
  // t(0.975, 2) 0.01 sqrt(4/3) = [0.6603, 0.7597].
  std::vector<validation::DensityResults> results(3);
  const double e[] = {0.70, 0.71, 0.72};
  for (int i = 0; i < 3; ++i) results[static_cast<std::size_t>(i)].prepared = true,
                              results[static_cast<std::size_t>(i)].sample["void_ratio"] = e[i];
  std::vector<std::pair<std::string, const validation::DensityResults*>> samples = {
      {"seed1", &results[0]}, {"seed2", &results[1]}, {"seed3", &results[2]}, {"seed4", nullptr}};
  validation::Row row;
  row.quantity = "void_ratio_after_preparation";
  row.density = "loose";
  row.check = "within";
  row.reference = 0.73;
  row.tolerance = 0.0;
  validation::RowResult r = validation::evaluate(row, samples);
  CHECK(r.valued == 3);
  CHECK(r.samples.size() == 4);  // the sample without results is listed, without a value
  CHECK_FALSE(r.samples[3].measured.value);
  CHECK(r.spread.mean == Approx(0.71));
  CHECK(*r.spread.high == Approx(0.71 + 4.30265272975 * 0.01 * std::sqrt(4.0 / 3)).epsilon(1e-9));
  CHECK(r.verdict == Verdict::Consistent);
  CHECK(r.holds == 0);  // no sample has exactly 0.73
  row.reference = 0.77;  // beyond the interval by 0.0103: inconsistent, until the tolerance reaches it
  CHECK(validation::evaluate(row, samples).verdict == Verdict::Inconsistent);
  row.tolerance = 0.011;
  r = validation::evaluate(row, samples);
  CHECK(r.verdict == Verdict::Consistent);
  CHECK(r.holds == 0);
  row.reference = 0.71, row.tolerance = 0.005;
  CHECK(validation::evaluate(row, samples).holds == 1);
}

TEST_CASE("decisions: shifts in baseline standard deviations and the reading that explains a row", "[ensemble]") {
  // A row on the loose sample's void ratio, paper 0.73 +/- 0.005. Baseline samples 0.70, 0.71,
  // 0.72 (mean 0.71, sd 0.01, interval [0.660, 0.760]: consistent); "looser" adds 0.02 to each
  // (shift +2 sd); "denser" takes 0.06 off (mean 0.65, interval [0.600, 0.700]: inconsistent).
  auto reading = [](double offset) {
    validation::ReadingResults r;
    for (int i = 0; i < 3; ++i) {
      validation::DensityResults d;
      d.prepared = true;
      d.sample["void_ratio"] = 0.70 + 0.01 * i + offset;
      r.push_back({"seed" + std::to_string(i + 1), "", {{"loose", d}}});
    }
    return r;
  };
  validation::Row row;
  row.name = "e0, loose";
  row.quantity = "void_ratio_after_preparation";
  row.density = "loose";
  row.check = "within";
  row.reference = 0.73;
  row.tolerance = 0.005;
  const std::map<std::string, validation::ReadingResults> readings = {
      {"baseline", reading(0)}, {"looser", reading(0.02)}, {"denser", reading(-0.06)}};
  auto d = validation::decide({row}, readings, {"baseline", "looser", "denser"}, "baseline");
  REQUIRE(d.size() == 1);
  REQUIRE(d[0].readings.size() == 2);
  CHECK(d[0].readings[0].reading == "looser");
  CHECK(*d[0].readings[0].shift_sd == Approx(2.0));
  CHECK(*d[0].readings[1].shift_sd == Approx(-6.0));
  CHECK(d[0].baseline.verdict == Verdict::Consistent);
  CHECK(d[0].readings[1].result.verdict == Verdict::Inconsistent);
  CHECK(d[0].explanation.rfind("consistent on the baseline", 0) == 0);
  CHECK(d[0].outcome == validation::Outcome::Consistent);
  // With "denser" as the baseline the row is inconsistent, and the two other readings explain it.
  d = validation::decide({row}, readings, {"denser", "baseline", "looser"}, "denser");
  CHECK(d[0].baseline.verdict == Verdict::Inconsistent);
  CHECK(d[0].made_consistent_by == std::vector<std::string>{"baseline", "looser"});
  // t = 0.06 / sqrt(2 x 0.01^2 / 3) = 7.35 and 0.08 / 0.008165 = 9.80, both above t(0.95, 4) = 2.13.
  CHECK(d[0].explanation == "consistent under baseline (+6.0 sd, t = 7.35), looser (+8.0 sd, t = 9.80)");
  // A paper value no reading reaches: unexplained, naming the reading that comes closest.
  row.reference = 0.90;
  d = validation::decide({row}, readings, {"denser", "baseline", "looser"}, "denser");
  CHECK(d[0].made_consistent_by.empty());
  CHECK(d[0].explanation.find("unexplained") == 0);
  CHECK(d[0].outcome == validation::Outcome::Unexplained);
  CHECK(d[0].explanation.find("closest: looser") != std::string::npos);
  CHECK_THROWS(validation::decide({row}, readings, {"x"}, "x"));

  // Judged on a full-size ensemble: its samples 0.690, 0.691, 0.692 (sd 0.001, interval
  // [0.686, 0.696]) miss 0.73 +/- 0.005 although this study's baseline is consistent (its scatter
  // is larger); "looser" shifts the mean by +0.02 (to 0.711: still a miss), a reading of +0.04
  // would reach it. The verdicts and causes are the full-size ensemble's.
  row.reference = 0.73;
  validation::RowResult big;
  for (int i = 0; i < 3; ++i) big.samples.push_back({"seed" + std::to_string(i + 1), {0.690 + 0.001 * i, ""}});
  big = validation::judge_values(row, big.samples);
  REQUIRE(big.verdict == Verdict::Inconsistent);
  std::map<std::string, validation::ReadingResults> more = readings;
  more["loosest"] = reading(0.04);
  // "noisy" shifts the mean by as much, but its samples (0.66, 0.75, 0.84) scatter by 0.09: t =
  // 0.04 / sqrt(0.01^2/3 + 0.09^2/3) = 0.77, not resolved, so it explains nothing although it
  // would reach the paper.
  more["noisy"] = reading(0.04);
  for (int i = 0; i < 3; ++i) more["noisy"][static_cast<std::size_t>(i)].densities["loose"].sample["void_ratio"] += 0.08 * (i - 1);
  d = validation::decide({row}, more, {"baseline", "looser", "loosest", "noisy"}, "baseline", {{row.name, big}});
  REQUIRE(d[0].readings[2].t);
  CHECK(*d[0].readings[2].t == Approx(0.04 / std::sqrt(0.0001 / 3 + 0.0081 / 3)).epsilon(1e-6));
  CHECK_FALSE(d[0].readings[2].resolved);
  CHECK(d[0].unresolved_by == std::vector<std::string>{"noisy"});
  REQUIRE(d[0].full);
  CHECK(d[0].baseline.verdict == Verdict::Consistent);  // this study's own baseline ...
  CHECK(d[0].readings[0].full->verdict == Verdict::Inconsistent);  // ... but the full size is judged
  CHECK(d[0].readings[0].full->spread.mean == Approx(0.711));
  CHECK(d[0].readings[1].full->verdict == Verdict::Consistent);
  CHECK(d[0].made_consistent_by == std::vector<std::string>{"loosest"});
  CHECK(d[0].explanation.find("consistent under loosest (+4.0 sd, t = 4.90)") == 0);
}

TEST_CASE("a trend judged by the majority rule: it must hold in more than half of the samples", "[ensemble]") {
  // εv growth of three samples 0.02, 0.06, 0.30 % against "at least 0.05 %": holds in 2 of 3.
  std::vector<validation::DensityResults> results(3);
  const double growth[] = {0.02, 0.06, 0.30};
  std::vector<std::pair<std::string, const validation::DensityResults*>> samples;
  for (int i = 0; i < 3; ++i) {
    validation::TestResult t;
    t.number = 1;
    t.series["cycle"] = {1, 5};
    t.series["cycle_end"] = {1, 1};
    t.series["volumetric_strain"] = {0.0, growth[i] / 100};
    results[static_cast<std::size_t>(i)].tests.push_back(t);
    samples.emplace_back("seed" + std::to_string(i + 1), &results[static_cast<std::size_t>(i)]);
  }
  validation::Row row;
  row.quantity = "ev_growth";
  row.density = "loose";
  row.check = "at_least";
  row.reference = 0.05;
  row.from_cycle = 1;
  row.to_cycle = 5;
  row.rule = "majority";
  validation::RowResult r = validation::evaluate(row, samples);
  CHECK(r.valued == 3);
  CHECK(r.holds == 2);
  CHECK(r.verdict == Verdict::Consistent);
  row.reference = 0.10;  // now it holds in 1 of 3: inconsistent, though the interval reaches 0.10
  r = validation::evaluate(row, samples);
  CHECK(r.holds == 1);
  CHECK(r.verdict == Verdict::Inconsistent);
  row.rule = "interval";
  CHECK(validation::evaluate(row, samples).verdict == Verdict::Consistent);
  row.rule = "majority";  // one sample: not judged
  CHECK(validation::evaluate(row, {samples[0]}).verdict == Verdict::NotJudged);
  // every (a case without scatter): one sample is judged, and every sample must hold.
  row.rule = "every";
  CHECK(validation::evaluate(row, {samples[2]}).verdict == Verdict::Consistent);    // 0.30 >= 0.10
  CHECK(validation::evaluate(row, {samples[0]}).verdict == Verdict::Inconsistent);  // 0.02 < 0.10
  CHECK(validation::evaluate(row, samples).verdict == Verdict::Inconsistent);       // 1 of 3
  row.reference = 0.01;
  CHECK(validation::evaluate(row, samples).verdict == Verdict::Consistent);         // 3 of 3
}
