// The decisions study's judgement of a row (decisions.hpp): shifts in units of max(baseline sd,
// the row's resolution) and phrased with the ±10 clip, and a reading that lacks a run the row
// reads is not judged on it.
#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "judge/decisions.hpp"

using validation::DensityResults;
using validation::ReadingResults;
using validation::Verdict;

namespace {

// Three samples of the loose density: void ratio e0 + k * step, and Tests 1 and 2 whose εv at the
// end of cycle 1 is ev (%) + k * 0.1 (k = 0, 1, 2).
ReadingResults samples(double e0, double step, double ev = 1.0) {
  ReadingResults out;
  for (int k = 0; k < 3; ++k) {
    DensityResults d;
    d.prepared = true;
    d.sample["void_ratio"] = e0 + step * k;
    for (int t : {1, 2}) {
      validation::TestResult test;
      test.number = t;
      test.name = "test" + std::to_string(t);
      test.series["cycle"] = {1};
      test.series["cycle_end"] = {1};
      test.series["volumetric_strain"] = {(ev + 0.1 * k) / 100};
      d.tests.push_back(test);
    }
    out.push_back({"seed" + std::to_string(k + 1), "", {{"loose", d}}});
  }
  return out;
}

validation::Row e0_row(double reference) {
  validation::Row row;
  row.name = "e0, loose";
  row.quantity = "void_ratio_after_preparation";
  row.density = "loose";
  row.check = "within";
  row.reference = reference;
  row.tolerance = 0.005;
  row.resolution = 0.005;
  return row;
}

validation::Row ev_row(const std::string& test = "") {
  validation::Row row;
  row.name = "loose: εv after cycle 1";
  row.quantity = "ev_after_cycle";
  row.density = "loose";
  row.cycle = 1;
  row.test = test;
  row.check = "within";
  row.reference = 1.1;
  row.tolerance = 0.5;
  row.resolution = 0.005;
  return row;
}

}  // namespace

TEST_CASE("decisions: a shift counts in max(sd, resolution) and beyond ±10 is said so, with its value", "[decisions]") {
  // The baseline's samples agree to 1e-6 (sd 1e-6), below the resolution 0.005: the unit is 0.005.
  // "far" moves every sample by +0.14: 0.14 / 0.005 = +28 (in the baseline's own sd it would be
  // 140,000). "near" moves them by +0.003: +0.6. The paper's 0.84 ± 0.005 is missed by the baseline
  // (0.700 ± 1e-6) and met by "far" (0.840), whose shift is resolved (t = 0.14 / sqrt(2 x 1e-12 / 3)).
  const std::map<std::string, ReadingResults> readings = {
      {"baseline", samples(0.70, 1e-6)}, {"far", samples(0.84, 1e-6)}, {"near", samples(0.703, 1e-6)}};
  const auto d = validation::decide({e0_row(0.84)}, readings, {"baseline", "far", "near"}, "baseline");
  REQUIRE(d.size() == 1);
  REQUIRE(d[0].readings.size() == 2);
  REQUIRE(d[0].readings[0].shift_sd);
  CHECK(*d[0].readings[0].shift_sd == Approx(28.0));
  CHECK(*d[0].readings[1].shift_sd == Approx(0.6));
  CHECK(d[0].baseline.verdict == Verdict::Inconsistent);
  CHECK(d[0].made_consistent_by == std::vector<std::string>{"far"});
  CHECK(d[0].judged);
  CHECK(d[0].outcome == validation::Outcome::Explained);
  INFO(d[0].explanation);
  CHECK(d[0].explanation.rfind("consistent under far (beyond +10 sd (+28), t = ", 0) == 0);

  // A scatter above the resolution is the unit: samples 0.70, 0.71, 0.72 (sd 0.01) against 0.73,
  // 0.74, 0.75: +0.03 is +3.0 sd. The interval of one sample, mean ± t(0.975, 2) 0.01 sqrt(4/3) =
  // ± 0.0497, reaches the paper's 0.78 ± 0.005 from 0.74, not from 0.71.
  const auto wide = validation::decide({e0_row(0.78)}, {{"baseline", samples(0.70, 0.01)}, {"up", samples(0.73, 0.01)}},
                                       {"baseline", "up"}, "baseline");
  CHECK(*wide[0].readings[0].shift_sd == Approx(3.0));
  // t = 0.03 / sqrt(2 x 0.0001 / 3) = 3.67 > t(0.95, 4) = 2.13: resolved.
  CHECK(wide[0].explanation == "consistent under up (+3.0 sd, t = 3.67)");
}

TEST_CASE("decisions: a reading lacking a run a row reads is not judged on that row", "[decisions]") {
  // Reading "r" is the baseline moved by +0.01 in e0 and +0.3 % in εv, but its seed3 has no Test 2
  // (the run not finished): the rows that read every test are not judged under it; the row of the
  // preparation and a row naming Test 1 alone are.
  ReadingResults r = samples(0.71, 0.01, 1.3);
  auto& seed3 = r[2].densities.at("loose");
  seed3.tests.pop_back();
  seed3.missing_runs = {"test2"};
  std::map<std::string, ReadingResults> readings = {{"baseline", samples(0.70, 0.01)}, {"r", r}};

  auto d = validation::decide({e0_row(0.73), ev_row(), ev_row("test1")}, readings, {"baseline", "r"}, "baseline");
  REQUIRE(d.size() == 3);
  // The preparation: judged, +0.01 / 0.01 = +1 sd.
  CHECK(d[0].readings[0].missing.empty());
  CHECK(*d[0].readings[0].shift_sd == Approx(1.0));
  CHECK(d[0].judged);
  // Every test: not judged (seeds 1 and 2 alone would compare another set of samples).
  CHECK(d[1].readings[0].missing == std::vector<std::string>{"seed3 test2"});
  CHECK(d[1].readings[0].result.verdict == Verdict::NotJudged);
  CHECK_FALSE(d[1].readings[0].shift_sd);
  CHECK_FALSE(d[1].judged);
  CHECK(d[1].explanation == "not judged: no reading has every run this row reads (r lacks seed3 test2)");
  CHECK(d[1].outcome == validation::Outcome::NotJudged);
  // Test 1 alone: judged, +0.3 % / 0.1 % = +3 sd.
  CHECK(d[2].readings[0].missing.empty());
  CHECK(*d[2].readings[0].shift_sd == Approx(3.0));
  CHECK(d[2].judged);

  // With another reading that has every run, the row is judged, and says which reading it could not judge.
  readings["q"] = samples(0.70, 0.01, 1.0);
  d = validation::decide({ev_row()}, readings, {"baseline", "r", "q"}, "baseline");
  CHECK(d[0].judged);
  CHECK(d[0].explanation ==
        "consistent on the baseline (within the scatter of one sample); not judged under a reading that lacks runs this row reads "
        "(r lacks seed3 test2)");

  // The baseline lacking a run: the row is not judged at all.
  readings["baseline"][0].densities.at("loose").missing_runs = {"prepare"};
  d = validation::decide({e0_row(0.73)}, readings, {"baseline", "r", "q"}, "baseline");
  CHECK_FALSE(d[0].judged);
  CHECK(d[0].baseline.verdict == Verdict::NotJudged);
  CHECK(d[0].explanation == "not judged: the baseline lacks runs this row reads (seed1 prepare)");
  CHECK(d[0].outcome == validation::Outcome::NotJudged);
}

TEST_CASE("decisions: a trend no reading makes hold is within scatter when one sample's interval reaches the paper's region",
          "[decisions]") {
  // "e0 at least 0.72" held by most samples. Baseline 0.70, 0.71, 0.72: it holds in 1 of 3, and the
  // interval of one sample, 0.71 ± t(0.975, 2) 0.01 sqrt(4/3) = ± 0.0497, reaches 0.72. Shifted down
  // by 0.1 it reaches no further than 0.66: unexplained. The reading "down" (0.01 lower) helps neither.
  validation::Row row = e0_row(0.72);
  row.rule = "majority";
  row.check = "at_least";
  for (const auto& [base, outcome, words] : {std::tuple{0.70, validation::Outcome::WithinScatter, "no reading does: within scatter"},
                                             std::tuple{0.60, validation::Outcome::Unexplained, "unexplained: no reading makes it hold"}}) {
    const auto d = validation::decide({row}, {{"baseline", samples(base, 0.01)}, {"down", samples(base - 0.01, 0.01)}},
                                      {"baseline", "down"}, "baseline");
    REQUIRE(d.size() == 1);
    INFO(d[0].explanation);
    CHECK(d[0].baseline.verdict == Verdict::Inconsistent);
    CHECK(d[0].outcome == outcome);
    CHECK(d[0].explanation.rfind(words, 0) == 0);
  }
}
