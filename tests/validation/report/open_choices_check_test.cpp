// The open choices' best set at the paper's size, set beside the calibration and the paper study:
// its counts as the records give them, a table of only the rows not consistent everywhere, and a
// check of another set than the calibration's best refused. On fixture report folders.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "report/open_choices_check.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void write_json(const fs::path& file, const json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(1) << "\n";
}

json stamp(long spheres, long samples) {
  return {{"engine", "0.1.0+aaaa"}, {"engine_source", "1234 schema 4"}, {"baseline", "b"}, {"spheres", spheres}, {"samples", samples},
          {"date", "2026-11-29"}};
}

// Three rows: A consistent everywhere, B inconsistent only at the check, C inconsistent in the paper study.
json validation_record(const std::string& b, const std::string& c, long spheres, long samples, const json& variants) {
  json j{{"stamp", stamp(spheres, samples)}, {"judged_from", {{"results", "r"}}}, {"complete", true}, {"missing_results", json::array()}};
  if (!variants.is_null()) j["judged_from"]["variants"] = variants;
  j["rows"] = {{{"name", "A"}, {"verdict", "consistent"}}, {{"name", "B"}, {"verdict", b}}, {{"name", "C"}, {"verdict", c}}};
  int consistent = 1 + (b == "consistent") + (c == "consistent");
  int not_judged = (b == "not judged") + (c == "not judged");
  j["consistent"] = consistent, j["not_judged"] = not_judged, j["inconsistent"] = 3 - consistent - not_judged, j["total"] = 3;
  return j;
}

json posterior_record() {
  json per_row = {{{"name", "A"}, {"consistent_at_best_set", true}},
                  {{"name", "B"}, {"consistent_at_best_set", true}},
                  {{"name", "C"}, {"consistent_at_best_set", true}}};
  return {{"best_set", {{"name", "i6s013"}, {"chi2", 1.0}}},
          {"stamp", stamp(512, 3)},
          {"rows_consistent", {{"best_set", {{"name", "i6s013"}, {"consistent", 3}, {"judged", 3}}}, {"per_row", per_row}}}};
}

}  // namespace

TEST_CASE("open choices' check: counts from the records, only the rows not consistent everywhere", "[report][open_choices]") {
  const fs::path report = dem::test::scratch_dir("open_choices_check_counts");
  REQUIRE(validation::open_choices_check_text(report).empty());  // not run: nothing
  write_json(report / "calibration/paper_open_choices/posterior.json", posterior_record());
  REQUIRE(validation::open_choices_check_text(report).empty());  // calibrated, not checked: nothing
  write_json(report / "calibration/paper_open_choices/best/validation.json",
             validation_record("inconsistent", "consistent", 8000, 3, json::array({"i6s013"})));
  write_json(report / "validation.json", validation_record("consistent", "inconsistent", 8000, 5, nullptr));
  const std::string text = validation::open_choices_check_text(report);
  CHECK(text.find("At 8,000 spheres, 3 samples per density, **2 of 3** rows are consistent (1 inconsistent, 0 not judged)") != std::string::npos);
  CHECK(text.find("at the calibration's 512 spheres, 3 samples, the same set made 3 of 3 consistent") != std::string::npos);
  CHECK(text.find("| the paper study (8,000 spheres, 5 samples) | best set, calibration (512 spheres, 3 samples) |") != std::string::npos);
  CHECK(text.find("| A |") == std::string::npos);  // consistent in each: not listed
  CHECK(text.find("| B | ✅ consistent | ✅ consistent | ❌ inconsistent |") != std::string::npos);
  CHECK(text.find("| C | ❌ inconsistent | ✅ consistent | ✅ consistent |") != std::string::npos);
  CHECK(text.find("Incomplete") == std::string::npos);
  CHECK(text.find("Another engine") == std::string::npos);
  CHECK(text.find("⚠") == std::string::npos);  // no weak verdict: no mark, no legend
  // A weak verdict of the paper study (B consistent by width only) is marked as everywhere, with the legend.
  json weak = validation_record("consistent", "inconsistent", 8000, 5, nullptr);
  weak["rows"][1]["warnings"] = json::array({"consistent by width only: none of the 5 samples lies in the paper's region"});
  write_json(report / "validation.json", weak);
  const std::string marked = validation::open_choices_check_text(report);
  CHECK(marked.find("| B | ✅ consistent ⚠ | ✅ consistent | ❌ inconsistent |") != std::string::npos);
  CHECK(marked.find("⚠ marks a verdict that cannot mean much") != std::string::npos);
}

TEST_CASE("open choices' check: a check of another set than the calibration's best is not set beside it", "[report][open_choices]") {
  const fs::path report = dem::test::scratch_dir("open_choices_check_other_set");
  write_json(report / "calibration/paper_open_choices/posterior.json", posterior_record());
  write_json(report / "calibration/paper_open_choices/best/validation.json",
             validation_record("consistent", "consistent", 8000, 3, json::array({"i2s006"})));
  std::string text = validation::open_choices_check_text(report);
  CHECK(text.find("⚠ The check in `calibration/paper_open_choices/best/` judged the set(s) i2s006, not the calibration's best set `i6s013`") !=
        std::string::npos);
  CHECK(text.find("rows are consistent") == std::string::npos);
  // A record made before validate named its variants: not taken for the best set's either.
  write_json(report / "calibration/paper_open_choices/best/validation.json", validation_record("consistent", "consistent", 8000, 3, nullptr));
  text = validation::open_choices_check_text(report);
  CHECK(text.find("judged a study that does not name its set") != std::string::npos);
  CHECK(text.find("rows are consistent") == std::string::npos);
}
