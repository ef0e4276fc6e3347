// --without-results keep|redraw (compare-runs, every mode; validate): a study that has not run here
// is no error. redraw gives the same tables as the explicit re-draw from the committed summary
// (compare-runs decisions --from-json, validate --from-json) and says which file it used; keep,
// and redraw where there is no summary, leaves OUT_DIR as it is, says so and exits 0. Without the
// option a missing runs.tsv stays an error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string source = DEM_SOURCE_DIR;

dem::test::CommandResult tool(const std::string& program, const std::string& args) {
  return dem::test::run_command("'" + std::string(DEM_BINARY_DIR) + "/bin/" + program + "' " + args + " 2>&1 < /dev/null");
}

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

}  // namespace

TEST_CASE("compare-runs --without-results: a study not run here keeps OUT_DIR, exit 0; without the option, an error",
          "[tools][compare-runs][without-results]") {
  const fs::path dir = dem::test::scratch_dir("without_results_keep");
  const fs::path none = dir / "not_run", out = dir / "out";
  fs::create_directories(out);
  dem::test::write_text((out / "table.md").string(), "the committed table\n");
  for (const std::string mode : {"stability", "critical-state", "decisions", "convergence"}) {
    for (const std::string how : {"keep", "redraw"}) {  // none of them has a committed summary in OUT_DIR
      const auto r = tool("compare-runs", mode + " " + q(none) + " " + q(out) + " --without-results " + how);
      INFO(mode << " --without-results " << how << ":\n" << r.out);
      CHECK(r.exit_code == 0);
      CHECK_THAT(r.out, Catch::Matchers::Contains("no results in " + none.string() + " yet") &&
                            Catch::Matchers::Contains(out.string() + " left as it is"));
    }
    const auto strict = tool("compare-runs", mode + " " + q(none) + " " + q(out));
    INFO(mode << " without the option:\n" << strict.out);
    CHECK(strict.exit_code == 2);
  }
  // A study planned but with nothing finished counts as not run.
  fs::create_directories(dir / "planned");
  dem::test::write_text((dir / "planned" / "runs.tsv").string(),
                        "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n"
                        "-\tdense\t-\tseed1/dense_prepare\t" + (dir / "planned" / "seed1" / "dense_prepare.h5").string() +
                            "\t-\t0\tas written\t1\n");
  auto r = tool("compare-runs", "stability " + q(dir / "planned") + " " + q(out) + " --without-results keep");
  INFO(r.out);
  CHECK(r.exit_code == 0);
  r = tool("compare-runs", "stability " + q(dir / "planned") + " " + q(out));
  CHECK(r.exit_code == 1);  // nothing finished, as before
  // liquefaction: every folder without results.
  r = tool("compare-runs", "liquefaction " + q(out) + " " + q(none) + " " + q(dir / "planned") + " --without-results keep");
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("left out") && Catch::Matchers::Contains("left as it is"));
  CHECK(dem::test::read_bytes((out / "table.md").string()) == "the committed table\n");
  CHECK(tool("compare-runs", "stability " + q(none) + " " + q(out) + " --without-results later").exit_code == 2);
}

TEST_CASE("compare-runs decisions --without-results redraw: the committed decisions.json re-drawn, as --from-json draws it",
          "[tools][compare-runs][without-results]") {
  const fs::path dir = dem::test::scratch_dir("without_results_decisions");
  const fs::path redrawn = dir / "redrawn", direct = dir / "direct", kept = dir / "kept";
  for (const fs::path& d : {redrawn, direct, kept}) {
    fs::create_directories(d);
    fs::copy_file(source + "/reports/decisions/decisions.json", d / "decisions.json");
  }
  const std::string refs = " --references " + q(fs::path(source) / "reference_data/paper.yaml");
  const auto r = tool("compare-runs", "decisions " + q(dir / "not_run") + " " + q(redrawn) + refs + " --without-results redraw");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("re-drawn from the committed " + (redrawn / "decisions.json").string()));
  REQUIRE(tool("compare-runs", "decisions --from-json " + q(direct / "decisions.json") + " " + q(direct) + refs).exit_code == 0);
  // The same table but for the path of the file in its first paragraph.
  const std::string a = dem::test::read_bytes((redrawn / "table.md").string()), b = dem::test::read_bytes((direct / "table.md").string());
  REQUIRE(a.find("\n") != std::string::npos);
  CHECK(a.substr(a.find('\n')) == b.substr(b.find('\n')));
  CHECK_THAT(a.substr(0, a.find('\n')), Catch::Matchers::Contains((redrawn / "decisions.json").string()));
  // keep: the committed file stays, no table is drawn.
  const auto k = tool("compare-runs", "decisions " + q(dir / "not_run") + " " + q(kept) + refs + " --without-results keep");
  CHECK(k.exit_code == 0);
  CHECK(!fs::exists(kept / "table.md"));
}

TEST_CASE("validate --without-results: judged again from the committed validation.json, or --out kept", "[tools][validate][without-results]") {
  const fs::path dir = dem::test::scratch_dir("without_results_validate");
  const fs::path redrawn = dir / "redrawn", direct = dir / "direct", empty = dir / "empty";
  for (const fs::path& d : {redrawn, direct}) {
    fs::create_directories(d);
    fs::copy_file(source + "/reports/validation.json", d / "validation.json");
  }
  const std::string refs = " --references " + q(fs::path(source) / "reference_data/paper.yaml");
  const auto r = tool("validate", "--results " + q(dir / "not_run") + " --out " + q(redrawn) + refs + " --without-results redraw");
  const auto d = tool("validate", "--from-json " + q(direct / "validation.json") + " --out " + q(direct) + refs);
  INFO(r.out << "\n" << d.out);
  CHECK(r.exit_code == d.exit_code);  // the verdicts' own status (a must-pass row inconsistent: 1)
  CHECK_THAT(r.out, Catch::Matchers::Contains("every row judged again from the committed " + (redrawn / "validation.json").string()));
  // The same tables but for the path of the record in their first line.
  std::string a = dem::test::read_bytes((redrawn / "validation.md").string()), b = dem::test::read_bytes((direct / "validation.md").string());
  REQUIRE(!a.empty());
  CHECK(a.substr(a.find('\n')) == b.substr(b.find('\n')));
  // No record: --out kept, exit 0; keep never judges.
  for (const std::string how : {"keep", "redraw"}) {
    const auto k = tool("validate", "--results " + q(dir / "not_run") + " --out " + q(empty) + refs + " --without-results " + how);
    INFO(k.out);
    CHECK(k.exit_code == 0);
    CHECK_THAT(k.out, Catch::Matchers::Contains("left as it is"));
    CHECK(!fs::exists(empty / "validation.md"));
  }
  CHECK(tool("validate", "--from-json " + q(direct / "validation.json") + " --out " + q(direct) + refs + " --without-results keep")
            .exit_code == 2);  // only with --results
}
