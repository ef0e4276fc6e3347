// compare-runs' computations on hand-made inputs: errors against a reference, the Pareto front and
// the cheapest point within a tolerance, the per-cycle quantities, and the stability outcomes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sections/variants.hpp"

using validation::Point;

TEST_CASE("Pareto front of wall time against error", "[compare]") {
  // Hand-made: (cost, error). Expected front: the reference (100, 0), (50, 0.02), (10, 0.2) and
  // (5, 0.5). Dominated: (60, 0.03) by (50, 0.02); (50, 0.05) by (50, 0.02) at equal cost;
  // (20, 0.2) by (10, 0.2) at equal error; (200, 0.01) by the reference.
  const std::vector<Point> p = {{100, 0}, {50, 0.02}, {60, 0.03}, {50, 0.05}, {10, 0.2}, {20, 0.2}, {5, 0.5}, {200, 0.01}};
  const std::vector<bool> expected = {true, true, false, false, true, false, true, false};
  CHECK(validation::pareto_front(p) == expected);
  // Two identical points do not dominate each other: both stay on the front.
  CHECK(validation::pareto_front({{1, 1}, {1, 1}}) == std::vector<bool>{true, true});
}

TEST_CASE("cheapest settings within a tolerance", "[compare]") {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Point> p = {{100, 0}, {50, 0.02}, {40, 0.009}, {10, 0.2}, {5, 0.5}, {1, inf}, {45, 0.009}};
  CHECK(validation::cheapest_within(p, 0.01) == 2);   // (40, 0.9 %), cheaper than (45, 0.9 %)
  CHECK(validation::cheapest_within(p, 0.05) == 2);   // (40) is cheaper than (50, 2 %) too
  CHECK(validation::cheapest_within(p, 0.10) == 2);
  CHECK(validation::cheapest_within(p, 0.25) == 3);   // (10, 20 %)
  CHECK(validation::cheapest_within(p, 1e300) == 4);  // the stopped variant (inf) never counts
  CHECK(validation::cheapest_within({{3, 0.2}}, 0.1) == -1);
  // Equal cost: the more accurate one.
  CHECK(validation::cheapest_within({{3, 0.05}, {3, 0.01}}, 0.1) == 1);
}

TEST_CASE("per-cycle quantities come from the cycle-end rows", "[compare]") {
  validation::TestResult t;
  // Two cycles; the cycle-end rows hold the values to compare (others are in between).
  t.series["cycle"] = {0, 1, 1, 2, 2};
  t.series["cycle_end"] = {0, 0, 1, 0, 1};
  t.series["volumetric_strain"] = {0, 0.001, 0.002, 0.003, 0.004};
  t.series["deviatoric_strain"] = {0, 0.01, 0.02, 0.03, 0.04};
  t.series["leg"] = {-1, 0, 1, 2, 3};
  t.series["strong_fabric_ratio"] = {0, 0.1, 0.2, 0.1, 0.2};
  t.series["q_over_p"] = {0, 0.1, 0.2, 0.1, 0.2};  // q/p = 1 x the ratio: slope 1
  const auto q = validation::convergence_quantities({{"void_ratio", 0.74}, {"coordination_number", 4.1},
                                                     {"coordination_number_mechanical", 4.3}},
                                                    {{"test1", t}});
  CHECK(q.at("e0") == 0.74);
  CHECK(q.at("coordination") == 4.1);
  CHECK(q.at("ev_cycle1") == 0.002);
  CHECK(q.at("ev_cycle2") == 0.004);
  CHECK(q.at("ed_cycle1") == 0.02);
  CHECK(q.at("ed_cycle2") == 0.04);
  CHECK(q.at("qp_slope") == Approx(1.0));
  CHECK(q.at("ev_growth_1_2") == Approx(0.002));  // 0.004 - 0.002
  // No coordination-number column and no legs in this test: neither cn_cycle<c> nor the angles.
  CHECK(q.size() == 8);
}

TEST_CASE("per-cycle coordination numbers and their change from cycle 1 to 2", "[compare]") {
  validation::TestResult t;
  t.series["cycle"] = {0, 1, 1, 2, 2};
  t.series["cycle_end"] = {0, 0, 1, 0, 1};
  t.series["volumetric_strain"] = {0, 0.001, 0.002, 0.003, 0.004};
  t.series["deviatoric_strain"] = {0, 0.01, 0.02, 0.03, 0.04};
  t.series["coordination_number"] = {4.2, 4.1, 4.05, 4.0, 3.98};
  const auto q = validation::convergence_quantities({}, {{"test1", t}});
  CHECK(q.at("cn_cycle1") == 4.05);
  CHECK(q.at("cn_cycle2") == 3.98);
  CHECK(q.at("cn_change_1_2") == Approx(-0.07));
}

TEST_CASE("stability outcomes: ran within the closure limit, stopped with a message, or not acceptable", "[compare]") {
  using validation::CaseRun;
  validation::Columns ok;
  ok["step"] = {0, 100, 200};
  // The first row, before energy came in (stored + dissipated below 1 % of its largest value),
  // is ignored: there the ratio is one of round-offs.
  ok["energy_closure_error"] = {0.5, 0.004, 0.006};
  for (const char* k : {"elastic_energy_normal", "elastic_energy_tangential", "kinetic_energy_centred",
                        "dissipated_by_damping", "dissipated_by_friction"})
    ok[k] = {0.001, 0.5, 1.0};
  auto o = validation::classify_case(CaseRun{true, std::nullopt, "", ok});
  CHECK(o.acceptable);
  CHECK(o.steps == 200);
  REQUIRE(o.closure);
  CHECK(*o.closure == 0.006);

  validation::Columns leaky = ok;
  leaky["energy_closure_error"] = {0, 0.004, 0.02};
  o = validation::classify_case(CaseRun{true, std::nullopt, "", leaky});
  CHECK_FALSE(o.acceptable);
  CHECK_THAT(o.outcome, Catch::Matchers::Contains("closure above"));

  // Cohesive contacts store negative energy: a store below zero counts as zero in the energy that
  // came in (the damping holds what they released), so the rows are judged, not all left out.
  validation::Columns cohesive = ok;
  cohesive["energy_closure_error"] = {0.5, 0.004, 0.03};
  // Last row: stored -7.99 + 1 + 1, dissipated 5 + 1; summed with its sign the energy in would be
  // 0.01, below 1 % of the second row's 2, and the 3 % would go unseen.
  cohesive["elastic_energy_normal"] = {0, 0, -7.99};
  cohesive["dissipated_by_damping"] = {0.001, 0.5, 5.0};
  o = validation::classify_case(CaseRun{true, std::nullopt, "", cohesive});
  REQUIRE(o.closure);
  CHECK(*o.closure == 0.03);
  CHECK_FALSE(o.acceptable);

  validation::Columns nan = ok;
  nan["p"] = {1, std::nan(""), 1};
  o = validation::classify_case(CaseRun{true, std::nullopt, "", nan});
  CHECK_FALSE(o.acceptable);
  CHECK_THAT(o.outcome, Catch::Matchers::Contains("non-finite"));

  o = validation::classify_case(CaseRun{false, 2, "numerics.time_step = 6e-06 s is above the allowed ...", {}});
  CHECK(o.acceptable);
  CHECK(o.steps == 0);
  CHECK_THAT(o.outcome, Catch::Matchers::Contains("refused"));
  CHECK_THAT(o.message, Catch::Matchers::Contains("time_step"));

  validation::Columns partial;
  partial["step"] = {0, 200, 231};
  o = validation::classify_case(CaseRun{false, 1, "non-finite kinetic energy at step 231", partial});
  CHECK(o.acceptable);
  CHECK(o.steps == 231);
  CHECK_THAT(o.outcome, Catch::Matchers::Contains("stopped early"));

  o = validation::classify_case(CaseRun{false, 1, "", partial});  // a stop without a message is not clear
  CHECK_FALSE(o.acceptable);
  partial["p"] = {1, 2, std::nan("")};  // NaN written before the stop
  o = validation::classify_case(CaseRun{false, 1, "stopped", partial});
  CHECK_FALSE(o.acceptable);
  o = validation::classify_case(CaseRun{});
  CHECK_FALSE(o.acceptable);
  CHECK(o.outcome == "not run");
}
