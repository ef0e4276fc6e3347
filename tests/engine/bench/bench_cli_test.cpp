// The arguments of dem-bench and bench-report (CLI11, as the other programs): --help of every
// program and sub-command exits 0 without running anything, an unknown option or a bad value exits
// 2 naming it. (The positional forms reports/bench/run_bench.sh uses stay: BENCH_DIR STEPS REPS SKIN,
// `size BENCH_DIR TILES STEPS REPS SKIN ORDER`, `shear BENCH_DIR STEPS REPS SKIN`.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <nlohmann/json.hpp>

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
  // A date that is not YYYY-MM-DD, or no such day, is refused before any file is read.
  for (const char* bad : {"4/12/2026", "2026-13-01", "2026-02-30", "2026-12-4"}) {
    const auto date = tool("bench-report", std::string("a b --steps 1 --reps 1 --skin 1 --date ") + bad);
    INFO(date.out);
    CHECK(date.exit_code == 2);
    CHECK_THAT(date.out, Catch::Matchers::Contains("--date") && Catch::Matchers::Contains(bad));
  }
}

// The side-by-side table is refused when LAMMPS did not time the packing our engine timed: on the
// packing jammed with mu = 0 (which stands without the tangential springs LAMMPS starts without)
// the two codes' contacts per sphere must agree. The files are the shape dem-bench and
// lammps_bench.sh write, cut to one case (--cases mu0:0.5) and no sizes; the 2Nc/N values are those
// of two real runs: 6.11 against LAMMPS's 6.10 (the cell's tilts given) and 4.37 (read orthogonal).
TEST_CASE("bench-report: refuses a like-for-like row whose two codes started from different packings", "[bench][cli]") {
  const std::string dir = dem::test::scratch_dir("bench_report_same_packing");
  dem::test::write_text(dir + "/bench.json", R"({"vector_lanes": 8, "peak_rss_MB": 27.4,
    "runs": [{"packing": "mu0", "friction": 0.5, "threads": 1, "particle_steps_per_s_median": 3.0e7, "coordination_number": 6.11},
             {"packing": "mu0", "friction": 0.5, "threads": 2, "particle_steps_per_s_median": 5.5e7, "coordination_number": 6.11}],
    "two_runs_at_once": [{"packing": "mu0", "friction": 0.5, "total_particle_steps_per_s_median": 5.8e7}]})");
  dem::test::write_text(dir + "/shear.json", R"({"runs": [{"cell": "orthorhombic", "cpu_rate_median": 1.5e7, "min": 1.4e7, "max": 1.6e7},
    {"cell": "sheared", "cpu_rate_median": 1.4e7, "min": 1.3e7, "max": 1.6e7}]})");
  dem::test::write_text(dir + "/laws.json", R"({"scene": "scenes/tests/test1.yaml", "path": "[TC1]", "repetitions": 5,
    "runs": [{"law": "linear", "set": "", "steps": 100, "cpu_s_per_step_median": 5.8e-5, "min": 5.6e-5, "max": 6.3e-5,
              "over_linear_median": 1.0, "over_linear_min": 1.0, "over_linear_max": 1.0}]})");
  const auto lammps = [&](double start) {
    dem::test::write_text(dir + "/lammps_mu0_0.5.json",
                          R"({"runs": [{"friction": 0.5, "particle_steps_per_s_median": 1.0e7, "coordination_number_start": )" +
                              std::to_string(start) + R"(, "coordination_number_end": 6.10}]})");
  };
  const std::string out = dir + "/out";
  std::filesystem::create_directories(out);
  const std::string args = "'" + dir + "' '" + out + "' --steps 5000 --reps 7 --skin 2.5e-5 --cases mu0:0.5";

  lammps(4.37);
  const auto refused = tool("bench-report", args);
  INFO(refused.out);
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.out, Catch::Matchers::Contains("4.370") && Catch::Matchers::Contains("6.110") &&
                              Catch::Matchers::Contains("did not time the same packing"));
  CHECK(std::filesystem::is_empty(out));  // neither bench.json nor bench.md

  lammps(6.10);
  const auto kept = tool("bench-report", args + " --cores 2 --date 2026-12-04");
  INFO(kept.out);
  REQUIRE(kept.exit_code == 0);
  const std::string md = dem::test::read_bytes(out + "/bench.md");
  CHECK_THAT(md, Catch::Matchers::Contains("6.11 / 6.10 → 6.10"));
  // The day it ran, said in the table's text and in bench.json (the report's stamp of the section).
  CHECK_THAT(md, Catch::Matchers::Contains("measured by `make bench` on 2026-12-04 (2 cores,"));
  CHECK(nlohmann::json::parse(dem::test::read_bytes(out + "/bench.json")).at("date") == "2026-12-04");
}
