// The joint answer in the paper's terms: each scored set's rows counted consistent set by set and
// row by row, on hand-made misfits whose counts are known.
#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "row_verdicts.hpp"

namespace {

// A scored set whose rows are a curve (never judged) and three scalar rows with these verdicts.
calibration::ParameterSet set(const std::string& name, std::vector<std::optional<bool>> verdicts, bool scored = true) {
  calibration::ParameterSet s;
  s.name = name;
  s.misfit.valued = scored;
  calibration::RowMisfit curve;
  curve.name = "lab curve";
  s.misfit.rows.push_back(curve);
  const char* names[] = {"a", "b", "c"};
  for (std::size_t r = 0; r < verdicts.size(); ++r) {
    calibration::RowMisfit m;
    m.name = names[r];
    m.consistent = verdicts[r];
    s.misfit.rows.push_back(m);
  }
  return s;
}

}  // namespace

TEST_CASE("rows are counted consistent set by set and row by row; no set makes all consistent", "[calibration]") {
  // a and b never together: the space trades them. c is not judged in the second set.
  const std::vector<calibration::ParameterSet> sets = {set("s1", {true, false, true}), set("s2", {false, true, std::nullopt}),
                                                       set("s3", {true, false, false}), set("s4", {true, true, true}, false)};
  const calibration::RowVerdicts v = calibration::tally_rows(sets, 1);
  CHECK(v.rows == 3);
  REQUIRE(v.sets.size() == 3);  // s4 is not scored: it counts nowhere, though its rows say all consistent
  CHECK(v.all_consistent == 0);
  REQUIRE(v.best);
  CHECK(v.best->consistent == 1);
  CHECK(v.best->judged == 2);
  REQUIRE(v.most);
  CHECK(sets[v.most->set].name == "s1");
  CHECK(v.most->consistent == 2);
  REQUIRE(v.per_row.size() == 3);  // the curve is judged nowhere: not a row here
  CHECK(v.per_row[0].name == "a");
  CHECK(v.per_row[0].consistent_sets == 2);
  CHECK(v.per_row[0].judged_sets == 3);
  CHECK(v.per_row[0].most_with == 2);
  CHECK(v.per_row[1].consistent_sets == 1);
  CHECK(v.per_row[1].most_with == 1);  // b is consistent only in s2, which keeps nothing else
  CHECK(v.per_row[1].at_best == std::optional<bool>(true));
  CHECK(v.per_row[2].judged_sets == 2);
  CHECK(!v.per_row[2].at_best);
  CHECK(v.per_row[0].never_with == std::vector<std::string>{"b"});  // a and b: never in one set
  CHECK(v.per_row[1].never_with == std::vector<std::string>{"a", "c"});
  CHECK(v.per_row[2].never_with == std::vector<std::string>{"b"});
  const std::string md = calibration::rows_markdown(v, sets);
  CHECK_THAT(md, Catch::Contains("**1 of 3** rows are consistent"));
  CHECK_THAT(md, Catch::Contains("no set run makes all 3 consistent"));
  CHECK_THAT(md, Catch::Contains("| b | ✅ | 1 of 3 | 1 of 3 | a; c |"));
  const nlohmann::json j = calibration::rows_json(v, sets);
  CHECK(j["sets_with_every_row_consistent"] == 0);
  CHECK(j["most"]["name"] == "s1");
}

TEST_CASE("a set with every row judged and consistent is counted", "[calibration]") {
  const std::vector<calibration::ParameterSet> sets = {set("s1", {true, true, true}), set("s2", {true, false, true})};
  const calibration::RowVerdicts v = calibration::tally_rows(sets, 0);
  CHECK(v.all_consistent == 1);
  CHECK_THAT(calibration::rows_markdown(v, sets), Catch::Contains("**1 set makes all 3 consistent**"));
  // Without scalar rows (a calibration on curves only) there is nothing to count or say.
  const std::vector<calibration::ParameterSet> curves = {set("s1", {})};
  CHECK(calibration::tally_rows(curves, 0).rows == 0);
  CHECK(calibration::rows_markdown(calibration::tally_rows(curves, 0), curves).empty());
}
