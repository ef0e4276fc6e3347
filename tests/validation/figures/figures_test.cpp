// The data behind the figures (validation/figures/figures.hpp, build/bin/figure-data) on inputs whose
// columns are known analytically: the pi-plane point of a known stress, q/p of a known tensor, the
// target path of known legs, per-cycle statistics of two samples, Test 5's blocks, the strain
// increment arrows and their scale, a grading of known radii; and the whole tool on a synthetic
// result file written here, with the static gnuplot scripts drawing from what it wrote.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/time_series.hpp"
#include "analysis/legs.hpp"
#include "control/stress_path.hpp"
#include "figures/figures.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"

namespace fs = std::filesystem;
using validation::Columns;

namespace {

// Rows of stress (diagonal, in kPa) with everything else zero; all time-series columns present.
Columns series_of(const std::vector<dem::Vec3>& diag_kPa) {
  Columns c;
  for (const dem::SeriesColumn& col : dem::series_columns()) c[col.name] = std::vector<double>(diag_kPa.size(), 0.0);
  for (std::size_t i = 0; i < diag_kPa.size(); ++i) {
    c["step"][i] = static_cast<double>(i);
    c["stress_11"][i] = 1e3 * diag_kPa[i][0];
    c["stress_22"][i] = 1e3 * diag_kPa[i][1];
    c["stress_33"][i] = 1e3 * diag_kPa[i][2];
  }
  return c;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("figure data: the pi-plane point of a known stress", "[figures]") {
  // (120, 100, 80) kPa: p = 100 kPa, x = (s3 - s2)/(sqrt(2) p) = -20/(100 sqrt 2),
  // y = (2 s1 - s2 - s3)/(sqrt(6) p) = 60/(100 sqrt 6). Round-off only: 1e-12.
  const Eigen::Vector2d xy = validation::pi_stress(dem::Vec3(120e3, 100e3, 80e3));
  CHECK(xy[0] == Approx(-0.2 / std::sqrt(2.0)).margin(1e-12));
  CHECK(xy[1] == Approx(0.6 / std::sqrt(6.0)).margin(1e-12));
  // The named states at p, R: TC1 at y = sqrt(6) (R - 1)/(R + 2), TE1 at y = -sqrt(6) (R - 1)/(2R + 1),
  // both on the axis x = 0; A at the origin.
  const double R = 1.24;
  const validation::Table states = validation::named_states(1e5, R);
  REQUIRE(states.labels == std::vector<std::string>{"A", "TC1", "TC2", "TC3", "TE1", "TE2", "TE3"});
  CHECK(states.at(0, "x") == Approx(0).margin(1e-12));
  CHECK(states.at(0, "y") == Approx(0).margin(1e-12));
  CHECK(states.at(1, "x") == Approx(0).margin(1e-12));
  CHECK(states.at(1, "y") == Approx(std::sqrt(6.0) * (R - 1) / (R + 2)).epsilon(1e-12));
  CHECK(states.at(4, "y") == Approx(-std::sqrt(6.0) * (R - 1) / (2 * R + 1)).epsilon(1e-12));
  // TC2 is TC1 turned by 120 degrees: (-sqrt(3)/2, -1/2) times its radius.
  CHECK(states.at(2, "x") == Approx(-std::sqrt(3.0) / 2 * states.at(1, "y")).epsilon(1e-12));
  CHECK(states.at(2, "y") == Approx(-0.5 * states.at(1, "y")).epsilon(1e-12));
}

TEST_CASE("figure data: q/p of a known tensor, from its principal values", "[figures]") {
  // [[100, 20, 0], [20, 100, 0], [0, 0, 100]] kPa has principal values 120, 80 and 100 kPa:
  // q = sqrt(((120-80)^2 + (80-100)^2 + (120-100)^2)/2) = sqrt(1200) kPa, p = 100 kPa. The shear
  // stress counts (the engine's q), while the axis stresses alone would give q = 0.
  dem::Mat3 s;
  s << 100e3, 20e3, 0, 20e3, 100e3, 0, 0, 0, 100e3;
  CHECK(validation::q_over_p(s) == Approx(std::sqrt(1200.0) / 100).epsilon(1e-12));
  // The target q of TC and TE: q = 3p (R-1)/(R+2) and 3p (R-1)/(2R+1) [kPa].
  const validation::Table q = validation::target_q(1e5, 1.24);
  CHECK(q.at(0, "q") == Approx(300 * 0.24 / 3.24).epsilon(1e-12));
  CHECK(q.at(1, "q") == Approx(300 * 0.24 / 3.48).epsilon(1e-12));
  // Through a series: q against p and q/p against eps_d of one row.
  Columns c = series_of({{130, 85, 85}});
  c["deviatoric_strain"][0] = 0.002;
  const validation::Table qp = validation::q_against_p(c);
  CHECK(qp.at(0, "p") == Approx(100).epsilon(1e-12));
  CHECK(qp.at(0, "q") == Approx(45).epsilon(1e-12));
  const validation::Table ed = validation::qp_against_deviatoric_strain(c, 5);
  CHECK(ed.at(0, "eps_d") == Approx(0.2));
  CHECK(ed.at(0, "q/p") == Approx(0.45).epsilon(1e-12));
  // Units in the header.
  CHECK(qp.text().find("# p [kPa]\tq [kPa]\n") != std::string::npos);
}

TEST_CASE("figure data: the fabric ratio of a known fabric tensor", "[figures]") {
  // diag(0.4, 0.3, 0.3): m = 1/3, d = sqrt((0.1^2 + 0 + 0.1^2)/2) = 0.1, ratio 0.3.
  Columns c = series_of({{100, 100, 100}});
  c["strong_fabric_11"][0] = 0.4, c["strong_fabric_22"][0] = 0.3, c["strong_fabric_33"][0] = 0.3;
  const validation::Table t = validation::qp_against_fabric(c, "strong_fabric", 5);
  CHECK(t.at(0, "strong_fabric_ratio") == Approx(0.3).epsilon(1e-12));
  CHECK(t.at(0, "q/p") == Approx(0).margin(1e-12));
}

TEST_CASE("figure data: the target path of known legs, each leg once", "[figures]") {
  // A -> TC1 -> A -> TC1 (repeated leg drawn once) -> TE1.
  Columns legs;
  const dem::Vec3 tc = dem::named_state("TC1", 1e5, 1.24), a = dem::named_state("A", 1e5, 1.24), te = dem::named_state("TE1", 1e5, 1.24);
  for (const dem::Vec3& v : {tc, a, tc, a, te}) {
    legs["target_1"].push_back(v[0]);
    legs["target_2"].push_back(v[1]);
    legs["target_3"].push_back(v[2]);
  }
  const validation::Table t = validation::target_path(legs);
  REQUIRE(t.size() == 3);  // A->TC1, TC1->A, A->TE1
  const double y_tc = std::sqrt(6.0) * 0.24 / 3.24;
  CHECK(t.at(0, "dy") == Approx(y_tc).epsilon(1e-12));
  CHECK(t.at(1, "y_from") == Approx(y_tc).epsilon(1e-12));
  CHECK(t.at(1, "dy") == Approx(-y_tc).epsilon(1e-12));
  CHECK(t.at(2, "dy") == Approx(-std::sqrt(6.0) * 0.24 / 3.48).epsilon(1e-12));
}

TEST_CASE("figure data: per-cycle mean and spread of two samples", "[figures]") {
  validation::TestResult a, b;
  a.series["cycle"] = {0, 1, 1, 2};
  a.series["cycle_end"] = {0, 0, 1, 1};
  a.series["volumetric_strain"] = {0, 0.005, 0.001, 0.002};
  b.series = a.series;
  b.series["volumetric_strain"] = {0, 0.009, 0.003, 0.006};
  const auto& epsv = validation::cycle_quantities().at(0);
  const validation::Table t = validation::cycle_statistics({&a, &b}, epsv);
  REQUIRE(t.size() == 3);  // cycle 0 (first row), 1, 2
  CHECK(t.at(0, "mean") == 0);
  CHECK(t.at(1, "mean") == Approx(0.2));            // (0.1 + 0.3)/2 %
  CHECK(t.at(1, "sd") == Approx(std::sqrt(0.02)));  // sample sd of 0.1, 0.3
  CHECK(t.at(2, "n") == 2);
  CHECK(t.at(2, "min") == Approx(0.2));
  CHECK(t.at(2, "max") == Approx(0.6));
  // The sliding fraction has no cycle 0.
  a.series["sliding_fraction"] = {0.5, 0.1, 0.1, 0.1};
  CHECK(validation::cycle_statistics({&a}, validation::cycle_quantities().at(2)).at(0, "cycle") == 1);
}

TEST_CASE("figure data: Test 5's blocks of cycles loading one axis", "[figures]") {
  // Cycles 1-2 load axis 1 (A <-> TC1), cycle 3 axis 3 (A <-> TC3).
  Columns legs;
  const double p = 1e5, R = 1.24;
  int cycle = 0;
  for (const char* s : {"TC1", "A", "TC1", "A", "TC3", "A"}) {
    const dem::Vec3 v = dem::named_state(s, p, R);
    if (std::string(s) != "A") ++cycle;
    legs["cycle"].push_back(cycle);
    legs["target_1"].push_back(v[0]), legs["target_2"].push_back(v[1]), legs["target_3"].push_back(v[2]);
  }
  Columns series = series_of({{100, 100, 100}, {110, 100, 90}, {100, 100, 100}, {90, 100, 110}});
  series["cycle"] = {0, 1, 2, 3};
  std::vector<std::string> titles;
  const validation::Table t = validation::test5_blocks(series, legs, titles);
  REQUIRE(titles.size() == 2);
  CHECK(titles[0] == "cycles 1–2: A↔TC1 (steps 1–2)");
  CHECK(titles[1] == "cycles 3–3: A↔TC3 (steps 3–4)");
  // Rows 0-2 in block 1; block 2 starts with the last row of block 1 again, then row 3.
  REQUIRE(t.size() == 5);
  REQUIRE(t.block_starts == std::vector<std::size_t>{3});
  CHECK(t.rows[3] == t.rows[2]);
  CHECK(t.at(4, "s11/s33") == Approx(90.0 / 110));
}

TEST_CASE("figure data: strain increment arrows and a round scale", "[figures]") {
  Columns s = series_of({{110, 100, 90}, {90, 100, 110}, {110, 100, 90}});
  s["cycle"] = {1, 1, 2};
  s["leg_end"] = {1, 1, 1};
  s["leg"] = {0, 1, 2};
  s["pi_strain_increment_x"] = {0.0003, -0.0004, 0.0001};
  s["pi_strain_increment_y"] = {0.0004, 0.0003, 0};
  // Longest increment 5e-4: 0.12 / 5e-4 = 240, rounded down to 1, 2 or 5 x 10^k: 200.
  const double scale = validation::arrow_scale(s, {1, 2});
  CHECK(scale == Approx(200));
  const validation::Table t = validation::strain_increments(s, 1, scale);
  REQUIRE(t.size() == 2);
  CHECK(t.at(0, "arrow_dx") == Approx(0.06));
  CHECK(t.at(1, "order") == 2);
  CHECK(t.at(0, "x") == Approx(-0.1 / std::sqrt(2.0)));  // (110, 100, 90) kPa: (90 - 100)/(sqrt(2) 100)
  // A small scale: longest 0.5 -> 0.24 -> 0.2.
  s["pi_strain_increment_x"] = {0.5, 0, 0};
  CHECK(validation::arrow_scale(s, {1}) == Approx(0.2));
}

TEST_CASE("figure data: grading of known radii, by mass and by count", "[figures]") {
  // Diameters 2 and 4 mm: masses 8 : 64, so by mass 8/72 finer than 4 mm, by count 1/2.
  const validation::Table t = validation::grading_realised({2e-3, 1e-3});
  REQUIRE(t.size() == 2);
  CHECK(t.at(0, "diameter") == Approx(2));
  CHECK(t.at(0, "percent_finer_by_mass") == Approx(100.0 * 8 / 72));
  CHECK(t.at(0, "percent_finer_by_count") == Approx(50));
  CHECK(t.at(1, "percent_finer_by_mass") == Approx(100));
  CHECK(validation::grading_diameter_at({3e-3, 3.7e-3, 4.5e-3}, {0, 50, 100}, 50) == Approx(3.7e-3));
  CHECK(validation::grading_diameter_at({3e-3, 4.5e-3}, {0, 100}, 50) == Approx(3.75e-3));
}

TEST_CASE("figure data: the paper's values come from reference_data/paper.yaml", "[figures]") {
  const auto rows = validation::load_references(std::string(DEM_SOURCE_DIR) + "/reference_data/paper.yaml", "paper");
  CHECK(validation::paper_value(rows, "coordination_after_preparation", "loose") == Approx(4.09));
  CHECK(validation::paper_value(rows, "void_ratio_after_preparation", "dense") == Approx(0.57));
  CHECK(validation::paper_value(rows, "qp_strong_fabric_slope", "") == Approx(1.0));
  CHECK_FALSE(validation::paper_value(rows, "no_such_quantity", "loose"));
}

TEST_CASE("figure-data on a synthetic result: known columns, and every figure script draws", "[figures][tool]") {
  // One complete result, loose Test 1, written here: three rows at known stresses, two legs.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test-figures";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  Columns series = series_of({{100, 100, 100}, {121.5, 89.25, 89.25}, {100, 100, 100}});
  series["cycle"] = {0, 1, 1};
  series["cycle_end"] = {0, 0, 1};
  series["leg_end"] = {0, 1, 1};
  series["leg"] = {-1, 0, 1};
  series["volumetric_strain"] = {0, 0.001, 0.003};
  series["coordination_number"] = {4.2, 4.1, 4.0};
  series["q_over_p"] = {0, 0.3225, 0};  // q/p of the rows' stresses: row 2, q = 32.25 kPa at p = 100 kPa
  series["strong_fabric_ratio"] = {0, 0.3, 0.1};
  {
    dem::h5::Handle f = dem::h5::create_file((dir / "results" / "loose_test1.h5").string());
    dem::test::mark_complete(f);
    dem::h5::Handle ts = dem::h5::create_group(f, "timeseries");
    for (const auto& [name, v] : series) dem::h5::write<double>(ts, name, v, 1, "1");
    dem::h5::Handle lg = dem::h5::create_group(f, "legs");
    const dem::Vec3 tc = dem::named_state("TC1", 1e5, 1.24);
    std::map<std::string, std::vector<double>> legs = {{"cycle", {1, 1}}, {"target_1", {tc[0], 1e5}}, {"target_2", {tc[1], 1e5}},
                                                       {"target_3", {tc[2], 1e5}}};
    for (const dem::SeriesColumn& c : dem::leg_columns())
      if (!legs.count(c.name)) legs[c.name] = {0, 0};
    for (const auto& [name, v] : legs) dem::h5::write<double>(lg, name, v, 1, "1");
  }
  const std::string bin = std::string(DEM_BINARY_DIR) + "/bin";
  const std::string figs = (dir / "figs").string();
  const std::string cmd = "cd '" + dir.string() + "' && '" + bin + "/figure-data' figures results '" + figs + "' --references '" +
                          DEM_SOURCE_DIR + "/reference_data/paper.yaml' > log 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  // Fig. 4 of the run: p and q of each row, in kPa. Row 2: (121.5, 89.25, 89.25) kPa: p = 100, q = 32.25.
  const std::string q_p = slurp(dir / "figs" / "fig04_q_p_loose_test1.dat");
  CHECK(q_p.find("# p [kPa]\tq [kPa]\n100\t0\n100\t32.25\n100\t0\n") != std::string::npos);
  // Fig. 7 of a one-sample study: cycle 0 and 1, in %.
  const std::string ev = slurp(dir / "figs" / "fig07_epsv_cycles_loose_test1.dat");
  CHECK(ev.find("\n0\t0\t0\t1\t0\t0\n1\t0.3\t0\t1\t0.3\t0.3\n") != std::string::npos);
  // values.gp: what exists, and the paper's values from reference_data/paper.yaml.
  const std::string values = slurp(dir / "figs" / "values.gp");
  CHECK(values.find("has_loose_test1 = 1\n") != std::string::npos);
  CHECK(values.find("has_loose_test2 = 0\n") != std::string::npos);
  CHECK(values.find("has_dense = 0\n") != std::string::npos);
  CHECK(values.find("paper_cn_loose = 4.09\n") != std::string::npos);
  // The samples before shearing: no preparation here, so a header and no row (the figure says "not run").
  CHECK(slurp(dir / "figs" / "fig00_samples.dat").find("density [1]\tvoid ratio e0 [1]\tcoordination number [1]\n") != std::string::npos);
  CHECK(values.find("fig00_samples_rows = 0\n") != std::string::npos);
  // The slope after shearing: through the origin over the rows of a leg (not row 1, leg -1):
  // (0.3 x 0.3225 + 0.1 x 0) / (0.3^2 + 0.1^2) = 0.9675, loose (1); the paper's 1 ± 0.25 beside it.
  const std::string slopes = slurp(dir / "figs" / "fig00_slopes.dat");
  INFO(slopes);
  CHECK(slopes.find("density [1]\tslope of q/p against F^s_d/F^s_m [1]\n") != std::string::npos);
  CHECK(slopes.find("\t1\t0.9675\n") != std::string::npos);
  CHECK(values.find("fig00_slopes_rows = 1\n") != std::string::npos);
  CHECK(values.find("paper_slope_tolerance = 0.25\n") != std::string::npos);
  // No absolute path of this machine in anything written.
  for (const auto& e : fs::directory_iterator(dir / "figs")) CHECK(slurp(e.path()).find(dir.string()) == std::string::npos);
  // Every static script draws from this partial set (missing runs say "not run"): gnuplot exits 0.
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    std::string draw = "'";  // built piece by piece (GCC 12 warns, wrongly, on "..." + std::string temporaries)
    draw += DEM_SOURCE_DIR;
    draw += "/reports/make_figures.sh' '" + bin + "' '" + (dir / "results").string() + "' '" + figs + "' > '";
    draw += (dir / "draw.log").string() + "' 2>&1";
    CHECK(std::system(draw.c_str()) == 0);
    CHECK(fs::exists(dir / "figs" / "fig03_stress_paths.png"));
    CHECK(fs::exists(dir / "figs" / "fig10_coordination.png"));
    CHECK(fs::exists(dir / "figs" / "fig00_samples.png"));
    CHECK(fs::exists(dir / "figs" / "fig00_slopes.png"));
  }
}

TEST_CASE("figure-data settings: what the report quotes comes from the resolved scene of a run", "[figures][tool]") {
  // A real run of the engine (27 spheres, seconds): its result's scene, read back by figure-data.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test-figure-settings";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string bin = std::string(DEM_BINARY_DIR) + "/bin";
  std::string run = "'" + bin + "/dem' run '";
  run += DEM_SOURCE_DIR;
  run += "/scenes/stability/base.yaml' --out '" + (dir / "loose_prepare.h5").string() +
         "' --quiet --set 'particles.lattice.n=[3, 3, 3]' --set numerics.time_step=5.0e-7 --set material.friction=0.3 > /dev/null 2>&1";
  REQUIRE(std::system(run.c_str()) == 0);
  const std::string cmd = "'" + bin + "/figure-data' settings '" + dir.string() + "' > '" + (dir / "settings.tsv").string() + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string s = slurp(dir / "settings.tsv");
  CHECK(s.find("particles\t27\n") != std::string::npos);
  CHECK(s.find("lattice\t3×3×3\n") != std::string::npos);
  CHECK(s.find("time_step_prepare_s\t5e-07\n") != std::string::npos);
  CHECK(s.find("friction_prepare\t0.3\n") != std::string::npos);
  CHECK(s.find("target_pressure_kPa\t100\n") != std::string::npos);
  CHECK(s.find("max_energy_error\t0.05\n") != std::string::npos);
}

// make cyclic-tests' line of one test (figure-data tests-table), on hand-made columns: the worst
// tracking error over the three axes and every leg, the largest inertial number, and the values
// at the ends of cycle 1 and of the last cycle (3 here), CN also at the first row.
TEST_CASE("tests-table: one cyclic test's line from its series and legs", "[figures]") {
  validation::Columns series = {{"step", {0, 100, 200, 300, 400}},
                                {"cycle", {0, 1, 2, 3, 3}},
                                {"cycle_end", {0, 1, 1, 0, 1}},
                                {"volumetric_strain", {0, 0.001, 0.0015, 0.0019, 0.002}},
                                {"coordination_number", {4.5, 4.4, 4.35, 4.31, 4.3}}};
  validation::Columns legs = {{"rms_error_1", {0.001, 0.004}}, {"rms_error_2", {0.002, 0.0005}}, {"rms_error_3", {0.0031, 0.0}},
                              {"max_inertial_number", {2e-5, 7.5e-5}}};
  const validation::CyclicTestLine l = validation::cyclic_test_line(series, legs);
  CHECK(l.steps == "400");
  CHECK(l.tracking_percent == "0.400");
  CHECK(l.inertial_number == "7.50e-05");
  CHECK(l.last_cycle == "3");
  CHECK(l.ev_cycle1 == "0.1000");
  CHECK(l.ev_last == "0.2000");
  CHECK(l.cn_start == "4.500");
  CHECK(l.cn_cycle1 == "4.400");
  CHECK(l.cn_last == "4.300");
  legs.erase("rms_error_2");  // a column missing: its cell is a dash, the rest stays
  CHECK(validation::cyclic_test_line(series, legs).tracking_percent == "—");
  CHECK(validation::cyclic_test_line(series, legs).inertial_number == "7.50e-05");
}
