// Each number once per sentence (validation/report/prose_numbers.hpp): a sentence stating one
// quantity in two roundings is found; values set side by side (lists, ranges, ±) are not.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "report/prose_numbers.hpp"

using validation::numbers_restated;

TEST_CASE("prose: one number in two roundings in a sentence is found", "[report][prose]") {
  SECTION("the effective sample size as 1340 and 1300") {
    const auto found = numbers_restated(
        "Intro.\n\n96 parameter sets in 6 iterations of 16 (5184 runs, 869 core-min recorded); effective sample size 1340; not "
        "converged: it rests on 1300 effective points, 16.0 asked. The next sentence has 1300 alone.\n");
    REQUIRE(found.size() == 1);
    CHECK(found[0].longer == "1340");
    CHECK(found[0].shorter == "1300");
    CHECK(found[0].sentence.rfind("96 parameter sets", 0) == 0);
  }
  SECTION("a maximum of 0.0001237 said to stay below its own rounding, 0.00012") {
    const auto found = numbers_restated("The largest dense |εv| is 0.0001237 %, so it stays below 0.00012 % after 5 cycles.");
    REQUIRE(found.size() == 1);
    CHECK(found[0].longer == "0.0001237");
    CHECK(found[0].shorter == "0.00012");
  }
  SECTION("thousands separators: 12,345 and 12,000 runs") {
    const auto found = numbers_restated("The study made 12,345 runs, about 12,000 runs of one core.");
    REQUIRE(found.size() == 1);
    CHECK(found[0].longer == "12,345");
    CHECK(found[0].shorter == "12,000");
  }
}

TEST_CASE("prose: values set side by side, names and code are not a number said twice", "[report][prose]") {
  // Each from the committed report: the paper's values beside ours, a sample range beside its mean,
  // a bound above its value, names with digits, a version and a path in code.
  for (const std::string sentence : {
           "A void ratio of 0.7328 ± 0.0020 (loose), 0.6783 ± 0.0021 (medium) and 0.5563 ± 0.0011 (dense) against the paper's 0.73, 0.67 and 0.57.",
           "The slope is 1.0770 ± 0.0063 (medium, 1.07–1.08).",
           "The cell shrinks to 7.32 / 7.23 / 7.06 cm, where the paper gives 7.3 / 7.2 / 7.1 cm.",
           "The largest dense |εv| is 0.0001237 %: it stays below 0.00013 %.",
           "Test 3 visits TC1, A, TE1, A, TC2 in cycle 1 of 5, on seed13 and seed1.",
           "Made by engine `0.1.0+3d448a9766e3` on `results/study/paper/seed1`, see [the table](causes.md#cause-13) for 13.",
           "| 1340 | 1300 |",
           "5 samples of 8,000 spheres, 5 tests of 5 cycles.",
       }) {
    INFO(sentence);
    CHECK(numbers_restated(sentence).empty());
  }
}

TEST_CASE("prose: the report as committed states no number in two roundings outside its calibration sections", "[report][prose]") {
  // The scan over the whole generated report: each sentence it finds is one of the calibration
  // sections' "effective sample size 1340; ... rests on 1300 effective points" (the stop reason
  // written by a calibrate that rounded it to two digits; written again, both give three), and none
  // elsewhere.
  std::ifstream in(std::filesystem::path(DEM_SOURCE_DIR) / "reports" / "index.md");
  REQUIRE(in);
  const std::string text(std::istreambuf_iterator<char>(in), {});
  for (const validation::RestatedNumber& r : numbers_restated(text)) {
    INFO(r.sentence);
    CHECK(r.sentence.find("effective sample size") != std::string::npos);
  }
}
