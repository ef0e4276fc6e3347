// The arguments of dem-bench and bench-report (CLI11, as the other programs): --help of every
// program and sub-command exits 0 without running anything, an unknown option or a bad value exits
// 2 naming it. (The positional forms reports/bench/run_bench.sh uses stay: BENCH_DIR STEPS REPS SKIN,
// `size BENCH_DIR TILES STEPS REPS SKIN ORDER`, `shear BENCH_DIR STEPS REPS SKIN`.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <utility>

#include "engine/io/io_test_support.hpp"

namespace {

dem::test::CommandResult tool(const std::string& program, const std::string& args) {
  return dem::test::run_command("'" + std::string(DEM_BINARY_DIR) + "/bin/" + program + "' " + args + " 2>&1 < /dev/null");
}

}  // namespace

TEST_CASE("dem-bench and bench-report: --help exits 0, unknown options and bad values exit 2 named", "[bench][cli]") {
  const std::string dir = dem::test::scratch_dir("bench_cli");
  const std::string d = "'" + dir + "' ";
  for (const auto& [sub, args] : {std::pair<std::string, std::string>{"", d + "0"}, {"size", d + "1 10 1"}, {"shear", d + "10 1"}}) {
    const auto r = tool("dem-bench", sub + " --help");
    INFO("dem-bench " << sub << " --help:\n" << r.out);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Matchers::Contains("REPETITIONS"));
    // With the arguments it needs (STEPS 0 would build the packings): refused, nothing run.
    const auto bad = tool("dem-bench", sub + " " + args + " --no-such-option");
    INFO(bad.out);
    CHECK(bad.exit_code == 2);
    CHECK_THAT(bad.out, Catch::Matchers::Contains("--no-such-option"));
  }
  // A bad ORDER and a STEPS that is not a number are refused before any packing is built.
  const auto order = tool("dem-bench", "size '" + dir + "' 1 10 1 2.5e-5 shuffled");
  INFO(order.out);
  CHECK(order.exit_code == 2);
  CHECK_THAT(order.out, Catch::Matchers::Contains("ORDER"));
  const auto steps = tool("dem-bench", "'" + dir + "' many");
  INFO(steps.out);
  CHECK(steps.exit_code == 2);
  CHECK_THAT(steps.out, Catch::Matchers::Contains("STEPS"));
  CHECK(std::filesystem::is_empty(dir));

  const auto help = tool("bench-report", "--help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Matchers::Contains("--size-plan"));
  const auto unknown = tool("bench-report", "a b --steps 1 --reps 1 --skin 1 --no-such-option");
  INFO(unknown.out);
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.out, Catch::Matchers::Contains("--no-such-option"));
  const auto missing = tool("bench-report", "a b --steps 1 --reps 1");
  INFO(missing.out);
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.out, Catch::Matchers::Contains("--skin"));
}
