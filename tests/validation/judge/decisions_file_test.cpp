// What validate reads back of the decisions studies (decisions_file.hpp): the cause of a row is what
// the files of the largest size that judged it found, named from the files' own records, with what
// an explaining reading does to the other rows; a file written before shifts had a floor has its
// shifts restated from its own numbers.
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

// restate_shifts on a row of decisions.json as the file holds it.
std::string restate_shifts_json(const std::string& explanation, const nlohmann::json& row, double resolution) {
  nlohmann::json with = row;
  with["explanation"] = explanation;
  return validation::restate_shifts(explanation, validation::finding_from_json(with), resolution);
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
  // The 1,000-sphere file as committed: no schema, no size, no `judged`.
  const std::string small = write_json(
      dir / "small.json",
      {{"baseline", "baseline"},
       {"rows",
        {{{"name", "A"}, {"explanation", "consistent under r (1.50 sd, t = 2.52)"}},
         {{"name", "B"}, {"explanation", "unexplained: no reading makes it consistent"}},
         {{"name", "C"}, {"explanation", "not judged: fewer than 2 samples with a value"}}}}});
  // A readings file at 8,000 spheres: it judged A, not B (a run missing), and has no C.
  const std::string big = write_json(
      dir / "big.json",
      {{"schema", 2},
       {"baseline", "baseline"},
       {"particles", 8000},
       {"samples", 3},
       {"rows",
        {{{"name", "A"}, {"judged", true}, {"explanation", "consistent under r (-2.0 sd, t = 4.10)"}},
         {{"name", "B"}, {"judged", false}, {"explanation", "not judged: no reading has every run this row reads (r lacks seed3 test1)"}}}}});
  const std::vector<validation::Row> rows = {row_named("A", 0), row_named("B", 0), row_named("C", 0)};
  const DecisionsFile s = validation::read_decisions_file(small, rows), b = validation::read_decisions_file(big, rows);
  CHECK(validation::size_label(s) == "size not recorded");
  CHECK(validation::size_label(b) == "8,000 spheres, 3 samples");
  CHECK(s.rows.at("A").judged);
  CHECK_FALSE(s.rows.at("C").judged);  // an old file: "not judged" at the start of its explanation

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
  // One file: its finding as before (no size), its shift restated (resolution 0 here: the sd is the unit, the
  // file has no numbers, so the value is rephrased only).
  CHECK(validation::cause_text({s}, "A") == "consistent under r (+1.5 sd, t = 2.52)");
  CHECK(validation::cause_text({}, "A") == "the decisions study has not judged this row");
}

TEST_CASE("an explanation written before the floor: its shifts restated from its own numbers", "[decisions][validate]") {
  // The committed 1,000-sphere file's "medium: εv grows" row: baseline 0.000447401 ± 0.0002257 %, the
  // reading 0.286338 %; the row's resolution 0.005 %. (0.286338 - 0.000447401) / 0.005 = 57.18.
  const nlohmann::json medium = {{"baseline_mean", 0.000447401},
                                 {"baseline_sd", 0.0002257},
                                 {"readings", {{"shear_prep_friction", {{"mean", 0.286338}, {"shift_sd", 1266.68}}}}}};
  CHECK(restate_shifts_json("consistent under shear_prep_friction (1266.68 sd, t = 2.76), its shift of the mean applied",
                                   medium, 0.005) ==
        "consistent under shear_prep_friction (beyond +10 sd (+57), t = 2.76), its shift of the mean applied");
  // The dense slope: sd 0.118947 above the resolution 0.01, so the sd is the unit:
  // (0.954353 - 1.39596) / 0.118947 = -3.713.
  const nlohmann::json slope = {{"baseline_mean", 1.39596}, {"baseline_sd", 0.118947}, {"readings", {{"shear_prep_friction", {{"mean", 0.954353}}}}}};
  CHECK(restate_shifts_json("consistent under shear_prep_friction (-3.71 sd, t = 5.94)", slope, 0.01) ==
        "consistent under shear_prep_friction (-3.7 sd, t = 5.94)");
  // "mean shifted X sd" inside a reading's parentheses, and a reading the row does not list (its value kept,
  // rephrased): Test 3's lead, (0.14732 + 0.0336248) / 0.181819 = 0.995.
  const nlohmann::json lead = {{"baseline_mean", -0.0336248}, {"baseline_sd", 0.181819}, {"readings", {{"test3_directions", {{"mean", 0.14732}}}}}};
  CHECK(restate_shifts_json("most: test3_directions (5 of 5, mean shifted 1.00 sd); would be under other (0.34 sd, t = 0.57)", lead,
                                   0.005) == "most: test3_directions (5 of 5, mean shifted +1.0 sd); would be under other (+0.34 sd, t = 0.57)");
  // Nothing to restate: as it is.
  CHECK(restate_shifts_json("consistent on the full-size ensemble (within the scatter of one sample)", lead, 0.005) ==
        "consistent on the full-size ensemble (within the scatter of one sample)");
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
      "grading", {{{"name", "A"}, {"judged", true}, {"explanation", "no reading does: within scatter; most: grading_by_mass (0 of 5)"}}});
  // No `made_consistent_by` in A (a file written before it): the reading is read from the explanation.
  const std::string dashpot = study(
      "dashpot",
      {{{"name", "A"}, {"judged", true}, {"explanation", "consistent under contact_dashpots (-2.1 sd, t = 2.23), its shift of the mean applied"}},
       {{"name", "B"},
        {"judged", true},
        {"baseline_mean", 0.25},
        {"baseline_sd", 0.1},
        {"readings", {{"contact_dashpots", {{"mean", 0.5}}}}},
        {"made_consistent_by", nlohmann::json::array()},
        {"explanation", "consistent on the full-size ensemble"}},
       {{"name", "C"},
        {"judged", true},
        {"baseline_mean", 1.0},
        {"baseline_sd", 0.1},
        {"readings", {{"contact_dashpots", {{"mean", 1.0}}}}},
        {"explanation", "consistent on the full-size ensemble"}}});
  const std::vector<validation::Row> rows = {row_named("A", 0), row_named("B", 0.01), row_named("C", 0.01)};
  const std::vector<DecisionsFile> files = {validation::read_decisions_file(grading, rows), validation::read_decisions_file(dashpot, rows)};
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

TEST_CASE("the readings an explanation names after \"consistent under\"", "[decisions][validate]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "decisions_file_names";
  fs::remove_all(dir);
  const std::string file = write_json(
      dir / "x" / "decisions.json",
      {{"rows",
        {{{"name", "A"}, {"explanation", "consistent under a_1 (beyond -10 sd (-14), t = 24.34), b.2 (+1.5 sd, t = 2.52), its shift of the mean applied"}},
         {{"name", "B"}, {"explanation", "no reading does: within scatter; would be consistent under c (+1.0 sd, t = 1.41), but"}}}}});
  const DecisionsFile f = validation::read_decisions_file(file, {row_named("A", 0), row_named("B", 0)});
  CHECK(f.rows.at("A").explained_by == std::vector<std::string>{"a_1", "b.2"});
  CHECK(f.rows.at("B").explained_by.empty());  // "would be consistent under" explains nothing
}
