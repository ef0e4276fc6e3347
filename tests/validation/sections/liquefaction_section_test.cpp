// compare-runs liquefaction on an ensemble folder (seed<N>/, as the pipeline writes a study with
// `seeds`): per density and CSR the median N_L over the samples with its range and the counts
// liquefied / censored, a median that is itself censored written "> N", and every test in the
// per-sample table with its seed. The results are hand-made HDF5 files whose N_L are set exactly.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/compare-runs";
constexpr double period_s = 0.02;  // the scene's cyclic period

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A complete undrained cyclic test at `csr` (the shipped scene with its amplitude set, 2 CSR p0):
// a consolidation row, then the cyclic stage from t = 0.1 s for `cycles` periods; it stopped on
// r_u (liquefied) or ran to its duration (censored).
void write_test(const fs::path& file, double csr, double cycles, bool liquefied) {
  fs::create_directories(file.parent_path());
  const std::string scene_file = std::string(DEM_SOURCE_DIR) + "/scenes/tests/undrained_cyclic.yaml";
  std::string scene = read_file(scene_file);
  const std::string amplitude = "amplitude: 2.0e4";
  REQUIRE(scene.find(amplitude) != std::string::npos);
  scene.replace(scene.find(amplitude), amplitude.size(), "amplitude: " + std::to_string(2 * csr * 1e5));
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::test::mark_complete(f);
  dem::h5::write_text(f, "scene_yaml", scene);
  const double t0 = 0.1, t1 = t0 + cycles * period_s, ru1 = liquefied ? 0.95 : 0.4;
  dem::h5::set_attribute(f, "stage_end_cyclic", liquefied ? "until.pore_pressure_ratio met at time " + std::to_string(t1) + " s"
                                                           : std::string("duration reached"));
  dem::h5::Handle g = dem::h5::create_group(f, "timeseries");
  dem::h5::write<double>(g, "stage", {0, 1, 1}, 1, "1");
  dem::h5::write<double>(g, "time", {0, t0, t1}, 1, "s");
  dem::h5::write<double>(g, "p", {1e5, 1e5, 1e5 * (1 - ru1)}, 1, "Pa");
  dem::h5::write<double>(g, "pore_pressure_ratio", {0, 0, ru1}, 1, "1");
}

// A complete hold (the shipped scene: nothing applied) from t = 0.1 s: r_u rises linearly to 0.95
// at `collapse_cycles` periods, where until.pore_pressure_ratio ends it.
void write_collapsing_hold(const fs::path& file, double collapse_cycles) {
  fs::create_directories(file.parent_path());
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::test::mark_complete(f);
  dem::h5::write_text(f, "scene_yaml", read_file(std::string(DEM_SOURCE_DIR) + "/scenes/tests/undrained_hold.yaml"));
  const double t0 = 0.1, t1 = t0 + collapse_cycles * period_s;
  dem::h5::set_attribute(f, "stage_end_hold", "until.pore_pressure_ratio met at time " + std::to_string(t1) + " s");
  dem::h5::Handle g = dem::h5::create_group(f, "timeseries");
  dem::h5::write<double>(g, "stage", {0, 1, 1}, 1, "1");
  dem::h5::write<double>(g, "time", {0, t0, t1}, 1, "s");
  dem::h5::write<double>(g, "p", {1e5, 1e5, 0.05e5}, 1, "Pa");
  dem::h5::write<double>(g, "pore_pressure_ratio", {0, 0, 0.95}, 1, "1");
}

// compare-runs liquefaction on <dir>/results into <dir>/out; its table.md.
std::string liquefaction_table(const fs::path& dir) {
  const std::string cmd = bin + " liquefaction " + (dir / "out").string() + " " + (dir / "results").string() + " > " +
                          (dir / "log").string() + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  return read_file(dir / "out" / "table.md");
}

}  // namespace

TEST_CASE("compare-runs liquefaction: a hold that collapses on its own says which tests the loading set and which the collapse did",
          "[liquefaction][compare-runs]") {
  // One sample: its hold reaches r_u 0.95 after 10 cycles with nothing applied (r_u linear in
  // time: 0.095 per cycle). CSR 0.05 liquefied after 1 cycle, CSR 0.03 after 2: earlier, the hold's
  // r_u then at most 2 x 0.095 = 0.190. CSR 0.01 liquefied after 12 cycles: later than the hold.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_liquefaction_collapse";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  std::ofstream runs(dir / "results" / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n"
       << "-\tloose\t-\tseed1/loose_prepare\t/elsewhere/loose_prepare.h5\t-\t0\tas written\t1\n"
       << "-\tloose\thold\tseed1/loose_hold\t/elsewhere/loose_hold.h5\tseed1/loose_prepare\t0\tas written\t1\n";
  write_collapsing_hold(dir / "results" / "seed1" / "loose_hold.h5", 10);
  for (const auto& [csr, cycles] : std::vector<std::pair<std::string, double>>{{"0.05", 1}, {"0.03", 2}, {"0.01", 12}}) {
    runs << "-\tloose\tcsr" << csr << "\tseed1/loose_csr" << csr << "\t/elsewhere/loose_csr" << csr
         << ".h5\tseed1/loose_prepare\t0\tas written\t1\n";
    write_test(dir / "results" / "seed1" / ("loose_csr" + csr + ".h5"), std::stod(csr), cycles, true);
  }
  runs.close();
  const std::string table = liquefaction_table(dir);
  INFO(table);
  CHECK(table.find("⚠ seed1/loose_hold reached r_u ≥ 0.95 with nothing applied after 0.2000 s (10.00 cycles of 0.02 s): its sample "
                   "collapses at constant volume on its own, which bounds the N_L of every test of that sample; 2 of its cyclic tests "
                   "liquefied earlier, after 1.00 – 2.00 cycles, when the hold's r_u was at most 0.190: the loading set their N_L; "
                   "1 liquefied no earlier than the hold: their N_L is the sample's collapse, not set by the loading.") != std::string::npos);
  // The r_u figure's colours: a test's CSR by its rank in its density (0.01, 0.03, 0.05: 1, 2, 3),
  // the hold 0; each the first of its CSR (one sample), so each in the key.
  const std::string values = read_file(dir / "out" / "values.gp");
  INFO(values);
  for (const std::string line : {"liq_run_1 = \"seed1/loose_hold\"", "liq_run_csr_1 = \"hold\"", "liq_run_csr_rank_1 = \"0\"",
                                 "liq_run_csr_2 = \"0.05\"", "liq_run_csr_rank_2 = \"3\"", "liq_run_csr_rank_3 = \"2\"",
                                 "liq_run_csr_4 = \"0.01\"", "liq_run_csr_rank_4 = \"1\"", "liq_run_first_4 = \"1\""})
    CHECK(values.find(line + "\n") != std::string::npos);
  // Both figure scripts draw from this output.
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
    for (const std::string figure : {"csr_nl", "ru"}) {
      const std::string draw = "cd '" + (dir / "out").string() + "' && GNUPLOT_LIB='" + DEM_SOURCE_DIR + "/reports/gnuplot' gnuplot '" +
                               DEM_SOURCE_DIR + "/reports/gnuplot/liquefaction_" + figure + ".gp' > draw.log 2>&1";
      CHECK(std::system(draw.c_str()) == 0);
      CHECK(fs::file_size(dir / "out" / (figure + ".png")) > 0);
    }
}

TEST_CASE("compare-runs liquefaction: median and range of N_L over an ensemble's samples, censored ones as > N",
          "[liquefaction][compare-runs]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_liquefaction";
  fs::remove_all(dir);
  // CSR 0.02: seed 1 liquefied after 2 cycles, seeds 2 and 3 ran their 50 cycles without: the
  // median is seed 2's or 3's, censored: "> 50.00"; the range 2.00 – > 50.00.
  // CSR 0.05: 1, 3, 2 cycles, all liquefied: median 2.00, range 1.00 – 3.00.
  const struct {
    int seed;
    double csr, cycles;
    bool liquefied;
  } tests[] = {{1, 0.02, 2, true}, {2, 0.02, 50, false}, {3, 0.02, 50, false}, {1, 0.05, 1, true}, {2, 0.05, 3, true}, {3, 0.05, 2, true}};
  fs::create_directories(dir / "results");
  std::ofstream runs(dir / "results" / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  for (int s = 1; s <= 3; ++s)
    runs << "-\tloose\t-\tseed" << s << "/loose_prepare\t/elsewhere/seed" << s << "/loose_prepare.h5\t-\t0\tas written\t" << s << "\n";
  for (const auto& t : tests) {
    std::ostringstream csr;
    csr << t.csr;
    const std::string run = "seed" + std::to_string(t.seed) + "/loose_csr" + csr.str();
    // The manifest records where the pipeline wrote; compare-runs finds the file under the folder.
    runs << "-\tloose\tcsr" << csr.str() << "\t" << run << "\t/elsewhere/" << run << ".h5\tseed" << t.seed
         << "/loose_prepare\t0\tas written\t" << t.seed << "\n";
    write_test(dir / "results" / ("seed" + std::to_string(t.seed)) / ("loose_csr" + csr.str() + ".h5"), t.csr, t.cycles, t.liquefied);
  }
  runs.close();
  const std::string table = liquefaction_table(dir);
  INFO(table);
  CHECK(table.find("Samples: loose 3 (seeds 1, 2, 3)") != std::string::npos);
  CHECK(table.find("| loose | 0.02 | 3 | 1 | 2 | > 50.00 (the median is censored) | 2.00 – > 50.00 |") != std::string::npos);
  CHECK(table.find("| loose | 0.05 | 3 | 3 | 0 | 2.00 | 1.00 – 3.00 |") != std::string::npos);
  CHECK(table.find("loose: 4 of 6 tests liquefied over 2 CSR(s).") != std::string::npos);
  // Every sample's test, with its seed; a censored one as "> N".
  CHECK(table.find("| seed2/loose_csr0.02 | 2 | 0.020 | 0.0200 | 100.00 | > 50.00 | not liquefied in 50.0 cycles |") != std::string::npos);
  CHECK(table.find("| seed3/loose_csr0.05 | 3 | 0.050 | 0.0500 | 100.00 | 2.00 | liquefied: r_u ≥ 0.95 |") != std::string::npos);
  // The figure's data: one row per density and CSR, the censored median's upper bound NaN (infinite).
  const std::string summary = read_file(dir / "out" / "csr_nl_summary.dat");
  INFO(summary);
  CHECK(summary.find("\"loose_csr0.02\"\t1\t0.02\t3\t1\t2\t50\tNaN\t1\t2\t0\t50\t1") != std::string::npos);
  CHECK(summary.find("\"loose_csr0.05\"\t1\t0.05\t3\t3\t0\t2\t2\t0\t1\t0\t3\t0") != std::string::npos);
  // The section's stamp beside its table: the 3 samples of runs.tsv; no preparation result here
  // (the tests start from files not in the folder), so no engine or baseline is recorded.
  const nlohmann::json stamp = nlohmann::json::parse(read_file(dir / "out" / "stamp.json"));
  CHECK(stamp.at("samples") == 3);
  CHECK(stamp.at("engine") == "not recorded");
  CHECK(stamp.at("baseline") == "not recorded");
}
