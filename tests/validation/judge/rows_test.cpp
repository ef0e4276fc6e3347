// Reading a reference file (validation/judge/rows.hpp): per-profile entries, the label, and errors that
// name the file, the row and the key with what is allowed.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "config/yaml_section.hpp"
#include "judge/rows.hpp"

namespace fs = std::filesystem;

namespace {

// A reference file of `rows` (YAML list items) in the test folder; returns its path.
std::string reference_file(const std::string& name, const std::string& rows, const std::string& top = "") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "rows_test";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << "source: \"your lab (illustrative)\"\n" << top << "rows:\n" << rows;
  return file.string();
}

const std::string two_rows =
    "  - {name: peak, quantity: peak_friction_angle, test: compression, reference: 35, check: within, tolerance: 1,\n"
    "     source: lab, reason: r, profiles: {small: {tolerance: 4, must_pass: true, reason: \"512 spheres\"}}}\n"
    "  - {name: e_cs, quantity: critical_state_void_ratio, reference: 0.6, check: at_most, source: lab, reason: r}\n";

std::string error_of(const std::string& file, const std::string& profile = "paper") {
  try {
    validation::read_references(file, profile);
  } catch (const dem::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("references: a profile some row names judges only those rows, with their entries", "[references]") {
  const std::string file = reference_file("profiles.yaml", two_rows);
  // `small` is named by the first row: that row alone, with its entry's tolerance, must_pass and reason.
  const validation::References small = validation::read_references(file, "small");
  REQUIRE(small.rows.size() == 1);
  CHECK(small.rows[0].name == "peak");
  CHECK(small.rows[0].tolerance == 4);
  CHECK(small.rows[0].must_pass);
  CHECK(small.rows[0].reason == "512 spheres");
  // A profile no row names (any name: profiles are the study's): every row with its own values.
  for (const char* profile : {"paper", "full", "quick"}) {
    const validation::References all = validation::read_references(file, profile);
    REQUIRE(all.rows.size() == 2);
    CHECK(all.rows[0].tolerance == 1);
    CHECK_FALSE(all.rows[0].must_pass);
    CHECK(all.rows[0].test == "compression");
    CHECK(all.rows[1].test.empty());
    CHECK(all.rows[1].density.empty());  // left to the study (its only density)
  }
  CHECK(validation::read_references(file, "small").label == "reference");  // the default label
  CHECK(validation::read_references(reference_file("label.yaml", two_rows, "label: lab\n"), "small").label == "lab");
}

TEST_CASE("references: paper.yaml's quick rows are its rows with a quick entry", "[references]") {
  // Counted from the file's text, independently of the reader: every row starts with "- {name:",
  // and a row checked at the quick size has "profiles: {quick: {".
  const std::string file = std::string(DEM_SOURCE_DIR) + "/reference_data/paper.yaml";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.str().find(what); at != std::string::npos; at = text.str().find(what, at + 1)) ++n;
    return n;
  };
  const validation::References paper = validation::read_references(file, "paper");
  const validation::References quick = validation::read_references(file, "quick");
  CHECK(paper.label == "paper");
  CHECK(paper.rows.size() == count("- {name:"));
  CHECK(quick.rows.size() == count("profiles: {quick: {"));
  REQUIRE(quick.rows.size() > 0);
  CHECK(quick.rows.size() < paper.rows.size());
  for (const validation::Row& r : quick.rows) CHECK((r.quantity == "void_ratio_after_preparation" || r.quantity == "coordination_after_preparation"));
}

TEST_CASE("references: literature.yaml reads, every row with its source and reason", "[references]") {
  // Counted from the file's text: each row starts with "  - name:" and names a source.
  const std::string file = std::string(DEM_SOURCE_DIR) + "/reference_data/literature.yaml";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::size_t rows = 0;
  for (std::size_t at = text.str().find("\n  - name:"); at != std::string::npos; at = text.str().find("\n  - name:", at + 1)) ++rows;
  const validation::References literature = validation::read_references(file, "paper");
  CHECK(literature.label == "literature");
  REQUIRE(literature.rows.size() == rows);
  for (const validation::Row& r : literature.rows) {
    CHECK_FALSE(r.source.empty());
    CHECK_FALSE(r.reason.empty());
    CHECK(r.density == "dense");  // the rows read the critical-state ensemble's only density
  }
}

TEST_CASE("references: a bad row is refused naming the file, the row and the key, with what is allowed", "[references]") {
  SECTION("an unknown key lists a row's keys") {
    const std::string file = reference_file("typo.yaml", "  - {name: peak, quantity: peak_friction_angle, reference: 35, check: within, tolerence: 1, source: lab, reason: r}\n");
    const std::string e = error_of(file);
    CHECK_THAT(e, Catch::Contains(file + ": rows[0] (\"peak\"): unknown key 'tolerence'"));
    CHECK_THAT(e, Catch::Contains("did you mean 'tolerance'?"));
    CHECK_THAT(e, Catch::Contains("a row's keys: name, group, quantity, variant, density, test,"));
  }
  SECTION("an unknown quantity lists the known ones") {
    const std::string file = reference_file("quantity.yaml", "  - {name: peak, quantity: phi_peak, reference: 35, check: within, source: lab, reason: r}\n");
    const std::string e = error_of(file);
    CHECK_THAT(e, Catch::Contains(file + ": rows[0] (\"peak\").quantity: unknown quantity 'phi_peak'; known: "));
    CHECK_THAT(e, Catch::Contains("peak_friction_angle"));
    CHECK_THAT(e, Catch::Contains("void_ratio_after_preparation"));
  }
  SECTION("a bad value in a profile's entry, and a profile name that is no name") {
    std::string file = reference_file("entry.yaml", "  - {name: peak, quantity: peak_friction_angle, reference: 35, check: within, source: lab, reason: r,\n"
                                                    "     profiles: {small: {tolerance: -1, reason: r}}}\n");
    CHECK_THAT(error_of(file), Catch::Contains(file + ": rows[0] (\"peak\").profiles.small.tolerance: must be in"));
    file = reference_file("entry_name.yaml", "  - {name: peak, quantity: peak_friction_angle, reference: 35, check: within, source: lab, reason: r,\n"
                                              "     profiles: {\"a/b\": {reason: r}}}\n");
    CHECK_THAT(error_of(file), Catch::Contains("rows[0] (\"peak\").profiles: 'a/b' is not a profile name"));
  }
  SECTION("the second row's error names the second row") {
    const std::string file = reference_file("second.yaml", two_rows + "  - {name: third, quantity: ev_growth, reference: 1, check: sometimes, source: s, reason: r}\n");
    CHECK_THAT(error_of(file), Catch::Contains(file + ": rows[2] (\"third\").check: must be one of: within, at_least, at_most"));
  }
}

namespace {

// A row "within `tolerance` of 10", judged on hand-made per-sample values.
validation::RowResult judged(const std::vector<double>& values, double tolerance, const std::string& rule = "interval",
                             const std::string& misfit = "") {
  validation::Row row;
  row.name = "x", row.check = "within", row.reference = 10, row.tolerance = tolerance, row.rule = rule;
  std::vector<validation::RowResult::PerSample> samples;
  for (double v : values) samples.push_back({"s", {v, "", misfit}});
  return validation::judge_values(row, samples);
}

}  // namespace

TEST_CASE("verdicts warn when the samples are too few for the row's tolerance", "[references][warnings]") {
  // Two samples 10 and 12: mean 11, sd sqrt(2), interval 11 -/+ t(0.975, 1) sqrt(2) sqrt(1.5)
  // = 11 -/+ 12.706 x 1.7321 = 11 -/+ 22.01: 44.0 wide. Against a tolerance of 1 (44 times) the
  // verdict, consistent, is near automatic and warned about; against 11.1 (3.97 times), not.
  const validation::RowResult wide = judged({10, 12}, 1);
  CHECK(wide.verdict == validation::Verdict::Consistent);
  REQUIRE(wide.warnings.size() == 1);
  CHECK(wide.warnings[0].rfind("samples too few to judge: the interval of one sample (44 wide, 2 samples) is 44 times the tolerance 1", 0) == 0);
  CHECK(judged({10, 12}, 11.1).warnings.empty());
  CHECK(judged({10, 12}, 10.9).warnings.size() == 1);  // 4.04 times
  // Five samples 9.9, 10, 10, 10, 10.1: sd 0.0707, interval 10 -/+ 2.776 x 0.0707 x 1.0954 = 0.43
  // wide, 0.86 times a tolerance of 0.5: no warning.
  CHECK(judged({9.9, 10, 10, 10, 10.1}, 0.5).warnings.empty());
  // Trends (rule majority) read no interval, and a check without a tolerance has nothing to compare.
  CHECK(judged({10, 12}, 1, "majority").warnings.empty());
  CHECK(judged({10, 12}, 0).warnings.empty());
}

TEST_CASE("a consistent verdict with no sample in the paper's region says it is consistent by width only", "[references][warnings]") {
  // Three samples 10.6, 10.7, 10.8 against 10 +/- 0.5: none in [9.5, 10.5]; mean 10.7, sd 0.1,
  // interval 10.7 -/+ t(0.975, 2) 0.1 sqrt(4/3) = 10.7 -/+ 4.303 x 0.1155 = [10.203, 11.197], which
  // reaches 10.5: consistent, and flagged. Its width, 0.99, is under 4 x 0.5: no other warning.
  const validation::RowResult wide = judged({10.6, 10.7, 10.8}, 0.5);
  CHECK(wide.verdict == validation::Verdict::Consistent);
  CHECK(wide.holds == 0);
  CHECK(wide.warnings == std::vector<std::string>{
                             "consistent by width only: none of the 3 samples lies in the paper's region; the interval of one sample reaches it"});
  // One sample inside (10.45; the interval then 1.6 wide, under 2): no flag; the verdict
  // inconsistent (all three at 11.6-11.8): no flag.
  CHECK(judged({10.45, 10.7, 10.75}, 0.5).warnings.empty());
  const validation::RowResult far = judged({11.6, 11.7, 11.8}, 0.5);
  CHECK(far.verdict == validation::Verdict::Inconsistent);
  CHECK(far.warnings.empty());
}

TEST_CASE("verdicts carry each distinct misfit of their samples' values once", "[references][warnings]") {
  const validation::RowResult r = judged({10, 10.5, 9.5}, 5, "interval", "does not fit");
  CHECK(r.warnings == std::vector<std::string>{"does not fit"});
}

TEST_CASE("a quasi-static reference is not judged on runs at a finite rate", "[references][warnings]") {
  // 10.6, 10.7, 10.8 against 10 +/- 0.5 is consistent (by width only, above); and 14, 15, 16 is
  // inconsistent. Declared quasi-static, both are not judged, the values kept, the reason first.
  validation::Row row;
  row.name = "x", row.check = "within", row.reference = 10, row.tolerance = 0.5, row.quasi_static = true;
  for (const std::vector<double>& values : {std::vector<double>{10.6, 10.7, 10.8}, std::vector<double>{14, 15, 16}}) {
    std::vector<validation::RowResult::PerSample> samples;
    for (double v : values) samples.push_back({"s", {v, "", ""}});
    const validation::RowResult r = validation::judge_values(row, samples);
    CHECK(r.verdict == validation::Verdict::NotJudged);
    CHECK(r.valued == 3);
    REQUIRE_FALSE(r.warnings.empty());
    CHECK(r.warnings[0].rfind("not judged: the reference holds in the quasi-static limit", 0) == 0);
    // Not called consistent, so never "consistent by width only" (14, 15, 16 do warn that their
    // interval, 2 x 4.303 x 1 x sqrt(4/3) = 9.94 wide, is 19.9 times the tolerance).
    for (const std::string& w : r.warnings) CHECK(w.find("by width only") == std::string::npos);
  }
  // The warning points to the critical-state section only for a quantity that section takes to
  // I -> 0 (its rate series fits the friction angle, critical_state_rates.cpp); a quasi-static
  // void ratio, which no section extrapolates, is said to have none (the report once pointed to
  // "the critical-state void ratio at I -> 0", computed nowhere).
  std::vector<validation::RowResult::PerSample> samples;
  for (double v : {10.6, 10.7, 10.8}) samples.push_back({"s", {v, "", ""}});
  row.quantity = "critical_state_friction_angle";
  CHECK(validation::judge_values(row, samples).warnings[0].find("the critical-state section compares it with its rate series taken to I -> 0") !=
        std::string::npos);
  row.quantity = "critical_state_void_ratio";
  const std::string none = validation::judge_values(row, samples).warnings[0];
  CHECK(none.find("critical-state section") == std::string::npos);
  CHECK(none.find("no section takes critical_state_void_ratio to I -> 0") != std::string::npos);
  // literature.yaml declares its two critical-state rows so.
  const validation::References literature =
      validation::read_references(std::string(DEM_SOURCE_DIR) + "/reference_data/literature.yaml", "paper");
  int quasi_static = 0;
  for (const validation::Row& r : literature.rows) quasi_static += r.quasi_static;
  CHECK(quasi_static == 2);
}
