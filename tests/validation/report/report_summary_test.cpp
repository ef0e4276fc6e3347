// The report's summary first: on the committed reports/ (the paper study's results are not on this
// machine), `validate --from-json` then `report --previous` as `make report-sections` does, and the
// index.md it writes puts the verdicts in its first 40 lines, reads at most 450 lines before its
// first appendix with no table cell there over 200 characters (the compact verdict table's at
// most 80), keeps every section of the earlier report, and leaves no placeholder. And the keeping
// of sections and paragraphs from an earlier report across the move into the appendix.
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

TEST_CASE("report --previous: a section moved into the appendix, and a paragraph, are the previous report's", "[report]") {
  const std::string marker = validation::inputs_not_here;
  const std::string fresh = "# Title\nGenerated on 2026-11-27\n\n## Verdicts\nnew table\n\n" +
                            validation::paragraph_not_here("starting", "Readings used") + "\n\n## Figures\n\n![f](figures/f.png)\n\n" +
                            validation::paragraph_not_here("after", "![f](figures/f.png)") + "\n\n![g](figures/g.png)\n\n" +
                            validation::paragraph_not_here("after", "![g](figures/g.png)") + "\n\n## Appendix: What was run\n" + marker +
                            "\n";
  const std::string previous = "# Title\nGenerated on 2026-11-20\n\n## Verdicts\nold table\n\nReadings used (first line):\ngrading by count.\n\n"
                               "## Figures\n\n![f](figures/f.png)\n\nThe note of f,\non two lines.\n\n## What was run\nold runs\n";
  std::vector<std::string> kept;
  const std::string out = validation::keep_sections_without_inputs(fresh, previous, kept);
  // Verdicts and Figures have their inputs: fresh, but for the paragraphs the markers name; g has
  // no note in the previous report (its marker is dropped); What was run is the previous body under
  // the fresh heading.
  CHECK(out == "# Title\nGenerated on 2026-11-27\n\n## Verdicts\nnew table\n\nReadings used (first line):\ngrading by count.\n\n## Figures\n\n"
               "![f](figures/f.png)\n\nThe note of f,\non two lines.\n\n![g](figures/g.png)\n\n\n\n## Appendix: What was run\nold runs\n");
  CHECK(kept == std::vector<std::string>{"What was run", "¶ Readings used", "¶ ![f](figures/f.png)"});
  CHECK(validation::section_name("## Appendix: What was run\n") == "What was run");
  CHECK(validation::section_name("### A sample in ParaView") == "A sample in ParaView");
  // The previous report ends with its last section under its old name: not cut short.
  CHECK_NOTHROW(validation::check_previous_report(previous, "# Title\n\n## Appendix: What was run\nx\n", "--previous 'old.md'"));
}

TEST_CASE("report: the committed report written again from what is committed, its summary first", "[report][summary]") {
  const fs::path dir = dem::test::scratch_dir("report_summary");
  const fs::path out = dir / "reports";
  fs::copy(source + "/reports", out, fs::copy_options::recursive);
  const std::string previous = (dir / "previous_index.md").string();
  fs::copy_file(source + "/reports/index.md", previous);
  std::string decisions = " --decisions '" + (out / "decisions" / "decisions.json").string() + "'";
  for (const char* r : {"loose", "medium_dense", "dashpot"})  // the Makefile's READINGS
    if (fs::exists(out / "readings" / r / "decisions.json"))
      decisions += " --decisions '" + (out / "readings" / r / "decisions.json").string() + "'";
  const auto v = dem::test::run_command("'" + bin + "validate' --from-json '" + (out / "validation.json").string() + "' --references '" + source +
                                        "/reference_data/paper.yaml' --out '" + out.string() + "'" + decisions + " 2>&1");
  INFO(v.out);
  REQUIRE(v.exit_code == 0);
  const auto r = dem::test::run_command("cd '" + source + "' && '" + bin + "report' --results '" + (dir / "no_results").string() +
                                        "' --references reference_data/paper.yaml --out '" + out.string() + "' --sample seed1 --baseline "
                                        "reports/baselines/orthorhombic_validation.json --previous '" + previous + "' 2>&1");
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
  for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
    const std::string n = (*it)[1].str().substr(6);
    CHECK(text.find("\n### Cause " + n + "\n") > text.find("## Appendix: causes of the verdicts"));
  }
  // The set-up from what is committed: validation.json's samples (seed1..5, the three densities of
  // its rows) and figure-data's record of the settings, values.gp (samples.md: 8000 particles a sample).
  CHECK_THAT(text, Catch::Contains("| samples | 5 per density (loose, medium, dense), seed1–seed5 |"));
  CHECK_THAT(text, Catch::Contains("| spheres per sample | 8,000 |"));
  // No section of the earlier report lost, none printed twice; no placeholder.
  const std::set<std::string> before = section_names(dem::test::read_bytes(previous)), now = section_names(text);
  for (const std::string& s : before) {
    INFO(s);
    CHECK(now.count(s) == 1);
  }
  std::size_t size_checks = 0;
  for (const std::string& line : lines) size_checks += line.find("Size check: this study's baseline") != std::string::npos;
  CHECK(size_checks == 1);
  CHECK_FALSE(std::regex_search(text, std::regex(R"(= \? |\? (µs|MPa|kPa|s)[ ,.]|\{\{)")));
}
