// The paper study's misses among the calibration's sets at the paper's size: read from the
// calibration's posterior.json (its parts, declared once in study/posterior_summary.hpp) beside the
// committed paper study's validation.json, each miss answered from the part's counts: consistent
// together with every row of its density only when a set keeps them all; in none of the sets, with
// the confirming set's prediction, when none does. Fixture: a posterior.json of two parts written here.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "judge/rows.hpp"
#include "report/open_choices_parts.hpp"
#include "study/posterior_summary.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string source = DEM_SOURCE_DIR;
const std::string dense_slope = "slope of q/p against F^s_d/F^s_m, dense";
const std::string medium_growth = "medium: εv grows with cycles (cycles 1..5, %)";

void write_json(const fs::path& file, const json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(1) << "\n";
}

json stamp() {
  return {{"engine", "0.1.0+abc"}, {"engine_source", "6b7794fe6bc90d12 schema 4"}, {"baseline", "9a73430d74eb7aff"},
          {"spheres", 8000}, {"samples", 3}, {"date", "2026-12-03"}};
}

// Two parts: dense (2 rows judged: the slope consistent in 1 of 3 sets, that set keeping `most`
// rows), medium (2 rows: the εv growth consistent in none, a set confirmed with the given verdict).
json posterior(int most, std::optional<bool> confirmed_consistent) {
  json medium_confirmed_row{{"name", medium_growth}, {"predicted_probability", 0.3}};
  if (confirmed_consistent) medium_confirmed_row["consistent"] = *confirmed_consistent;
  json p;
  p["best_set"] = {{"name", "i1s001"}, {"chi2", 1.0}};
  p["sizes"] = {{{"profile", "small"}},
                {{"profile", "check"}, {"densities", {"dense"}}, {"stamp", stamp()}},
                {{"profile", "check"}, {"densities", {"medium"}}, {"stamp", stamp()},
                 {"reach", {{"points", 9000}, {"largest_probability_all_rows", 0.01},
                            {"rows", {{{"name", "e0, medium"}, {"largest_probability", 0.99}}, {{"name", medium_growth}, {"largest_probability", 0.04}}}}}},
                 {"confirmed", {{{"set", "i4s002"}, {"chosen", "best"}, {"predicted_probability", 0.21},
                                 {"rows", {{{"name", "e0, medium"}, {"predicted_probability", 0.7}}, medium_confirmed_row}}}}}}};
  p["largest_size_parts"] = {
      {{"densities", {"dense"}},
       {"rows_consistent",
        {{"scored_sets", 3},
         {"per_row", {{{"name", "e0, dense"}, {"consistent_sets", 3}, {"judged_sets", 3}, {"most_rows_consistent_with_it", 2}, {"set_with_most_rows", "i1s001"}},
                      {{"name", dense_slope}, {"consistent_sets", 1}, {"judged_sets", 3}, {"most_rows_consistent_with_it", most}, {"set_with_most_rows", "i2s004"}}}}}}},
      {{"densities", {"medium"}},
       {"rows_consistent",
        {{"scored_sets", 4},
         {"per_row", {{{"name", "e0, medium"}, {"consistent_sets", 4}, {"judged_sets", 4}, {"most_rows_consistent_with_it", 1}, {"set_with_most_rows", "i1s001"}},
                      {{"name", medium_growth}, {"consistent_sets", 0}, {"judged_sets", 4}}}}}}}};
  return p;
}

}  // namespace

TEST_CASE("the paper study's misses among the calibration's parts: answered from each part's counts", "[report][open_choices]") {
  const std::vector<validation::Row> rows = validation::load_references(source + "/reference_data/paper.yaml", "paper");
  const fs::path report = dem::test::scratch_dir("open_choices_parts");
  write_json(report / "validation.json", json::parse(dem::test::read_bytes(source + "/reports/validation.json")));
  const fs::path file = report / "calibration/paper_open_choices/posterior.json";
  REQUIRE(validation::open_choices_parts_text(report, rows).empty());  // no calibration: nothing

  SECTION("a set keeping every row of its density; a confirmed set missing the row") {
    write_json(file, posterior(2, false));
    const validation::PosteriorSummary summary = validation::read_posterior_summary(file.string());
    REQUIRE(summary.parts.size() == 2);
    CHECK(summary.parts[1].confirmed.size() == 1);
    CHECK(summary.parts[1].stamp.spheres == 8000);
    REQUIRE(summary.parts[1].reach);
    CHECK(summary.parts[1].reach->points == 9000);
    CHECK_FALSE(summary.parts[0].reach);
    const std::string text = validation::open_choices_parts_text(report, rows);
    INFO(text);
    CHECK_THAT(text, Catch::Contains("Scored so far: dense 3 set(s) on 2 rows; medium 4 set(s) on 2 rows."));
    CHECK_THAT(text, Catch::Contains("(8,000 spheres, 3 samples, 2026-12-03)"));
    CHECK_THAT(text, Catch::Contains("| " + dense_slope + " | 1.421 ± 0.040, holds in 0 of 5 ❌ | 1 of 3 | "
                                     "✅ consistent together with all 2 rows of its density in set i2s004 | — |"));
    CHECK_THAT(text, Catch::Contains("| " + medium_growth + " |") &&
                         Catch::Contains("| 0 of 4 | ❌ in none, not even in set i4s002, the posterior's best prediction among the sets "
                                         "scored (all 2 rows: 0.21; this row: 0.30) | 0.040 (9000 points) |"));
  }
  SECTION("a row consistent only in sets that lose another; a confirmed set not scored yet") {
    write_json(file, posterior(1, std::nullopt));
    const std::string text = validation::open_choices_parts_text(report, rows);
    INFO(text);
    CHECK_THAT(text, Catch::Contains("| 1 of 3 | consistent in 1 set(s), never together with all 2 rows of its density (at most 1, set i2s004) |"));
    CHECK_THAT(text, Catch::Contains("❌ in none; set i4s002, the posterior's best prediction among the sets scored (all 2 rows: 0.21; this row: "
                                     "0.30), not scored yet"));
    CHECK(text.find("✅ consistent together") == std::string::npos);
    CHECK_THAT(text, Catch::Contains("largest probability that one sample agrees, at random points of its region"));  // a part has its reach
  }
  SECTION("a probe and a named set after the confirmed set: each named for what it is; another choice refused") {
    json p = posterior(2, false);
    p["sizes"][2]["confirmed"].push_back({{"set", "i5p2"}, {"chosen", "probe"}, {"predicted_probability", 0.01},
                                           {"rows", {{{"name", medium_growth}, {"predicted_probability", 0.04}, {"consistent", false}}}}});
    p["sizes"][2]["confirmed"].push_back({{"set", "i2s007"}, {"chosen", "named"}, {"predicted_probability", 0.002},
                                           {"rows", {{{"name", medium_growth}, {"predicted_probability", 0.5}, {"consistent", false},
                                                      {"mean", 0.0398}, {"sd", 0.0065}, {"samples", 3}}}}});
    write_json(file, p);
    const validation::PosteriorSummary summary = validation::read_posterior_summary(file.string());
    REQUIRE(summary.parts[1].confirmed.size() == 3);
    CHECK(summary.parts[1].confirmed[0].chosen == validation::Choice::best);
    CHECK(summary.parts[1].confirmed[1].chosen == validation::Choice::probe);
    CHECK(summary.parts[1].confirmed[2].chosen == validation::Choice::named);
    const std::string text = validation::open_choices_parts_text(report, rows);
    INFO(text);
    // (The cell is longer than a table's cells may be: it is given in a note below the table.)
    CHECK_THAT(text, Catch::Contains("not even in set i4s002, the posterior's best prediction among the sets scored (all 2 rows: 0.21; "
                                     "this row: 0.30), not even in set i5p2, a new set where the posterior's prediction is best (run at "
                                     "the first size too) (all 1 rows: 0.010; this row: 0.040), not even in set i2s007, a set of the "
                                     "first size the calibration file names (run once the iterations end) (all 1 rows: 0.0020; this row: 0.50; "
                                     "measured 0.0398 ± 0.0065 on 3 samples)"));
    p["sizes"][2]["confirmed"][2]["chosen"] = "guessed";
    write_json(file, p);
    CHECK_THROWS_WITH(validation::read_posterior_summary(file.string()), Catch::Contains("chosen: 'guessed' is not best, probe or named"));
  }
  SECTION("no part with its reach yet: no column for it") {
    json p = posterior(2, false);
    p["sizes"][2].erase("reach");
    write_json(file, p);
    const std::string text = validation::open_choices_parts_text(report, rows);
    INFO(text);
    CHECK(text.find("largest probability") == std::string::npos);
    CHECK_THAT(text, Catch::Contains("(all 2 rows: 0.21; this row: 0.30) |\n"));
  }
  SECTION("a part's row without its name: the file named in the error") {
    json p = posterior(2, false);
    p["largest_size_parts"][0]["rows_consistent"]["per_row"][0].erase("name");
    write_json(file, p);
    CHECK_THROWS_WITH(validation::open_choices_parts_text(report, rows),
                      Catch::Contains("posterior.json") && Catch::Contains("largest_size_parts.per_row.name: missing"));
  }
}
