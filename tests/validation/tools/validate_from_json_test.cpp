// validate --from-json: every row judged again from the per-sample values an earlier validate
// recorded in its validation.json, without the results. On a study of real results (the shipped
// 1,000-sphere samples as the preparations of three samples), the tables written from the results
// and from their own validation.json are the same, byte for byte, but for their first line (what
// was judged); a FILE that is missing, not JSON or not a validation.json is an error naming it,
// exit 2. On the committed reports/validation.json, with the decisions files the report passes,
// every cell of the compact verdict table is at most 80 characters, and each cause links to its entry.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "judge/verdicts.hpp"
#include "validation/markdown_cells.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/validate";
const std::string source = DEM_SOURCE_DIR;

dem::test::CommandResult validate(const std::string& args) { return dem::test::run_command("'" + bin + "' " + args + " 2>&1"); }

std::string text_of(const fs::path& p) { return dem::test::read_bytes(p.string()); }

// The text after its first line (the provenance line) and the blank line after it.
std::string after_first_line(const std::string& text) {
  const std::size_t end = text.find('\n');
  return end == std::string::npos ? "" : text.substr(end + 1);
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

// The cells of each line of the first Markdown table in `text` (its lines start with '|'), "\|"
// kept as is (the limit counts the Markdown).
std::vector<std::vector<std::string>> table_cells(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != '|') {
      if (!out.empty()) break;
      continue;
    }
    out.push_back(dem::test::markdown_cells(line, dem::test::Escaped::Keep));
  }
  return out;
}

// A study of one density, three samples: the shipped dense, medium and loose 1,000-sphere samples
// as the dense preparations of seed1..3 (three packings, so three distinct values per row).
fs::path make_study(const fs::path& dir) {
  const std::vector<std::string> packings = {"dense_1k.h5", "medium_1k.h5", "loose_1k.h5"};
  fs::create_directories(dir / "results");
  std::ofstream runs(dir / "results" / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  for (int seed = 1; seed <= 3; ++seed) {
    const fs::path s = dir / "results" / ("seed" + std::to_string(seed));
    fs::create_directories(s);
    fs::copy_file(source + "/scenes/samples/" + packings[seed - 1], s / "dense_prepare.h5", fs::copy_options::overwrite_existing);
    runs << "-\tdense\t-\tseed" << seed << "/dense_prepare\t/x/seed" << seed << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
  }
  return dir / "results";
}

}  // namespace

TEST_CASE("validate --from-json: the tables judged again from validation.json are those judged from the results", "[validate][cli][from-json]") {
  const fs::path dir = dem::test::scratch_dir("validate_from_json_same");
  const fs::path results = make_study(dir);
  // An interval row (consistent or not, whatever the packings give), a trend of every sample, and a
  // row no sample can meet (a void ratio of 5): inconsistent, with the decisions study's cause.
  std::ofstream(dir / "refs.yaml") << "source: lab\nlabel: lab\nrows:\n"
      "  - {name: \"e0 (void ratio)\", quantity: void_ratio_after_preparation, reference: 0.6, check: within, tolerance: 0.1, source: s, reason: r}\n"
      "  - {name: CN, quantity: coordination_after_preparation, rule: majority, reference: 3, check: at_least, source: s, reason: r}\n"
      "  - {name: \"e0 far off\", quantity: void_ratio_after_preparation, reference: 5, check: within, tolerance: 0.1, source: s, reason: r}\n";
  std::ofstream(dir / "decisions.json") << R"({"schema": 2, "rows": [{"name": "e0 far off", "judged": true, "made_consistent_by": [], "outcome": "unexplained",
      "explanation": "unexplained: no reading makes it consistent; the interval of the baseline misses the paper by 4.300"}]})";
  const std::string refs = (dir / "refs.yaml").string(), decisions = (dir / "decisions.json").string();
  const auto from_results = validate("--results '" + results.string() + "' --references '" + refs + "' --out '" + (dir / "a").string() +
                                     "' --decisions '" + decisions + "'");
  INFO(from_results.out);
  REQUIRE(fs::exists(dir / "a" / "validation.json"));
  CHECK(from_results.exit_code == 0);  // nothing missing, nothing must pass
  const auto again = validate("--from-json '" + (dir / "a" / "validation.json").string() + "' --references '" + refs + "' --out '" +
                              (dir / "b").string() + "' --decisions '" + decisions + "'");
  INFO(again.out);
  CHECK(again.exit_code == from_results.exit_code);
  for (const char* file : {"verdicts.md", "validation.md", "causes.md"}) {
    INFO(file);
    const std::string a = text_of(dir / "a" / file), b = text_of(dir / "b" / file);
    REQUIRE_FALSE(a.empty());
    CHECK(after_first_line(a) == after_first_line(b));
    CHECK_THAT(first_line(a), Catch::Contains("Judged by `validate` from the results in `" + results.string() + "`"));
    CHECK_THAT(first_line(b), Catch::Contains("Judged again by `validate --from-json` from the per-sample values recorded in `" +
                                              (dir / "a" / "validation.json").string() + "`"));
  }
  // The verdicts are those of the rows as written: 0.6 +/- 0.1 and CN >= 3 hold for packings of
  // e = 0.55-0.73 and CN 4.2-6.1 (the three shipped samples), e = 5 does not.
  const nlohmann::json ja = nlohmann::json::parse(text_of(dir / "a" / "validation.json"));
  const nlohmann::json jb = nlohmann::json::parse(text_of(dir / "b" / "validation.json"));
  CHECK(ja.at("rows") == jb.at("rows"));
  CHECK(ja.at("rows")[2].at("verdict") == "inconsistent");
  CHECK(ja.at("rows")[1].at("verdict") == "consistent");
  CHECK(jb.at("judged_from").at("validation_json") == (dir / "a" / "validation.json").string());
  // The cause links to its entry: causes.md#cause-3, "### Cause 3" there.
  CHECK_THAT(text_of(dir / "b" / "verdicts.md"), Catch::Contains("[no reading explains it](causes.md#cause-3)"));
  CHECK_THAT(text_of(dir / "b" / "causes.md"), Catch::Contains("\n### Cause 3\n\n**e0 far off**: ❌ inconsistent"));
  // As the report includes it: the same text, each cause linked into the same document.
  std::string in_report = text_of(dir / "b" / "verdicts.md");
  for (std::size_t at; (at = in_report.find("](causes.md#")) != std::string::npos;) in_report.erase(at + 2, 9);
  CHECK(text_of(dir / "b" / "verdicts_in_report.md") == in_report);
  CHECK_THAT(in_report, Catch::Contains("[no reading explains it](#cause-3)"));
  // Judged again from its own output once more: the same again.
  const auto third = validate("--from-json '" + (dir / "b" / "validation.json").string() + "' --references '" + refs + "' --out '" +
                              (dir / "b").string() + "' --decisions '" + decisions + "'");
  CHECK(third.exit_code == from_results.exit_code);
  CHECK(after_first_line(text_of(dir / "a" / "verdicts.md")) == after_first_line(text_of(dir / "b" / "verdicts.md")));
}

TEST_CASE("validate --from-json: a missing, malformed or foreign FILE is an error naming it, exit 2", "[validate][cli][from-json]") {
  const fs::path dir = dem::test::scratch_dir("validate_from_json_bad");
  const std::string refs = source + "/reference_data/paper.yaml";
  const auto run = [&](const std::string& file) {
    return validate("--from-json '" + file + "' --references '" + refs + "' --out '" + (dir / "out").string() + "'");
  };
  struct Case {
    std::string name, content, message;
  };
  const std::string f = (dir / "v.json").string();
  for (const Case& c : std::vector<Case>{
           {"not JSON", "{\"rows\": [", f + ": not JSON"},
           {"not an object", "[1, 2]", f + ": is array, expected an object"},
           {"no samples", R"({"profile": "paper", "rows": []})", f + ": samples: missing"},
           {"a value of the wrong type", R"({"profile": "paper", "samples": ["seed1"], "missing_samples": [], "missing_results": [],
              "rows": [{"name": "e0, loose", "density": "loose", "per_sample": [{"sample": "seed1", "value": "0.73"}]}]})",
            f + ": rows[0].per_sample[0].value: is string, expected a number or null"},
           {"a row of the reference file missing", R"({"profile": "paper", "samples": [], "missing_samples": [], "missing_results": [],
              "rows": []})", f + " has no row 'e0, loose' of " + refs},
       }) {
    INFO(c.name);
    std::ofstream(f, std::ios::trunc) << c.content;
    const auto r = run(f);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains("error: --from-json " + c.message));
    CHECK_FALSE(fs::exists(dir / "out" / "verdicts.md"));
  }
  const auto missing = run((dir / "nothing.json").string());
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.out, Catch::Contains("--from-json '" + (dir / "nothing.json").string() + "' does not exist"));
  // --results and --from-json together, or neither: exit 2.
  CHECK(validate("--results '" + dir.string() + "' --from-json '" + f + "' --references '" + refs + "' --out '" + (dir / "out").string() + "'")
            .exit_code == 2);
  const auto neither = validate("--references '" + refs + "' --out '" + (dir / "out").string() + "'");
  CHECK(neither.exit_code == 2);
  CHECK_THAT(neither.out, Catch::Contains("one of --results"));
}

TEST_CASE("validate --from-json on the committed validation: every compact cell at most 80 characters, each cause linked", "[validate][cli][from-json][report]") {
  const fs::path dir = dem::test::scratch_dir("validate_from_json_committed");
  std::string decisions = " --decisions '" + source + "/reports/decisions/decisions.json'";
  for (const char* r : {"loose", "medium_dense", "dashpot"})  // the Makefile's READINGS
    if (fs::exists(source + "/reports/readings/" + r + "/decisions.json"))
      decisions += " --decisions '" + source + "/reports/readings/" + r + "/decisions.json'";
  const auto r = validate("--from-json '" + source + "/reports/validation.json' --references '" + source +
                          "/reference_data/paper.yaml' --out '" + dir.string() + "'" + decisions);
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  const std::string verdicts = text_of(dir / "verdicts.md"), causes = text_of(dir / "causes.md");
  const auto table = table_cells(verdicts);
  const nlohmann::json j = nlohmann::json::parse(text_of(dir / "validation.json"));
  REQUIRE(table.size() == j.at("rows").size() + 2);  // heading, delimiter, a line per row
  int linked = 0;
  for (const auto& line : table)
    for (const std::string& cell : line) {
      INFO(cell);
      CHECK(validation::code_points(cell) <= validation::compact_cell_limit);
      const std::size_t at = cell.find("](causes.md#cause-");
      if (at == std::string::npos) continue;
      ++linked;
      const std::string n = cell.substr(at + 18, cell.size() - at - 19);
      CHECK_THAT(causes, Catch::Contains("\n### Cause " + n + "\n"));
    }
  CHECK(linked == j.at("inconsistent").get<int>() + j.at("not_judged").get<int>());
}

TEST_CASE("validate --densities: only those densities' rows judged, recorded, and judged again on them", "[validate][cli][from-json]") {
  // The committed paper study judged on its medium and dense rows alone: the loose rows (every row
  // of reference_data/paper.yaml that names density loose) are left out, the others keep their verdicts.
  const fs::path dir = dem::test::scratch_dir("validate_densities");
  const std::string refs = source + "/reference_data/paper.yaml";
  const nlohmann::json all = nlohmann::json::parse(text_of(source + "/reports/validation.json"));
  std::map<std::string, std::string> verdict_of;
  std::size_t loose = 0;
  for (const auto& r : all.at("rows")) {
    verdict_of[r.at("name").get<std::string>()] = r.at("verdict").get<std::string>();
    loose += r.at("density") == "loose";
  }
  REQUIRE(loose > 0);
  const auto r = validate("--from-json '" + source + "/reports/validation.json' --references '" + refs + "' --densities medium dense --out '" +
                          (dir / "a").string() + "'");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json a = nlohmann::json::parse(text_of(dir / "a" / "validation.json"));
  CHECK(a.at("rows").size() == all.at("rows").size() - loose);
  CHECK(a.at("judged_from").at("densities") == nlohmann::json({"medium", "dense"}));
  for (const auto& row : a.at("rows")) {
    CHECK(row.at("density") != "loose");
    CHECK(row.at("verdict") == verdict_of.at(row.at("name").get<std::string>()));
  }
  // Its record judged again without the option: on the densities it records.
  const auto again = validate("--from-json '" + (dir / "a" / "validation.json").string() + "' --references '" + refs + "' --out '" +
                              (dir / "b").string() + "'");
  INFO(again.out);
  CHECK(again.exit_code == 0);
  CHECK(nlohmann::json::parse(text_of(dir / "b" / "validation.json")).at("rows") == a.at("rows"));
  // A density no row has: exit 2, named with the densities there are.
  const auto bad = validate("--from-json '" + source + "/reports/validation.json' --references '" + refs + "' --densities tight --out '" +
                            (dir / "c").string() + "'");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.out, Catch::Contains("--densities: no row of the reference file is of density 'tight' (its densities: dense, loose, medium)"));
}

TEST_CASE("validate --borrow: a density left out recorded with the reading that stands for it, kept when judged again",
          "[validate][cli][from-json]") {
  // The committed dashpot readings study has the reading contact_dashpots on the loose rows: a
  // record of the medium and dense rows borrows them; judged again, the record keeps what it
  // borrowed (and its variants); a wrong form, a density judged here, or a reading the file lacks: exit 2.
  const fs::path dir = dem::test::scratch_dir("validate_borrow");
  const std::string refs = source + "/reference_data/paper.yaml", record = source + "/reports/validation.json";
  const std::string dashpot = source + "/reports/readings/dashpot/decisions.json";
  const auto run = [&](const std::string& extra, const std::string& out) {
    return validate("--from-json '" + record + "' --references '" + refs + "' --densities medium dense " + extra + " --out '" +
                    (dir / out).string() + "'");
  };
  const auto a = run("--borrow 'loose:contact_dashpots:" + dashpot + "'", "a");
  INFO(a.out);
  REQUIRE(a.exit_code == 0);
  const nlohmann::json borrowed = nlohmann::json::parse(text_of(dir / "a" / "validation.json")).at("judged_from").at("borrowed");
  CHECK(borrowed == nlohmann::json::array({{{"density", "loose"}, {"reading", "contact_dashpots"}, {"decisions", dashpot}}}));
  const auto again = validate("--from-json '" + (dir / "a" / "validation.json").string() + "' --references '" + refs + "' --out '" +
                              (dir / "b").string() + "'");
  INFO(again.out);
  CHECK(again.exit_code == 0);
  CHECK(nlohmann::json::parse(text_of(dir / "b" / "validation.json")).at("judged_from").at("borrowed") == borrowed);

  const auto form = run("--borrow loose:contact_dashpots", "c");
  CHECK(form.exit_code == 2);
  CHECK_THAT(form.out, Catch::Contains("--borrow: 'loose:contact_dashpots': expected DENSITY:READING:FILE"));
  const auto judged_here = run("--borrow 'medium:contact_dashpots:" + dashpot + "'", "d");
  CHECK(judged_here.exit_code == 2);
  CHECK_THAT(judged_here.out, Catch::Contains("'medium' is judged from this study's runs"));
  const auto no_reading = run("--borrow 'loose:no_such_reading:" + dashpot + "'", "e");
  CHECK(no_reading.exit_code == 2);
  CHECK_THAT(no_reading.out, Catch::Contains("has no reading 'no_such_reading' on a row of density 'loose'"));
}

TEST_CASE("validate names samples that are one sample: the same values to the last digit in every row, exit 1", "[validate][cli][samples]") {
  // Found by a hostile sweep: seed 2 a copy of seed 1 (a seed set in preparation_set) was judged
  // as "2 samples" with sd 0. Judged again from a record of three samples whose first two agree to
  // the last digit in both rows: validate names them, exits 1, and the record says so; one ulp apart
  // in one row, they are independent samples and the same record passes.
  const fs::path dir = dem::test::scratch_dir("validate_identical_samples");
  std::ofstream(dir / "refs.yaml") << "source: lab\nrows:\n"
      "  - {name: e0, quantity: void_ratio_after_preparation, density: dense, reference: 0.62, check: within, tolerance: 0.1, source: s, reason: r}\n"
      "  - {name: z, quantity: coordination_after_preparation, density: dense, reference: 5.0, check: within, tolerance: 2, source: s, reason: r}\n";
  const auto record = [&](const std::string& second_e0) {
    std::ofstream(dir / "record.json")
        << R"({"profile": "paper", "samples": ["seed1", "seed2", "seed3"], "missing_samples": [], "missing_results": [], "rows": [)"
        << R"({"name": "e0", "density": "dense", "per_sample": [{"sample": "seed1", "value": 0.6123456789}, )"
        << R"({"sample": "seed2", "value": )" << second_e0 << R"(}, {"sample": "seed3", "value": 0.6301}]}, )"
        << R"({"name": "z", "density": "dense", "per_sample": [{"sample": "seed1", "value": 4.75}, {"sample": "seed2", "value": 4.75}, )"
        << R"({"sample": "seed3", "value": 4.9}]}]})";
    return validate("--from-json '" + (dir / "record.json").string() + "' --references '" + (dir / "refs.yaml").string() + "' --out '" +
                    (dir / "out").string() + "'");
  };
  const auto same = record("0.6123456789");
  INFO(same.out);
  CHECK(same.exit_code == 1);
  CHECK(same.out.find("error: samples seed1 and seed2 give the same values to the last digit in every row: one sample counted 2 times") !=
        std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(text_of(dir / "out" / "validation.json"));
  CHECK(j.at("identical_samples") == nlohmann::json::array({nlohmann::json::array({"seed1", "seed2"})}));
  CHECK(j.at("complete") == false);
  char next[32];  // the next double above 0.6123456789, to 17 digits (read back exactly)
  std::snprintf(next, sizeof next, "%.17g", std::nextafter(0.6123456789, 1.0));
  const auto apart = record(next);
  INFO(apart.out);
  CHECK(apart.exit_code == 0);
  CHECK(apart.out.find("one sample counted") == std::string::npos);
  CHECK(nlohmann::json::parse(text_of(dir / "out" / "validation.json")).at("identical_samples").empty());
}
