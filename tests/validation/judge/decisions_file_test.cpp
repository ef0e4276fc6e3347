// What validate reads back of the decisions studies (decisions_file.hpp): the cause of a row is what
// the files of the largest size that judged it found, named from the files' own records, with what
// an explaining reading does to the other rows; a file of another schema is refused.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "judge/decisions_file.hpp"
#include "study/format.hpp"

namespace fs = std::filesystem;
using validation::DecisionsFile;

namespace {

std::string write_json(const fs::path& file, const nlohmann::json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(2);
  return file.string();
}

validation::Row row_named(const std::string& name, double resolution) {
  validation::Row r;
  r.name = name;
  r.resolution = resolution;
  return r;
}

}  // namespace

TEST_CASE("shift phrases: two significant digits, beyond ±10 said with the value", "[decisions][format]") {
  CHECK(validation::shift_phrase(-3.714) == "-3.7 sd");
  CHECK(validation::shift_phrase(0.6) == "+0.60 sd");
  CHECK(validation::shift_phrase(10.0) == "+10 sd");  // the clip itself is still shown as it is
  CHECK(validation::shift_phrase(28.4) == "beyond +10 sd (+28)");
  CHECK(validation::shift_phrase(-1266.68) == "beyond -10 sd (-1300)");
  CHECK(validation::shift_phrase(0) == "0 sd");
  CHECK(validation::thousands(8000L) == "8,000");
  CHECK(validation::thousands(1000000L) == "1,000,000");
}

TEST_CASE("validate --decisions: a row's cause is the largest size that judged it, that size named", "[decisions][validate]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "decisions_file";
  fs::remove_all(dir);
  // A file that does not record its size.
  const auto row = [](const std::string& name, bool judged, const std::vector<std::string>& by, const std::string& explanation) {
    const std::string outcome = !by.empty() ? "explained" : judged ? "unexplained" : "not judged";
    return nlohmann::json{{"name", name}, {"judged", judged}, {"made_consistent_by", by}, {"outcome", outcome}, {"explanation", explanation}};
  };
  const std::string small = write_json(dir / "small.json", {{"schema", 2},
                                                            {"baseline", "baseline"},
                                                            {"rows",
                                                             {row("A", true, {"r"}, "consistent under r (+1.5 sd, t = 2.52)"),
                                                              row("B", true, {}, "unexplained: no reading makes it consistent"),
                                                              row("C", false, {}, "not judged: fewer than 2 samples with a value")}}});
  // A readings file at 8,000 spheres: it judged A, not B (a run missing), and has no C.
  const std::string big = write_json(
      dir / "big.json",
      {{"schema", 2},
       {"baseline", "baseline"},
       {"particles", 8000},
       {"samples", 3},
       {"rows",
        {row("A", true, {"r"}, "consistent under r (-2.0 sd, t = 4.10)"),
         row("B", false, {}, "not judged: no reading has every run this row reads (r lacks seed3 test1)")}}});
  const DecisionsFile s = validation::read_decisions_file(small), b = validation::read_decisions_file(big);
  CHECK(validation::size_label(s) == "size not recorded");
  CHECK(validation::size_label(b) == "8,000 spheres, 3 samples");
  CHECK(s.rows.at("A").judged);
  CHECK_FALSE(s.rows.at("C").judged);

  for (const std::vector<DecisionsFile>& files : {std::vector<DecisionsFile>{s, b}, std::vector<DecisionsFile>{b, s}}) {
    // A: both judged it; 8,000 spheres is the larger size, whichever file is given first.
    const std::vector<const DecisionsFile*> f = validation::findings_for(files, "A");
    REQUIRE(f.size() == 1);
    CHECK(f.front()->particles == 8000L);
    CHECK(validation::cause_text(files, "A") == "8,000 spheres, 3 samples: consistent under r (-2.0 sd, t = 4.10)");
    // B: only the 1,000-sphere file judged it.
    CHECK(validation::cause_text(files, "B") == "size not recorded: unexplained: no reading makes it consistent");
    // C: no file judged it; the one that has it says why.
    CHECK(validation::cause_text(files, "C") == "size not recorded: not judged: fewer than 2 samples with a value");
    CHECK(validation::cause_text(files, "D") == "no decisions study has judged this row");
  }
  // One file: its finding as written (no size).
  CHECK(validation::cause_text({s}, "A") == "consistent under r (+1.5 sd, t = 2.52)");
  CHECK(validation::cause_text({}, "A") == "the decisions study has not judged this row");
}

TEST_CASE("a decisions.json of another schema is refused, naming the schema and what to do", "[decisions][validate]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "decisions_file_schema";
  fs::remove_all(dir);
  // A file without `schema` named its readings in prose alone (schema 1); one of a later schema
  // may record what this tool would misread.
  for (const nlohmann::json& schema : {nlohmann::json(), nlohmann::json(1), nlohmann::json(3)}) {
    nlohmann::json j = {{"baseline", "baseline"}, {"rows", {{{"name", "A"}, {"judged", true}, {"made_consistent_by", {"r"}}, {"outcome", "explained"}, {"explanation", "x"}}}}};
    if (!schema.is_null()) j["schema"] = schema;
    const std::string file = write_json(dir / ("s" + schema.dump() + ".json"), j);
    const std::string expected = "is of schema " + (schema.is_null() ? std::string("1") : schema.dump());
    CHECK_THROWS_WITH(validation::read_decisions_file(file), Catch::Contains(expected) && Catch::Contains("compare-runs decisions"));
  }
  // Schema 2 without the typed fields: the key named.
  const std::string lacking = write_json(dir / "lacking.json", {{"schema", 2}, {"rows", {{{"name", "A"}, {"explanation", "x"}}}}});
  CHECK_THROWS_WITH(validation::read_decisions_file(lacking), Catch::Contains("judged"));
}

TEST_CASE("validate --decisions: two studies of the same size both said, the one that explains first, with its side effects",
          "[decisions][validate]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "decisions_file_same_size";
  fs::remove_all(dir);
  // Two readings studies at 8,000 spheres, as reports/readings/<name>/decisions.json. "grading" (given
  // first) does not explain row A; "dashpot" does, and shifts row B's mean by 0.5 - 0.25 = +0.25 in
  // the row's units (baseline sd 0.1: +2.5 sd) and row C's by 0.
  auto study = [&](const std::string& name, const nlohmann::json& rows) {
    return write_json(dir / name / "decisions.json",
                      {{"schema", 2}, {"baseline", "baseline"}, {"particles", 8000}, {"samples", 3}, {"rows", rows}});
  };
  const std::string grading = study(
      "grading", {{{"name", "A"},
                   {"judged", true},
                   {"made_consistent_by", nlohmann::json::array()},
                   {"outcome", "within scatter"},
                   {"explanation", "no reading does: within scatter; most: grading_by_mass (0 of 5)"}}});
  const std::string dashpot = study(
      "dashpot",
      {{{"name", "A"},
        {"judged", true},
        {"made_consistent_by", {"contact_dashpots"}},
        {"outcome", "explained"},
        {"explanation", "consistent under contact_dashpots (-2.1 sd, t = 2.23), its shift of the mean applied"}},
       {{"name", "B"},
        {"judged", true},
        {"baseline_mean", 0.25},
        {"baseline_sd", 0.1},
        {"readings", {{"contact_dashpots", {{"mean", 0.5}}}}},
        {"made_consistent_by", nlohmann::json::array()},
        {"outcome", "consistent"},
        {"explanation", "consistent on the full-size ensemble"}},
       {{"name", "C"},
        {"judged", true},
        {"baseline_mean", 1.0},
        {"baseline_sd", 0.1},
        {"readings", {{"contact_dashpots", {{"mean", 1.0}}}}},
        {"made_consistent_by", nlohmann::json::array()},
        {"outcome", "consistent"},
        {"explanation", "consistent on the full-size ensemble"}}});
  const std::vector<validation::Row> rows = {row_named("A", 0), row_named("B", 0.01), row_named("C", 0.01)};
  const std::vector<DecisionsFile> files = {validation::read_decisions_file(grading), validation::read_decisions_file(dashpot)};
  CHECK(validation::study_label(files[1]) == "dashpot");
  CHECK(files[1].rows.at("A").explained_by == std::vector<std::string>{"contact_dashpots"});
  CHECK(*files[1].rows.at("B").mean_shift("contact_dashpots") == Approx(0.25));

  const std::vector<const DecisionsFile*> picked = validation::findings_for(files, "A");
  REQUIRE(picked.size() == 2);
  CHECK(validation::study_label(*picked[0]) == "dashpot");  // the finding that explains the row first

  // The side effects as validate finds them: a row's full-size samples moved by the shift and judged
  // again. B is "at most 0.5", held by more than half of the samples. Samples 0.2, 0.25, 0.3 moved by
  // +0.25 are 0.45, 0.5, 0.55: 2 of 3 hold, still consistent. Samples 0.3, 0.35, 0.4 moved are 0.55,
  // 0.6, 0.65: none holds, inconsistent. C's shift is 0: consistent still.
  auto full = [](const validation::Row& row, std::vector<double> values) {
    std::vector<validation::RowResult::PerSample> samples;
    for (std::size_t i = 0; i < values.size(); ++i) samples.push_back({"seed" + std::to_string(i + 1), {values[i], ""}});
    return validation::judge_values(row, std::move(samples));
  };
  validation::Row b = rows[1], c = rows[2];
  b.rule = c.rule = "majority";
  b.check = c.check = "at_most";
  b.reference = 0.5, c.reference = 1.5;
  const validation::RowResult b_keeps = full(b, {0.2, 0.25, 0.3}), b_breaks = full(b, {0.3, 0.35, 0.4}), c_full = full(c, {1.0, 1.1, 0.9});
  REQUIRE(b_keeps.verdict == validation::Verdict::Consistent);
  REQUIRE(b_breaks.verdict == validation::Verdict::Consistent);
  CHECK_FALSE(validation::turned_inconsistent(files[1], "contact_dashpots", b, b_keeps));
  CHECK(validation::turned_inconsistent(files[1], "contact_dashpots", b, b_breaks) == std::optional<std::string>("B (+2.5 sd)"));
  CHECK_FALSE(validation::turned_inconsistent(files[1], "contact_dashpots", c, c_full));
  CHECK_FALSE(validation::turned_inconsistent(files[1], "other_reading", b, b_breaks));  // no mean recorded for it
  CHECK_FALSE(validation::turned_inconsistent(files[0], "contact_dashpots", b, b_breaks));  // the file has no row B
  const validation::TurnsInconsistent breaks_b = [&](const DecisionsFile& f, const std::string& reading) {
    std::vector<std::string> broken;
    for (const auto& [row, result] : {std::pair{b, b_breaks}, std::pair{c, c_full}})
      if (auto x = validation::turned_inconsistent(f, reading, row, result)) broken.push_back(*x);
    return broken;
  };
  CHECK(validation::cause_text(files, "A", breaks_b) ==
        "8,000 spheres, 3 samples: *dashpot*: consistent under contact_dashpots (-2.1 sd, t = 2.23), its shift of the mean applied; "
        "but contact_dashpots turns 1 consistent row inconsistent: B (+2.5 sd) · "
        "*grading*: no reading does: within scatter; most: grading_by_mass (0 of 5)");
  // No side effect: said so; without the function, the findings alone.
  const validation::TurnsInconsistent none = [](const DecisionsFile&, const std::string&) { return std::vector<std::string>{}; };
  CHECK(validation::cause_text(files, "A", none) ==
        "8,000 spheres, 3 samples: *dashpot*: consistent under contact_dashpots (-2.1 sd, t = 2.23), its shift of the mean applied; "
        "contact_dashpots turns no consistent row inconsistent · *grading*: no reading does: within scatter; most: grading_by_mass (0 of 5)");
  CHECK(validation::cause_text({files[0]}, "A") == "no reading does: within scatter; most: grading_by_mass (0 of 5)");
}


TEST_CASE("the cause in one line is worded from the finding's outcome, not from its explanation's words", "[decisions][validate]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "decisions_file_outcome";
  fs::remove_all(dir);
  // Each explanation says something else than its outcome: the line follows the outcome.
  const auto row = [](const std::string& name, const std::string& outcome, const std::vector<std::string>& by) {
    return nlohmann::json{{"name", name}, {"judged", outcome != "not judged"}, {"made_consistent_by", by}, {"outcome", outcome},
                          {"explanation", "unexplained: words that say otherwise"}};
  };
  const std::string file = write_json(dir / "decisions.json", {{"schema", 2},
                                                               {"rows",
                                                                {row("A", "explained", {"r1", "r2"}), row("B", "within scatter", {}),
                                                                 row("C", "not judged", {}), row("D", "consistent", {}),
                                                                 row("E", "unexplained", {})}}});
  const std::vector<DecisionsFile> files = {validation::read_decisions_file(file)};
  CHECK(files[0].rows.at("A").outcome == validation::Outcome::Explained);
  CHECK(validation::cause_line(files, "A") == "r1 (+1) explains it");
  const validation::TurnsInconsistent two = [](const DecisionsFile&, const std::string&) { return std::vector<std::string>{"x", "y"}; };
  CHECK(validation::cause_line(files, "A", two) == "r1 (+1) explains it, breaks 2 other rows");
  CHECK(validation::cause_line(files, "B") == "within scatter; no reading explains it");
  CHECK(validation::cause_line(files, "C") == "not judged by the decisions study");
  CHECK(validation::cause_line(files, "D") == "consistent in the decisions study");
  CHECK(validation::cause_line(files, "E") == "no reading explains it");
  CHECK(validation::cause_line(files, "F") == "no decisions study judged it");
  CHECK(validation::cause_line(files, "B", {}, 10) == "within sc…");  // 9 code points and the ellipsis
  // Written back, the outcome is kept.
  CHECK(validation::decisions_file_json(files[0])["rows"][1]["outcome"] == "within scatter");

  // An outcome the file cannot have: an unknown name, or "explained" without a reading (and a reading without it).
  for (const auto& [bad, expected] : {std::pair{row("A", "explainable", {}), std::string("`outcome` 'explainable' is none of")},
                                      std::pair{row("A", "explained", {}), std::string("'explained' goes with one or more")},
                                      std::pair{row("A", "unexplained", {"r1"}), std::string("`outcome` 'unexplained' with 1 reading(s)")}}) {
    const std::string wrong = write_json(dir / "wrong.json", {{"schema", 2}, {"rows", {bad}}});
    CHECK_THROWS_WITH(validation::read_decisions_file(wrong), Catch::Contains(expected));
  }
}
