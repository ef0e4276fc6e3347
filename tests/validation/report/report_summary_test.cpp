// The report's summary first: on the committed reports/ (the paper study's results are not on this
// machine), `validate --from-json` then `report` as `make report-sections` does, reading back what
// the committed report took from the results (study_values.json), and the index.md it writes
// puts the verdicts in its first 40 lines, reads at most 450 lines before its first appendix with
// no table cell there over 200 characters (the compact verdict table's at most 80), has every
// section of the committed report, its text but for the lines that say where it was written
// from, and leaves no placeholder.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "engine/io/io_test_support.hpp"
#include "judge/verdicts.hpp"
#include "report/report.hpp"
#include "validation/markdown_cells.hpp"

namespace fs = std::filesystem;

namespace {

const std::string source = DEM_SOURCE_DIR;
const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The cells of a Markdown table line ("| a | b \| c |"), the Markdown of each as written.
std::vector<std::string> cells_of(const std::string& line) { return dem::test::markdown_cells(line, dem::test::Escaped::Keep); }

// The names of the level-2 sections of a report (report.hpp: section_name).
std::set<std::string> section_names(const std::string& text) {
  std::set<std::string> out;
  for (const std::string& line : lines_of(text))
    if (line.rfind("## ", 0) == 0) out.insert(validation::section_name(line));
  return out;
}

}  // namespace

TEST_CASE("report: the committed report written again from what is committed, its summary first", "[report][summary]") {
  const fs::path dir = dem::test::scratch_dir("report_summary");
  const fs::path out = dir / "reports";
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  const std::string committed = dem::test::read_bytes(source + "/reports/index.md");
  std::string decisions = " --decisions '" + (out / "decisions" / "decisions.json").string() + "'";
  for (const char* r : {"loose", "medium_dense", "dashpot"})  // the Makefile's READINGS
    if (fs::exists(out / "readings" / r / "decisions.json"))
      decisions += " --decisions '" + (out / "readings" / r / "decisions.json").string() + "'";
  // From the repository, as make runs it (sections from another engine kept, headed ⚠: make's
  // OTHER_SECTIONS): validation.json records the reference file as given.
  const auto v = dem::test::run_command("cd '" + source + "' && '" + bin + "validate' --from-json '" + (out / "validation.json").string() +
                                        "' --references reference_data/paper.yaml --out '" + out.string() + "'" + decisions + " 2>&1");
  INFO(v.out);
  REQUIRE(v.exit_code == 0);
  const auto r = dem::test::run_command("cd '" + source + "' && '" + bin + "report' --results '" + (dir / "no_results").string() +
                                        "' --references reference_data/paper.yaml --out '" + out.string() + "' --sample seed1 --baseline "
                                        "reports/baselines/orthorhombic_validation.json --allow-other-baseline 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  const std::string text = dem::test::read_bytes((out / "index.md").string());
  const std::vector<std::string> lines = lines_of(text);
  // The verdicts within the first 40 lines: the section, its count and the compact table's heading.
  std::size_t verdicts = 0, count = 0, table = 0, appendix = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!verdicts && lines[i] == "## Verdicts") verdicts = i + 1;
    if (verdicts && !count && lines[i].rfind("Of ", 0) == 0 && lines[i].find(" consistent**") != std::string::npos) count = i + 1;
    if (count && !table && lines[i].rfind("| row | paper | ours", 0) == 0) table = i + 1;
    if (!appendix && lines[i].rfind("## Appendix", 0) == 0) appendix = i + 1;
  }
  CHECK(verdicts > 0);
  CHECK(count > 0);
  CHECK(table > 0);
  CHECK(table <= 40);
  // The main read: before the first appendix, at most 450 lines, no cell over 200 characters; the
  // compact table's cells at most 80.
  REQUIRE(appendix > 0);
  CHECK(appendix - 1 <= 450);
  for (std::size_t i = 0; i + 1 < appendix; ++i) {
    if (lines[i].rfind("|", 0) != 0) continue;
    for (const std::string& cell : cells_of(lines[i])) {
      INFO("line " << i + 1 << ": " << cell);
      CHECK(validation::code_points(cell) <= 200);
    }
  }
  std::size_t compact_lines = 0;
  for (std::size_t i = table - 1; table && i < lines.size() && lines[i].rfind("|", 0) == 0; ++i, ++compact_lines)
    for (const std::string& cell : cells_of(lines[i])) {
      INFO("line " << i + 1 << ": " << cell);
      CHECK(validation::code_points(cell) <= validation::compact_cell_limit);
    }
  CHECK(compact_lines > 2);
  // Every cause the compact table links to has its entry, in the appendix.
  const std::regex link(R"(\]\(#(cause-[0-9]+)\))");
  std::size_t links = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it, ++links) {
    const std::string n = (*it)[1].str().substr(6);
    CHECK(text.find("\n### Cause " + n + "\n") > text.find("## Appendix: causes of the verdicts"));
  }
  CHECK(links > 0);  // the committed verdicts have inconsistent rows, each linked to its cause
  CHECK(text.find("](causes.md#") == std::string::npos);  // none to a file the report does not hold
  // The set-up from what is committed: validation.json's samples (seed1..5, the three densities of
  // its rows) and figure-data's record of the settings, values.gp (samples.md: 8000 particles a sample).
  CHECK_THAT(text, Catch::Contains("| samples | 5 per density (loose, medium, dense), seed1–seed5 |"));
  CHECK_THAT(text, Catch::Contains("| spheres per sample | 8,000 |"));
  // Every section of the committed report, none printed twice, and the same text but for the lines
  // that say where the values came from (the header's, the set-up's source, what the verdicts were
  // judged from);
  // no placeholder.
  const std::set<std::string> before = section_names(committed), now = section_names(text);
  for (const std::string& s : before) {
    INFO(s);
    CHECK(now.count(s) == 1);
  }
  CHECK_THAT(text, Catch::Contains("(its values read back from `" + (out / "study_values.json").string() + "`)"));
  const auto body = [](const std::string& t) {
    std::string out;
    for (const std::string& line : lines_of(t))
      if (line.rfind("Generated on ", 0) != 0 && line.rfind("Source: ", 0) != 0 && line.rfind("The results were written by", 0) != 0 &&
          line.rfind("was read back from", 0) != 0 && line.find("every value of the paper judged on every sample (from") == std::string::npos &&
          line.rfind("Judged by `validate`", 0) != 0 && line.rfind("Judged again by `validate --from-json`", 0) != 0)
        out += line + "\n";
    return out;
  };
  CHECK(body(text) == body(committed));
  // Each check of a study's baseline once, named by what it compares: the 1,000-sphere decisions
  // study's a size check; the readings studies' (3 of the paper study's own 8,000-sphere samples)
  // one sample-count check, each row once; never the same table twice.
  std::size_t merged = 0;
  for (const std::string& line : lines) merged += line.find("Each row once, with the readings studies whose baseline has it.") != std::string::npos;
  CHECK(merged == 1);
  std::set<std::string> tables;
  std::size_t size_checks = 0, count_checks = 0;
  for (const std::string& heading : {std::string("\n### Size check"), std::string("\n### Sample-count check")})
    for (std::size_t at = text.find(heading); at != std::string::npos; at = text.find(heading, at + 1)) {
      const std::size_t end = text.find("\n#", at + 1);
      tables.insert(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
      ++(heading == "\n### Size check" ? size_checks : count_checks);
    }
  CHECK(size_checks == 1);
  CHECK(count_checks == 1);
  CHECK(tables.size() == size_checks + count_checks);
  CHECK_THAT(text, Catch::Contains("### Size check: this study's baseline (1,000 spheres, 3 samples) against the paper study's ensemble "
                                   "(8,000 spheres, 5 samples)"));
  CHECK_THAT(text, Catch::Contains("### Sample-count check: this study's baseline (3 samples) against the paper study's ensemble (5 samples), "
                                   "both of 8,000 spheres"));
  // Every table cell of the whole report, appendices included, at most 200 characters (a longer
  // one is cut by the table writer, in full in a note under it). The stability matrix's table is
  // written by `compare-runs stability` from its results, which are not on this machine: its
  // committed table predates the limit until `make stability-report` draws it again.
  std::string section;
  std::size_t long_cells = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("## ", 0) == 0) section = validation::section_name(lines[i]);
    if (lines[i].rfind("|", 0) != 0 || section == "Stability") continue;
    for (const std::string& cell : cells_of(lines[i])) {
      INFO("line " << i + 1 << " (" << section << "): " << cell);
      CHECK(validation::code_points(cell) <= 200);
      long_cells += validation::code_points(cell) > 200;
    }
  }
  CHECK(long_cells == 0);
  // "Generated on" is the day the report was written, never before a section it holds: every
  // stamp line's date (each section's own) is on or before it.
  std::smatch generated;
  REQUIRE(std::regex_search(text, generated, std::regex(R"(Generated on ([0-9]{4}-[0-9]{2}-[0-9]{2}))")));
  std::size_t dated = 0;
  for (const std::string& line : lines) {
    std::smatch d;
    if ((line.rfind("*Made by engine", 0) == 0 || line.rfind("*⚠ Made by engine", 0) == 0) &&
        std::regex_search(line, d, std::regex(R"(, ([0-9]{4}-[0-9]{2}-[0-9]{2})\))"))) {
      INFO(line);
      CHECK(d[1].str() <= generated[1].str());
      ++dated;
    }
  }
  CHECK(dated >= 10);
  CHECK_FALSE(std::regex_search(text, std::regex(R"(= \? |\? (µs|MPa|kPa|s)[ ,.]|\{\{)")));
}
