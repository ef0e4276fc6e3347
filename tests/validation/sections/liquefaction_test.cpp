// The liquefaction section's computations (validation/sections/liquefaction.hpp) on hand-made inputs: N_L
// and p0 of a synthetic control stage, what ended a stage, the CSR of a name and of a scene, and
// r_u of a hold at a given time.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "analysis/time_series.hpp"
#include "sections/liquefaction.hpp"

namespace {

// A consolidation (stage 0) ending at t = 0.18 s, then a control stage (stage 1) with rows every
// 1 ms from its first row at t = 0.1803 s to t_end; p falls linearly from 100 kPa at the stage
// start to 5 kPa at t_end, r_u = 1 - p / p0 as the engine writes it.
validation::Columns two_stages(double t_end) {
  validation::Columns c;
  for (const dem::SeriesColumn& col : dem::series_columns()) c[col.name] = {};
  const auto add = [&](double stage, double t, double p, double ru) {
    for (auto& [name, v] : c) v.push_back(0.0);
    c["stage"].back() = stage, c["time"].back() = t, c["p"].back() = p, c["pore_pressure_ratio"].back() = ru;
  };
  add(0, 0, 9e4, 0);
  add(0, 0.18, 99831.8, 0);
  const double t0 = 0.1803, p0 = 1e5;
  std::vector<double> times = {t0};
  for (double t = 0.181; t < t_end; t += 0.001) times.push_back(t);
  times.push_back(t_end);  // the row of the step the stop criterion was met at
  for (double t : times) {
    const double p = p0 - (p0 - 5e3) * (t - t0) / (t_end - t0);
    add(1, t, p, 1 - p / p0);
  }
  return c;
}

}  // namespace

TEST_CASE("N_L, p0 and r_u of a synthetic undrained cyclic stage", "[liquefaction][report-sections]") {
  // The engine's own message for this stop: "... met at time 0.212404 s after 1.6052 cycles";
  // N_L = (0.212404 - 0.1803) / 0.02 = 1.6052.
  const validation::Columns c = two_stages(0.212404);
  const validation::StageRows rows = validation::stage_rows(c, 1);
  CHECK(rows.first == 2);
  CHECK(rows.last == c.at("stage").size() - 1);
  const validation::ControlStage s = validation::summarise_control_stage(c, 1, 0.02);
  CHECK(s.start_time_s == 0.1803);
  CHECK(s.end_time_s == 0.212404);
  CHECK(s.cycles == Approx(1.6052).epsilon(1e-12));
  CHECK(s.p0_Pa == 1e5);  // the stage's first row, not the consolidation's last
  CHECK(s.ru_end == Approx(0.95).epsilon(1e-12));
  CHECK(s.ru_max == Approx(0.95).epsilon(1e-12));
  CHECK_THROWS_WITH(validation::stage_rows(c, 2), Catch::Contains("no row of stage 2"));
  // r_u against cycles: from 0 at the stage start to N_L at its end.
  const validation::Table t = validation::ru_against_cycles(c, 1, 0.02);
  CHECK(t.rows.front()[0] == 0);
  CHECK(t.rows.back()[0] == Approx(1.6052).epsilon(1e-12));
  CHECK(t.rows.back()[1] == Approx(0.95).epsilon(1e-12));
}

TEST_CASE("r_u of a hold at a time since its stage start", "[liquefaction][report-sections]") {
  // Linear in time from 0 to 0.95 over 0.5 s: 0.19 per 0.1 s, between rows too.
  const validation::Columns c = two_stages(0.6803);
  CHECK(validation::value_since_start(c, 1, "pore_pressure_ratio", 0) == Approx(0).margin(1e-12));
  CHECK(validation::value_since_start(c, 1, "pore_pressure_ratio", 0.1) == Approx(0.19).epsilon(1e-9));
  CHECK(validation::value_since_start(c, 1, "pore_pressure_ratio", 0.10025) == Approx(0.19 * 1.0025).epsilon(1e-9));
  CHECK(validation::value_since_start(c, 1, "pore_pressure_ratio", 0.5) == Approx(0.95).epsilon(1e-9));
  CHECK(std::isnan(validation::value_since_start(c, 1, "pore_pressure_ratio", 0.51)));  // past the hold: not invented
}

TEST_CASE("what ended a cyclic stage, and the CSR of a name and of a scene", "[liquefaction][report-sections]") {
  CHECK(validation::stop_criterion("until.pore_pressure_ratio met at time 0.2 s after 1.01 cycles") == "pore_pressure_ratio");
  CHECK(validation::stop_criterion("until.double_amplitude_strain met at time 0.5 s after 16 cycles") == "double_amplitude_strain");
  CHECK(validation::stop_criterion("duration reached").empty());
  CHECK(validation::stop_criterion("").empty());
  CHECK(validation::csr_from_name("loose_csr0.05") == 0.05);
  CHECK(validation::csr_from_name("medium_csr0.3") == 0.3);
  CHECK_FALSE(validation::csr_from_name("loose_hold"));
  CHECK_FALSE(validation::csr_from_name("loose_csr"));
  CHECK_FALSE(validation::csr_from_name("loose_csr0.05b"));
  // The study's loose CSR 0.01: q amplitude 2,000 Pa about p0 = 100 kPa.
  CHECK(validation::cyclic_stress_ratio(2000, 1e5) == Approx(0.01).epsilon(1e-15));
  CHECK(std::isnan(validation::cyclic_stress_ratio(2000, 0)));
}

TEST_CASE("median and range of N_L over samples with censored tests", "[liquefaction][report-sections]") {
  using validation::CensoredCycles;
  // Three samples, one did not liquefy in its 50 cycles (N_L > 50): the median is the middle
  // value, 5, known whatever the censored N_L is (it can only be above 50, above the other two);
  // the range runs from 2 to "> 50".
  validation::CensoredSummary s = validation::summarise_censored({{5, false}, {50, true}, {2, false}});
  CHECK(s.samples == 3);
  CHECK(s.liquefied == 2);
  CHECK(s.censored == 1);
  CHECK_FALSE(s.median_censored);
  CHECK(s.median_low == 5);
  CHECK(validation::median_text(s) == "5.00");
  CHECK(validation::censored_text(s.least) == "2.00");
  CHECK(validation::censored_text(s.largest) == "> 50.00");

  // Two of three did not liquefy: the median's own sample is censored, "> 50".
  s = validation::summarise_censored({{2, false}, {50, true}, {50, true}});
  CHECK(s.median_censored);
  CHECK(std::isinf(s.median_high));
  CHECK(validation::median_text(s) == "> 50.00");

  // Four samples, two censored at 50: the median is (4 + T)/2 with T > 50, so > 27.
  s = validation::summarise_censored({{4, false}, {50, true}, {2, false}, {50, true}});
  CHECK(s.median_censored);
  CHECK(validation::median_text(s) == "> 27.00");

  // Four samples, one censored: the median is (4 + 6)/2 = 5 whatever T > 50 is.
  s = validation::summarise_censored({{4, false}, {50, true}, {2, false}, {6, false}});
  CHECK_FALSE(s.median_censored);
  CHECK(validation::median_text(s) == "5.00");

  // A censored N below liquefied ones (tests of different durations): N_L > 5 may be anywhere
  // above 5, so the median of {>5, 10, 20} lies between 10 (N_L just above 5) and 20 (N_L above 20).
  s = validation::summarise_censored({{5, true}, {10, false}, {20, false}});
  CHECK(s.median_censored);
  CHECK(validation::median_text(s) == "10.00 – 20.00");
  CHECK(validation::censored_text(s.least) == "> 5.00");

  // Every sample liquefied: the plain median and range.
  s = validation::summarise_censored({{3, false}, {1, false}, {2, false}});
  CHECK(s.censored == 0);
  CHECK(validation::median_text(s) == "2.00");
  CHECK(validation::censored_text(s.least) + " – " + validation::censored_text(s.largest) == "1.00 – 3.00");
  CHECK_THROWS_AS(validation::summarise_censored({}), std::invalid_argument);
}
