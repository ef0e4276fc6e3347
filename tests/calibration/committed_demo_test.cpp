// The committed two-size demonstration replays from its ledgers: nothing runs, and the posterior,
// the truths inside their 95 % intervals and the sizes' sets are the ones committed. A scene of the
// demonstration changed since it was scored fails this test: run make calibration-two-sizes again.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

TEST_CASE("the committed two-size calibration replays from its ledgers, runs nothing, and recovers both truths", "[calibration][cli]") {
  const fs::path src = DEM_SOURCE_DIR;
  const fs::path committed = src / "reports" / "calibration" / "synthetic_two_sizes";
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "committed_two_sizes";
  fs::remove_all(dir);
  fs::create_directories(dir / "report");
  for (const char* f : {"scored_sets.json", "scored_sets.large.json", "truth.json"}) fs::copy_file(committed / f, dir / "report" / f);
  // The calibration file with its paths made absolute and its report here.
  std::string cal = dem::test::read_bytes((src / "pipeline" / "calibrations" / "synthetic_two_sizes.yaml").string());
  cal = std::regex_replace(cal, std::regex("study: \\.\\./studies/"), "study: " + (src / "pipeline" / "studies").string() + "/");
  cal = std::regex_replace(cal, std::regex("references: \\.\\./\\.\\./"), "references: " + src.string() + "/");
  cal = std::regex_replace(cal, std::regex("report: [^\n]*"), "report: " + (dir / "report").string());
  std::ofstream(dir / "cal.yaml") << cal;
  const auto r = dem::test::run_command("cd '" + dir.string() + "' && '" + std::string(DEM_BINARY_DIR) +
                                        "/bin/calibrate' cal.yaml -j 1 --ledger-only --ledger-engine --truth report/truth.json 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("] started ") == std::string::npos);
  const nlohmann::json now = nlohmann::json::parse(dem::test::read_bytes((dir / "report" / "posterior.json").string()));
  const nlohmann::json then = nlohmann::json::parse(dem::test::read_bytes((committed / "posterior.json").string()));
  CHECK(now["parameters"] == then["parameters"]);
  CHECK(now["sets"] == then["sets"]);
  CHECK(now["largest_size"] == then["largest_size"]);
  for (const auto& p : now["parameters"]) CHECK(p["truth_inside_95"] == true);
  // 80 % or more of the sets at 1,000 spheres or fewer.
  REQUIRE(now["sizes"].size() == 2);
  CHECK(now["sizes"][0]["stamp"]["spheres"].get<long>() <= 1000);
  const double small = now["sizes"][0]["sets"].get<double>(), large = now["sizes"][1]["sets"].get<double>();
  CHECK(small / (small + large) >= 0.8);
}
