// build/bin/report on a copy of the committed reports/ with stamps put in: the paper study's in
// validation.json, the decisions study's (same baseline and engine) in decisions.json, the critical
// state's (another baseline) in critical_state/stamp.json. The report is refused, exit 1, naming
// the section, both baselines and the option, and index.md is left as it was; with
// --allow-other-baseline it is written, the section headed ⚠ and named in the header.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string source = DEM_SOURCE_DIR;
const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

// `file`'s JSON with `key` set to `value`, the other keys kept in their order.
void set_key(const fs::path& file, const std::string& key, const nlohmann::ordered_json& value) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(dem::test::read_bytes(file.string()));
  j[key] = value;
  std::ofstream(file) << j.dump(1) << "\n";
}

}  // namespace

TEST_CASE("report: a section from another baseline refused, then kept under ⚠ with --allow-other-baseline", "[report][stamp][cli]") {
  const fs::path dir = dem::test::scratch_dir("report_stamps_cli");
  const fs::path out = dir / "reports";
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  const nlohmann::ordered_json paper = {{"engine", "0.1.0+aaaa"}, {"baseline", "1111111111111111"}, {"spheres", 8000}, {"samples", 5}, {"date", "2026-11-27"}};
  set_key(out / "validation.json", "stamp", paper);
  set_key(out / "study_values.json", "stamp", paper);  // the values from the same results
  set_key(out / "decisions" / "decisions.json", "stamp",
          {{"engine", "0.1.0+aaaa"}, {"baseline", "1111111111111111"}, {"spheres", 1000}, {"samples", 3}, {"date", "2026-11-02"}});
  // The committed convergence summary has its own (real) baseline: put it on the paper's here, so
  // that the critical state is the one section from another baseline.
  set_key(out / "convergence" / "summary.json", "baseline", "1111111111111111");
  set_key(out / "literature" / "validation.json", "stamp", paper);  // judged on results of their own, stamped
  fs::remove(out / "liquefaction" / "stamp.json");  // a section made before stamps: said so, not refused
  std::ofstream(out / "critical_state" / "stamp.json")
      << R"({"engine": "0.1.0+aaaa", "baseline": "2222222222222222", "spheres": 8000, "samples": 1, "date": "2026-11-25"})" << "\n";
  const std::string before = dem::test::read_bytes((out / "index.md").string());
  const std::string report = "cd '" + source + "' && '" + bin + "report' --results '" + (dir / "no_results").string() +
                             "' --references reference_data/paper.yaml --out '" + out.string() + "' --sample seed1";
  const auto refused = dem::test::run_command(report + " 2>&1");
  INFO(refused.out);
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.out, Catch::Contains("Critical state: friction, void ratio and coordination against μ") && Catch::Contains("2222222222222222") &&
                              Catch::Contains("1111111111111111") && Catch::Contains("--allow-other-baseline"));
  CHECK(dem::test::read_bytes((out / "index.md").string()) == before);  // not written
  const auto kept = dem::test::run_command(report + " --allow-other-baseline 2>&1");
  INFO(kept.out);
  REQUIRE(kept.exit_code == 0);
  const std::string text = dem::test::read_bytes((out / "index.md").string());
  CHECK_THAT(text, Catch::Contains("The paper study's numbers were made by engine `0.1.0+aaaa` on baseline `1111111111111111` (8,000 spheres, "
                                   "5 samples, 2026-11-27)"));
  CHECK_THAT(text, Catch::Contains("\n⚠ Made on another baseline or engine than the paper study's, or not stamped, kept by `report --allow-other-baseline` "
                                   "and counted in no verdict: \"Critical state: friction, void ratio and coordination against μ\" "
                                   "(another baseline).\n"));
  CHECK_THAT(text, Catch::Contains("\n## Appendix: ⚠ from another baseline: Critical state: friction, void ratio and coordination against μ\n\n"
                                   "*⚠ Made by engine `0.1.0+aaaa` on baseline `2222222222222222` (8,000 spheres, 1 sample, 2026-11-25)"));
  CHECK_THAT(text, Catch::Contains("\n## Appendix: What the paper's open choices change\n\n*Made by engine `0.1.0+aaaa` on baseline "
                                   "`1111111111111111` (1,000 spheres, 3 samples, 2026-11-02).*\n"));
  CHECK_THAT(text, Catch::Contains("\n## Appendix: Liquefaction: cyclic stress ratio against cycles\n\n*Stamp not recorded: made before stamps "
                                   "(its engine and baseline are unknown).*\n"));
  // Written again: the same text (the date aside, which is today's both times).
  const auto again = dem::test::run_command(report + " --allow-other-baseline 2>&1");
  INFO(again.out);
  REQUIRE(again.exit_code == 0);
  CHECK(dem::test::read_bytes((out / "index.md").string()) == text);
}

TEST_CASE("report: values read back from other results than validation.json judged are refused", "[report][stamp][cli]") {
  const fs::path dir = dem::test::scratch_dir("report_values_cli");
  const fs::path out = dir / "reports";
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  REQUIRE(fs::exists(out / "study_values.json"));
  set_key(out / "validation.json", "stamp",
          {{"engine", "0.1.0+aaaa"}, {"baseline", "1111111111111111"}, {"spheres", 8000}, {"samples", 5}, {"date", "2026-11-27"}});
  set_key(out / "study_values.json", "stamp",
          {{"engine", "0.1.0+bbbb"}, {"baseline", "3333333333333333"}, {"spheres", 1000}, {"samples", 3}, {"date", "2026-11-26"}});
  const std::string before = dem::test::read_bytes((out / "index.md").string());
  const std::string report = "cd '" + source + "' && '" + bin + "report' --results '" + (dir / "no_results").string() +
                             "' --references reference_data/paper.yaml --out '" + out.string() + "' --sample seed1";
  const auto refused = dem::test::run_command(report + " 2>&1");
  INFO(refused.out);
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.out, Catch::Contains("study_values.json was written from results on another baseline") &&
                              Catch::Contains("3333333333333333") && Catch::Contains("1111111111111111"));
  CHECK(dem::test::read_bytes((out / "index.md").string()) == before);
  // Kept on purpose: said in the header, with the stamp of the values.
  set_key(out / "convergence" / "summary.json", "baseline", "1111111111111111");
  const auto kept = dem::test::run_command(report + " --allow-other-baseline 2>&1");
  INFO(kept.out);
  REQUIRE(kept.exit_code == 0);
  const std::string text = dem::test::read_bytes((out / "index.md").string());
  CHECK_THAT(text, Catch::Contains("the values of `" + (out / "study_values.json").string() + "` (another baseline)"));
  CHECK_THAT(text, Catch::Contains("made by engine `0.1.0+bbbb` on baseline `3333333333333333` (1,000 spheres, 3 samples, 2026-11-26)"));
  // A file that is not of this shape: exit 1, naming it.
  std::ofstream(out / "study_values.json") << R"({"values": {"a": 1}})" << "\n";
  const auto bad = dem::test::run_command(report + " 2>&1");
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.out, Catch::Contains("study_values.json: value \"a\" is not text"));
}

TEST_CASE("report: a validation.json that judged other results than --results is refused", "[report][stamp][cli]") {
  // Found by a hostile sweep: report took the validation.json of another study beside its
  // --results and showed its verdicts as this study's. The results here: the shipped 1,000-sphere
  // samples as the dense preparations of three samples; validate stamps its validation.json with
  // their engine, baseline, spheres and samples. That record is accepted; the same record with
  // another sample count or sphere count (another profile) or another baseline is refused, naming
  // both values, unless --allow-other-baseline keeps it (said in the header).
  const fs::path dir = dem::test::scratch_dir("report_judged_cli");
  const fs::path results = dir / "results", out = dir / "reports";
  fs::create_directories(results);
  std::ofstream runs(results / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  const char* packings[] = {"dense_1k.h5", "medium_1k.h5", "loose_1k.h5"};
  for (int seed = 1; seed <= 3; ++seed) {
    const fs::path s = results / ("seed" + std::to_string(seed));
    fs::create_directories(s);
    fs::copy_file(source + "/scenes/samples/" + packings[seed - 1], s / "dense_prepare.h5");
    runs << "-\tdense\t-\tseed" << seed << "/dense_prepare\t/x/seed" << seed << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
  }
  runs.close();
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  std::ofstream(dir / "refs.yaml") << "source: lab\nrows:\n  - {name: e0, quantity: void_ratio_after_preparation, density: dense, "
                                      "reference: 0.6, check: within, tolerance: 0.2, source: s, reason: r}\n";
  const auto validated = dem::test::run_command("'" + bin + "validate' --results '" + results.string() + "' --references '" +
                                                (dir / "refs.yaml").string() + "' --out '" + (dir / "judged").string() + "' 2>&1");
  INFO(validated.out);
  const nlohmann::ordered_json judged = nlohmann::ordered_json::parse(dem::test::read_bytes((dir / "judged" / "validation.json").string()));
  const nlohmann::ordered_json stamp = judged.at("stamp");
  REQUIRE(stamp.at("samples") == 3);
  REQUIRE(stamp.at("spheres") == 1000);
  const std::string report = "cd '" + source + "' && '" + bin + "report' --results '" + results.string() +
                             "' --references reference_data/paper.yaml --out '" + out.string() + "' --sample seed1";
  const std::string refusal = "judged other results than --results";
  set_key(out / "validation.json", "stamp", stamp);
  const auto same = dem::test::run_command(report + " 2>&1");
  INFO(same.out);
  CHECK(same.out.find(refusal) == std::string::npos);
  struct Other {
    std::string key;
    nlohmann::ordered_json value;
    std::string said;
  };
  for (const Other& o : {Other{"samples", 5, "samples (3 here, 5 judged)"}, Other{"spheres", 8000, "spheres (1000 here, 8000 judged)"},
                         Other{"baseline", "2222222222222222", "2222222222222222 judged)"}}) {
    INFO(o.key);
    nlohmann::ordered_json other = stamp;
    other[o.key] = o.value;
    set_key(out / "validation.json", "stamp", other);
    const std::string before = dem::test::read_bytes((out / "index.md").string());
    const auto refused = dem::test::run_command(report + " 2>&1");
    INFO(refused.out);
    CHECK(refused.exit_code == 1);
    CHECK_THAT(refused.out, Catch::Contains(refusal) && Catch::Contains(o.said) && Catch::Contains("--allow-other-baseline"));
    CHECK(dem::test::read_bytes((out / "index.md").string()) == before);  // not written
  }
}

// The class behind a section headed ⚠ that the header did not name (the earlier baseline's
// comparison, whose table is filled after the header's list was made): on the committed reports
// with the earlier baseline given, every heading "## Appendix: ⚠ from another ...: NAME" is named
// in the header's list.
TEST_CASE("report: the header names every section it heads with ⚠", "[report][stamp][cli]") {
  const fs::path dir = dem::test::scratch_dir("report_stamps_header");
  const fs::path out = dir / "reports";
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  const std::string report = "cd '" + source + "' && '" + bin + "report' --results '" + (dir / "no_results").string() +
                             "' --references reference_data/paper.yaml --out '" + out.string() +
                             "' --sample seed1 --baseline reports/baselines/orthorhombic_validation.json --allow-other-baseline 2>&1";
  const auto run = dem::test::run_command(report);
  INFO(run.out);
  REQUIRE(run.exit_code == 0);
  const std::string text = dem::test::read_bytes((out / "index.md").string());
  const std::string banner_start = "\n⚠ Made on another baseline or engine than the paper study's";
  const std::size_t banner_at = text.find(banner_start);
  REQUIRE(banner_at != std::string::npos);
  const std::string banner = text.substr(banner_at, text.find('\n', banner_at + 1) - banner_at);
  const std::string mark = "\n## Appendix: ⚠ from another ";
  int headed = 0;
  for (std::size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1)) {
    const std::size_t name_at = text.find(": ", at + mark.size()) + 2, end = text.find('\n', name_at);
    const std::string name = text.substr(name_at, end - name_at);
    INFO("headed ⚠: " << name);
    CHECK_THAT(banner, Catch::Contains("\"" + name + "\""));
    ++headed;
  }
  CHECK(headed >= 1);  // the earlier baseline's comparison at least: another engine's
}
