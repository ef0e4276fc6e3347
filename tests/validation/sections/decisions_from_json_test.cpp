// compare-runs decisions --from-json: the decisions section re-drawn from a decisions.json alone.
// Every shift is restated from the recorded means against max(baseline sd, the row's resolution)
// and written by shift_text (beyond ±10: the value and a marker), the mean ± sd to the digits of
// the scatter, each mark as the file records it, the explanation as written, and a first
// paragraph that says where the table comes from and what it cannot show.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/compare-runs";

std::string read_all(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The shift column of `reading_index` in `dat` (tornado_<group>.dat) on the line of `reading`.
double dat_shift(const std::string& dat, const std::string& reading) {
  std::istringstream in(dat);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line.size() > reading.size() && line.compare(line.size() - reading.size() - 1, std::string::npos, "\t" + reading) == 0) {
      std::istringstream fields(line);
      double row = 0, k = 0, z = 0;
      fields >> row >> k >> z;
      return z;
    }
  }
  return -1e300;
}

// A decisions.json of a 1,000-sphere study: two rows, two readings, each reading's shift_sd as
// written against the resolution of its day (here the baseline sd alone, far below today's
// resolution for εv). `size` adds "particles" and "samples".
std::string decisions_json(bool size) {
  return std::string(R"js({
  "schema": 2, "baseline": "baseline",)js") +
         (size ? R"js( "particles": 1000, "samples": 3,)js" : "") + R"js(
  "rows": [
    {"name": "e0, loose", "group": "samples", "baseline_mean": 0.70049, "baseline_sd": 0.0213, "baseline_verdict": "consistent",
     "readings": {"r1": {"mean": 0.73, "shift_sd": 1.38545, "verdict": "inconsistent"},
                  "r2": {"mean": 0.69, "shift_sd": -0.492488, "verdict": "consistent"}},
     "judged": true, "made_consistent_by": [], "outcome": "consistent",
     "explanation": "consistent on the full-size ensemble (within the scatter of one sample)"},
    {"name": "ev, loose", "group": "volumetric strain", "baseline_mean": 1e-05, "baseline_sd": 2.4e-06, "baseline_verdict": "consistent",
     "readings": {"r1": {"mean": 0.28, "shift_sd": 116662, "verdict": "inconsistent"},
                  "r2": {"mean": 1.2e-05, "shift_sd": 0.833333, "verdict": "consistent"}},
     "judged": true, "made_consistent_by": ["r1"], "outcome": "explained",
     "explanation": "consistent under r1 (beyond +10 sd (+56), t = 2.76), its shift of the mean applied to the full-size ensemble"}
  ],
  "missing_results": 0
}
)js";
}

}  // namespace

TEST_CASE("compare-runs decisions --from-json: shifts restated against the resolution, clipped beyond 10, digits from the scatter",
          "[decisions][compare-runs]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_from_json";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "refs.yaml") << R"(source: test
rows:
  - {name: "e0, loose", group: samples, quantity: void_ratio_after_preparation, density: loose, reference: 0.71, check: within,
     tolerance: 0.02, resolution: 0.005, source: t, reason: t}
  - {name: "ev, loose", group: volumetric strain, quantity: ev_after_cycle, density: loose, cycle: 1, reference: 1.1, check: within,
     tolerance: 0.5, resolution: 0.005, source: t, reason: t}
)";
  std::ofstream(dir / "decisions.json") << decisions_json(false);
  const std::string common = "'" + bin + "' decisions --from-json '" + (dir / "decisions.json").string() + "' --references '" +
                             (dir / "refs.yaml").string() + "' ";

  auto r = dem::test::run_command(common + "'" + (dir / "out").string() + "' 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("shifts beyond ±10 sd (written with their value): 1 ->") != std::string::npos);
  const std::string md = read_all(dir / "out" / "table.md");
  INFO(md);

  // e0: sd 0.0213 > resolution 0.005, so the unit is the sd. r1: (0.73 - 0.70049) / 0.0213 =
  // 0.02951 / 0.0213 = 1.3854 -> "+1.39"; r2: -0.01049 / 0.0213 = -0.4925 -> "-0.49". The sd to two
  // significant digits, 0.021, and the mean to the same decimal, 0.700.
  CHECK(md.find("| e0, loose | 0.700 ± 0.021 ✅ | +1.39 ❌ | -0.49 ✅ | consistent on the full-size ensemble (within the scatter of one "
                "sample) |") != std::string::npos);
  // εv: sd 2.4e-6 is below the resolution 0.005, which is the unit. r1: (0.28 - 0.00001) / 0.005 =
  // 55.998, beyond 10: "+56 (beyond ±10)" (the file's 116662 was counted in the sd); r2: 2e-6 /
  // 0.005 = 0.0004 -> "+0.00" (the file's 0.83). Mean ± sd: sd 2.4e-6 to two digits is 7 decimals.
  CHECK(md.find("| ev, loose | 0.0000100 ± 0.0000024 ✅ | +56 (beyond ±10) ❌ | +0.00 ✅ | consistent under r1 (beyond +10 sd (+56), "
                "t = 2.76), its shift of the mean applied to the full-size ensemble |") != std::string::npos);
  CHECK(md.find("116662") == std::string::npos);
  CHECK(md.find("0.833") == std::string::npos);
  // The marks are the file's: r1 on e0 is ❌ although +1.39 sd is small (the file says so).
  // The first paragraph: where it comes from, the size, what it cannot re-draw.
  CHECK(md.rfind("Re-drawn from `" + (dir / "decisions.json").string() + "` alone, without the study's results", 0) == 0);
  CHECK(md.find("(not on the machine that drew it); size not recorded. Each shift") != std::string::npos);
  CHECK(md.find("the verdicts of the paper study's full-size ensemble (each mark below is the verdict on this study's own samples") !=
        std::string::npos);
  CHECK(md.find("Size check") == std::string::npos);  // the report draws the check, from decisions.json and validation.json
  CHECK(md.find("Readings (each one change from the baseline, `baseline`): r1, r2; their settings are not recorded in the file.") !=
        std::string::npos);
  // Groups in the file's order, each with its chart.
  CHECK(md.find("### samples") < md.find("### volumetric strain"));
  CHECK(md.find("![tornado chart: volumetric strain](tornado_volumetric_strain.png)") != std::string::npos);

  // The charts' data: the restated shifts (tornado.gp clips them for drawing and writes the value).
  const std::string ev_dat = read_all(dir / "out" / "tornado_volumetric_strain.dat");
  CHECK(dat_shift(ev_dat, "r1") == Approx((0.28 - 1e-5) / 0.005).epsilon(1e-5));
  CHECK(dat_shift(ev_dat, "r2") == Approx(2e-6 / 0.005).epsilon(1e-3));
  CHECK(dat_shift(read_all(dir / "out" / "tornado_samples.dat"), "r1") == Approx(0.02951 / 0.0213).epsilon(1e-5));
  const std::string gp = read_all(dir / "out" / "tornado_values.gp");
  CHECK(gp.find("tornado_groups = \"samples volumetric_strain\"") != std::string::npos);
  CHECK(gp.find("tornado_reading_n = 2") != std::string::npos);
  CHECK(!fs::exists(dir / "out" / "decisions.json"));  // the input is never written

  // A file that records its size says it.
  std::ofstream(dir / "decisions.json") << decisions_json(true);
  r = dem::test::run_command(common + "'" + (dir / "sized").string() + "' 2>&1");
  REQUIRE(r.exit_code == 0);
  CHECK(read_all(dir / "sized" / "table.md").find("measured at 1,000 spheres, 3 samples per reading") != std::string::npos);

  // With the paper study's validation.json, the marks are its full-size ensemble's verdicts, each
  // reading's shift of the mean applied to its samples (as drawn from the results), not the file's.
  // e0 (paper 0.71 ± 0.02: [0.69, 0.73]): samples 0.700, 0.702, 0.704, mean 0.702, sd 0.002,
  // interval 0.702 ± t(0.975, 2) 4.303 · 0.002 · √(4/3) = ± 0.0099: consistent; r1 shifts it by
  // +0.02951 to [0.7216, 0.7414], which reaches 0.73: consistent (the file's mark, on its own 3
  // samples, is ❌); r2 by -0.01049 to [0.6816, 0.7014]: consistent. εv (paper 1.1 ± 0.5: [0.6,
  // 1.6]): samples 0.58, 0.60, 0.62 (two in the region: no "by width only" ⚠), interval 0.60 ±
  // 0.0994 = [0.5006, 0.6994]: consistent; r1 shifts it by +0.27999 to [0.7800, 0.9793]:
  // consistent (the file's ❌).
  std::ofstream(dir / "validation.json") << R"js({"profile": "paper", "samples": ["seed1", "seed2", "seed3"], "missing_samples": [],
    "missing_results": [], "rows": [
    {"name": "e0, loose", "density": "loose", "per_sample": [{"sample": "seed1", "value": 0.700}, {"sample": "seed2", "value": 0.702},
                                                             {"sample": "seed3", "value": 0.704}]},
    {"name": "ev, loose", "density": "loose", "per_sample": [{"sample": "seed1", "value": 0.58}, {"sample": "seed2", "value": 0.60},
                                                             {"sample": "seed3", "value": 0.62}]}]})js";
  std::ofstream(dir / "decisions.json") << decisions_json(false);
  r = dem::test::run_command(common + "'" + (dir / "full").string() + "' --ensemble-json '" + (dir / "validation.json").string() + "' 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  const std::string full = read_all(dir / "full" / "table.md");
  INFO(full);
  CHECK(full.find("| e0, loose | 0.700 ± 0.021 ✅ | +1.39 ✅ | -0.49 ✅ |") != std::string::npos);
  CHECK(full.find("| ev, loose | 0.0000100 ± 0.0000024 ✅ | +56 (beyond ±10) ✅ | +0.00 ✅ |") != std::string::npos);
  CHECK(full.find("each mark below is the verdict on this study's own samples") == std::string::npos);
  CHECK(full.find("of the paper study's full-size ensemble with that shift of the mean applied") != std::string::npos);
  // A file that records the readings' settings: the same table as drawn from the results.
  nlohmann::json with_settings = nlohmann::json::parse(decisions_json(true));
  with_settings["settings"] = {{"baseline", "as written"}, {"r1", "damping.form = local"}};
  std::ofstream(dir / "decisions.json") << with_settings.dump();
  r = dem::test::run_command(common + "'" + (dir / "set").string() + "' 2>&1");
  REQUIRE(r.exit_code == 0);
  CHECK(read_all(dir / "set" / "table.md").find("| reading | settings |\n|---|---|\n| baseline | as written |\n| r1 | damping.form = local |\n") !=
        std::string::npos);
  // --ensemble-json without --from-json: exit 2.
  CHECK(dem::test::run_command("'" + bin + "' decisions '" + dir.string() + "' '" + (dir / "y").string() + "' --ensemble-json '" +
                               (dir / "validation.json").string() + "' 2>&1")
            .exit_code == 2);

  // Bad arguments: a results folder beside --from-json, or an option of the results mode: exit 2.
  CHECK(dem::test::run_command(common + "'" + dir.string() + "' '" + (dir / "x").string() + "' 2>&1").exit_code == 2);
  CHECK(dem::test::run_command(common + "'" + (dir / "x").string() + "' --ensemble '" + dir.string() + "' 2>&1").exit_code == 2);
  CHECK(dem::test::run_command(common + "2>&1").exit_code == 2);
  // A file that is not JSON: exit 2, the file named.
  std::ofstream(dir / "broken.json") << "{ not json";
  r = dem::test::run_command("'" + bin + "' decisions --from-json '" + (dir / "broken.json").string() + "' '" + (dir / "x").string() +
                             "' --references '" + (dir / "refs.yaml").string() + "' 2>&1");
  CHECK(r.exit_code == 2);
  CHECK(r.out.find("broken.json") != std::string::npos);
}
