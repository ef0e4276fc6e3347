// compare-runs decisions on a study of readings only (pipeline/studies/readings_*.yaml): its
// baseline is another study's samples of the same seeds (--baseline-results), decisions.json
// records the size it was measured at, and a run not finished leaves its reading not judged on
// the rows that read it, never a crash.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <hdf5.h>
#include <nlohmann/json.hpp>

#include "judge/decisions_file.hpp"

#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "study/baseline.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/compare-runs";

// A complete preparation of `particles` spheres whose last void ratio is e0.
void write_preparation(const fs::path& file, double e0, int particles) {
  fs::create_directories(file.parent_path());
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::test::mark_complete(f);
  {
    dem::h5::Handle g = dem::h5::create_group(f, "timeseries");
    dem::h5::write<double>(g, "void_ratio", {0.9, e0}, 1, "1");
  }
  dem::h5::Handle p = dem::h5::create_group(f, "particles");
  dem::h5::Handle all = dem::h5::create_group(p, "all");
  dem::h5::Handle position = dem::h5::create_group(all, "position");
  // One frame of positions: frames x particles x 3, as the engine writes them (H5MD).
  const hsize_t dims[3] = {1, static_cast<hsize_t>(particles), 3};
  const std::vector<double> zeros(3 * static_cast<std::size_t>(particles), 0.0);
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t set = H5Dcreate2(position, "value", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  H5Dclose(set);
  H5Sclose(space);
}

// A complete test whose εv at the end of cycle 1 is ev_percent.
void write_test(const fs::path& file, double ev_percent) {
  fs::create_directories(file.parent_path());
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::test::mark_complete(f);
  dem::h5::Handle g = dem::h5::create_group(f, "timeseries");
  dem::h5::write<double>(g, "cycle", {1}, 1, "1");
  dem::h5::write<double>(g, "cycle_end", {1}, 1, "1");
  dem::h5::write<double>(g, "volumetric_strain", {ev_percent / 100}, 1, "1");
}

// runs.tsv of a study of one density (loose), a preparation and Tests 1 and 2 per seed; the result
// paths recorded elsewhere (as for a copied folder: compare-runs finds them under the study's folder).
void write_manifest(const fs::path& dir, const std::string& variant, int seeds) {
  fs::create_directories(dir);
  std::ofstream runs(dir / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  const std::string prefix = variant == "-" ? "" : variant + "_";
  for (int s = 1; s <= seeds; ++s)
    for (const std::string t : {"-", "test1", "test2"}) {
      const std::string run = "seed" + std::to_string(s) + "/" + prefix + "loose_" + (t == "-" ? "prepare" : t);
      runs << variant << "\tloose\t" << t << "\t" << run << "\t/elsewhere/" << run << ".h5\t-\t0\t"
           << (variant == "-" ? "as written" : "preparation: x = 1") << "\t" << s << "\n";
    }
}

}  // namespace

TEST_CASE("compare-runs decisions: a readings study against another study's samples of the same seeds", "[decisions][compare-runs]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_readings";
  fs::remove_all(dir);
  // The baseline study: 4 seeds of 8 spheres; e0 0.70, 0.71, 0.72 (seed4: 0.90, which must not be
  // read: the readings study has seeds 1-3), εv after cycle 1 of 1.0, 1.1, 1.2 % in both tests.
  write_manifest(dir / "paper", "-", 4);
  for (int s = 1; s <= 4; ++s) {
    const fs::path seed = dir / "paper" / ("seed" + std::to_string(s));
    write_preparation(seed / "loose_prepare.h5", s == 4 ? 0.90 : 0.69 + 0.01 * s, 8);
    for (int t : {1, 2}) write_test(seed / ("loose_test" + std::to_string(t) + ".h5"), 0.9 + 0.1 * s);
  }
  // The readings study: reading "r" on seeds 1-3, e0 +0.02; seed3's Test 2 not finished (no file).
  write_manifest(dir / "readings", "r", 3);
  for (int s = 1; s <= 3; ++s) {
    const fs::path seed = dir / "readings" / ("seed" + std::to_string(s));
    write_preparation(seed / "r_loose_prepare.h5", 0.71 + 0.01 * s, 8);
    for (int t : {1, 2})
      if (s != 3 || t != 2) write_test(seed / ("r_loose_test" + std::to_string(t) + ".h5"), 1.2 + 0.1 * s);
  }
  // Three rows; the medium one is of a density the readings study does not run.
  std::ofstream(dir / "refs.yaml") << R"(source: test
rows:
  - {name: "e0, loose", quantity: void_ratio_after_preparation, density: loose, reference: 0.71, check: within, tolerance: 0.02,
     resolution: 0.005, source: t, reason: t}
  - {name: "ev, loose", quantity: ev_after_cycle, density: loose, cycle: 1, reference: 1.1, check: within, tolerance: 0.5,
     resolution: 0.005, source: t, reason: t}
  - {name: "e0, medium", quantity: void_ratio_after_preparation, density: medium, reference: 0.67, check: within, tolerance: 0.02,
     source: t, reason: t}
)";
  const std::string common = "'" + bin + "' decisions '" + (dir / "readings").string() + "' '" + (dir / "out").string() + "' --references '" +
                             (dir / "refs.yaml").string() + "'";

  // Without a baseline of its own or from elsewhere: a clear error, exit 1.
  auto r = dem::test::run_command(common + " 2>&1");
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("no results of the baseline reading 'baseline'") != std::string::npos);

  r = dem::test::run_command(common + " --baseline-results '" + (dir / "paper").string() + "' 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(dir / "out" / "decisions.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j.at("particles") == 8);  // from the baseline's preparations
  CHECK(j.at("samples") == 3);    // seeds 1-3, not the baseline study's 4
  CHECK(j.at("schema") == 2);
  // The stamp of the readings study's own runs: seed1's preparation has 8 spheres, the study 3
  // samples; these fixtures carry no engine version and no resolved scene, so neither is recorded.
  CHECK(j.at("stamp").at("spheres") == 8);
  CHECK(j.at("stamp").at("samples") == 3);
  CHECK(j.at("stamp").at("engine") == "not recorded");
  CHECK(j.at("stamp").at("baseline") == "not recorded");
  {
    // With scenes: the stamp's baseline is that of the study the readings are shifts from (its
    // seed1 preparation), not the reading's own, which changes the preparation by design.
    const std::string paper_scene = "name: seed1/loose_prepare\nmaterial: {kn: 1000000}\n";
    for (const auto& [file, text] : {std::pair{dir / "paper" / "seed1" / "loose_prepare.h5", paper_scene},
                                     {dir / "readings" / "seed1" / "r_loose_prepare.h5", std::string("name: x\nmaterial: {kn: 2000000}\n")}}) {
      dem::h5::Handle f = dem::h5::open_file_write(file.string());
      dem::h5::write_text(f, "scene_yaml", text);
    }
    const auto again = dem::test::run_command(common + " --baseline-results '" + (dir / "paper").string() + "' 2>&1");
    REQUIRE(again.exit_code == 0);
    std::ifstream stamped(dir / "out" / "decisions.json");
    CHECK(nlohmann::json::parse(stamped).at("stamp").at("baseline") == validation::baseline_of(paper_scene));
  }
  REQUIRE(j.at("rows").size() == 2);  // the medium row left out
  const nlohmann::json& e0 = j.at("rows")[0];
  CHECK(e0.at("name") == "e0, loose");
  // Baseline mean 0.71 (seed4's 0.90 not read), sd 0.01; "r" 0.73: +0.02 / max(0.01, 0.005) = +2.
  CHECK(e0.at("baseline_mean").get<double>() == Approx(0.71));
  CHECK(e0.at("readings").at("r").at("shift_sd").get<double>() == Approx(2.0));
  CHECK(e0.at("judged") == true);
  // εv reads every test; seed3 of "r" lacks Test 2: not judged under "r", so the row is not judged.
  const nlohmann::json& ev = j.at("rows")[1];
  CHECK(ev.at("readings").at("r").at("verdict") == "not judged");
  CHECK(ev.at("readings").at("r").at("shift_sd").is_null());
  CHECK(ev.at("readings").at("r").at("missing_runs") == nlohmann::json::array({"seed3 test2"}));
  CHECK(ev.at("judged") == false);
  CHECK(ev.at("explanation") == "not judged: no reading has every run this row reads (r lacks seed3 test2)");
  CHECK(j.at("missing_results") == 1);
  // decisions.json is declared once (judge/decisions_file.hpp): what the reader makes of the file,
  // written again by the writer, is the file; the readings' settings are in it, the baseline first.
  {
    std::ifstream again(dir / "out" / "decisions.json");
    const nlohmann::json written = nlohmann::json::parse(again);
    const validation::DecisionsFile back = validation::read_decisions_file((dir / "out" / "decisions.json").string());
    CHECK(nlohmann::json(validation::decisions_file_json(back)) == written);
    REQUIRE(back.settings.size() == 2);
    CHECK(back.settings[0].first == "baseline");
    CHECK(back.settings[0].second.rfind("as written (", 0) == 0);
    CHECK(back.settings[1].first == "r");
  }
  std::ifstream table(dir / "out" / "table.md");
  const std::string md((std::istreambuf_iterator<char>(table)), std::istreambuf_iterator<char>());
  CHECK(md.find("Measured at 8 spheres, 3 samples") != std::string::npos);
  CHECK(md.find("runs missing —") != std::string::npos);
  CHECK(md.find("Only the rows of the densities this study runs (loose): 2 of 3") != std::string::npos);

  // A readings study whose seeds the baseline study lacks: a clear error, exit 1.
  write_manifest(dir / "small", "-", 2);
  r = dem::test::run_command(common + " --baseline-results '" + (dir / "small").string() + "' 2>&1");
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("has no runs of sample 'seed3'") != std::string::npos);
}
