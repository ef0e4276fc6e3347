// The arguments of the validation tools (validate, report, figure-data, ensemble-cycles,
// compare-runs), all through CLI11: every program and sub-command answers --help with exit 0, an
// unknown option is refused with exit 2 and named, and a missing argument exits 2 naming it.
// (What each tool does with good arguments: validate_cli_test.cpp, figures/figures_test.cpp, report/report_test.cpp,
// sections/.) The same for dem-bench and bench-report: tests/engine/bench/bench_cli_test.cpp.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "engine/io/io_test_support.hpp"

namespace {

dem::test::CommandResult tool(const std::string& program, const std::string& args) {
  return dem::test::run_command("'" + std::string(DEM_BINARY_DIR) + "/bin/" + program + "' " + args + " 2>&1 < /dev/null");
}

struct Command {
  std::string program, sub;  // sub: "" for the program itself
  std::string option;        // an option its --help must list
  std::string required;      // arguments it needs (an unknown option is refused with them given too)
};

const std::vector<Command> commands = {
    {"validate", "", "--references", "--results r --references f --out o"},
    {"report", "", "--templates", "--results r --references f --out o"},
    {"figure-data", "", "samples-table", "settings r"},
    {"figure-data", "figures", "--sample", "r f"},
    {"figure-data", "settings", "--prefix", "r"},
    {"figure-data", "samples-table", "--per-sample", "r --references f"},
    {"ensemble-cycles", "", "OUT_DIR", "r o"},
    {"compare-runs", "", "liquefaction", "stability r o"},
    {"compare-runs", "convergence", "--reference", "r o"},
    {"compare-runs", "stability", "--report-only", "r o"},
    {"compare-runs", "decisions", "--baseline-results", "r o"},
    {"compare-runs", "critical-state", "OUT_DIR", "r o"},
    {"compare-runs", "liquefaction", "RESULTS_DIR", "o r"},
};

}  // namespace

TEST_CASE("validation tools: every program and sub-command answers --help with exit 0", "[tools][cli]") {
  for (const Command& c : commands) {
    const auto r = tool(c.program, c.sub + " --help");
    INFO(c.program << " " << c.sub << " --help:\n" << r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Matchers::Contains(c.option));
  }
}

TEST_CASE("validation tools: an unknown option exits 2 and is named", "[tools][cli]") {
  for (const Command& c : commands) {
    // Nothing is run, and nothing is read: the arguments name no real file.
    const auto r = tool(c.program, c.sub + " " + c.required + " --no-such-option");
    INFO(c.program << " " << c.sub << ":\n" << r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains("--no-such-option"));
  }
}

TEST_CASE("validation tools: a missing argument exits 2 naming it", "[tools][cli]") {
  const struct {
    std::string program, args, named;
  } cases[] = {
      {"validate", "--results r --out o", "--references"},
      {"validate", "--results r --references f --out o --profile", "--profile"},  // an option without its value
      {"report", "--results r --references f", "--out"},
      {"figure-data", "", "subcommand is required"},  // no sub-command
      {"figure-data", "figures r", "FIG_DIR"},
      {"figure-data", "samples-table r", "--references"},
      {"figure-data", "settings r --prefix a --run b", "--run"},  // one or the other
      {"ensemble-cycles", "r", "OUT_DIR"},
      {"compare-runs", "stability r", "OUT_DIR"},
  };
  for (const auto& c : cases) {
    const auto r = tool(c.program, c.args);
    INFO(c.program << " " << c.args << ":\n" << r.out);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains(c.named));
  }
}
