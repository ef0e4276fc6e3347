// The calibration's references: curves read from CSV, their misfit on a run's series, and the
// calibration file's errors.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>

#include "calibration_file.hpp"
#include "config/yaml_section.hpp"
#include "references.hpp"
#include "sets.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "calibration_refs";

std::string write(const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "accepted";
}

// A run whose last stage has y = 2 x for x = 0 ... 1 (an earlier stage has other values).
validation::TestResult line_run() {
  validation::TestResult t;
  t.name = "triaxial";
  for (int i = 0; i < 3; ++i) t.series["stage"].push_back(0), t.series["x"].push_back(0.7), t.series["y"].push_back(9);
  for (int i = 0; i <= 10; ++i) t.series["stage"].push_back(1), t.series["x"].push_back(0.1 * i), t.series["y"].push_back(0.2 * i);
  return t;
}

std::vector<validation::Sample> samples_of(const std::vector<validation::TestResult>& runs) {
  std::vector<validation::Sample> out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    validation::Sample s;
    s.name = "seed" + std::to_string(i + 1);
    s.densities["dense"].tests.push_back(runs[i]);
    out.push_back(s);
  }
  return out;
}

}  // namespace

TEST_CASE("a curve is read on the run's last stage, where x first reaches each point", "[calibration]") {
  calibration::CurveRow c;
  c.x = "x", c.y = "y";
  c.points = {{0.25, 0, 0}, {0.7, 0, 0}, {1.5, 0, 0}};
  const auto v = calibration::curve_on_run(c, line_run());
  REQUIRE(v[0]);
  CHECK(*v[0] == Approx(0.5));  // between the rows at 0.2 and 0.3, not the first stage's 9
  CHECK(*v[1] == Approx(1.4));
  CHECK_FALSE(v[2]);            // never reached
}

TEST_CASE("a curve's chi2 divides by the tolerance, the specimens' and the samples' scatter", "[calibration]") {
  calibration::References r;
  calibration::CurveRow c{"line", "", "x", "y", "dense", "triaxial", 4, 0.1, {{0.5, 1.2, 0.2}}};
  r.curves = {c};
  // One sample: its scatter is taken as one specimen's (0.2): var = 0.1^2 + 0.2^2 / 4 + 0.2^2 / 1 = 0.06.
  const auto one = calibration::score(r, samples_of({line_run()}));
  REQUIRE(one.valued);
  CHECK(one.chi2 == Approx(0.2 * 0.2 / 0.06));
  // Three samples with y = 2x, 2x + 0.1, 2x - 0.1: mean 1.0, sd 0.1: var = 0.01 + 0.01 + 0.01 / 3.
  std::vector<validation::TestResult> three{line_run(), line_run(), line_run()};
  for (double& y : three[1].series["y"]) y += 0.1;
  for (double& y : three[2].series["y"]) y -= 0.1;
  const auto m = calibration::score(r, samples_of(three));
  CHECK(m.chi2 == Approx(0.04 / (0.01 + 0.01 + 0.01 / 3)));
  CHECK(m.rows[0].points == 1);
  // A point beyond the run: the set is not scored, and the note says why.
  r.curves[0].points.push_back({2.0, 4.0, 0.2});
  const auto beyond = calibration::score(r, samples_of({line_run()}));
  CHECK_FALSE(beyond.valued);
  CHECK_THAT(beyond.rows[0].note, Catch::Contains("never reaches 2"));
}

TEST_CASE("bad curve files and calibration files name the file, line and key", "[calibration]") {
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("a.csv", "x,y\n1,2\n3,abc\n")); }),
             Catch::Contains("a.csv:3") && Catch::Contains("'abc'"));
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("b.csv", "x,y,sd,z\n")); }),
             Catch::Contains("b.csv:1: column 4 is named 'z'") && Catch::Contains("specimen_1"));
  // Specimens' columns: at least 3 (a correlation from 2 is +-1), each row as many as the header.
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("b2.csv", "x,y,sd,specimen_1,specimen_2\n")); }),
             Catch::Contains("5 columns") && Catch::Contains("at least 3 specimens"));
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("b3.csv", "x,y,sd,specimen_1,specimen_2,specimen_3\n1,2,0.1,1.9,2\n")); }),
             Catch::Contains("b3.csv:2: 5 columns where the header has 6"));
  const auto with = calibration::read_curve_csv(write("b4.csv", "x,y,sd,specimen_1,specimen_2,specimen_3\n1,2,0.1,1.9,2,2.1\n"));
  CHECK(with.front().specimens == std::vector<double>{1.9, 2, 2.1});
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("c.csv", "x,y\n")); }), Catch::Contains("no points"));
  CHECK_THAT(error_of([] { calibration::read_curve_csv(write("d.csv", "x,y,sd\n1,2,-1\n")); }), Catch::Contains("negative"));
  const std::string head = "name: c\nstudy: s.yaml\nreferences: r.yaml\nreport: out\n";
  CHECK_THAT(error_of([&] { calibration::read_calibration(write("e.yaml", head + "parameters: [{name: a, keys: k}]\n")); }),
             Catch::Contains("exactly one prior"));
  CHECK_THAT(error_of([&] { calibration::read_calibration(write("f.yaml", head + "parameters: [{name: a, keys: k, log_uniform: [0, 1]}]\n")); }),
             Catch::Contains("log_uniform") && Catch::Contains("low > 0"));
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("g.yaml", head + "parameters: [{name: a, keys: k, uniform: [0, 1]}, "
                                                                   "{name: b, keys: [j, k], uniform: [0, 1]}]\n"));
             }),
             Catch::Contains("'k' is set by two parameters in the test runs"));
  // The same key in the preparation and in the test: two parameters (the paper's two frictions).
  CHECK(calibration::read_calibration(write("g2.yaml", head + "parameters: [{name: a, keys: k, applies_to: prepare, uniform: [0, 1]}, "
                                                            "{name: b, keys: k, uniform: [0, 1]}]\n")).parameters.size() == 2);
  // The same key in the tests of two densities: two parameters; in all tests and one density's: one key twice.
  const auto by_density = calibration::read_calibration(
      write("g3.yaml", head + "parameters: [{name: a, keys: k, densities: [dense], uniform: [0, 1]}, "
                              "{name: b, keys: k, densities: [medium], uniform: [0, 1]}]\n"));
  CHECK(by_density.parameters[0].densities == std::vector<std::string>{"dense"});
  calibration::ParameterSet set;
  set.u = Eigen::Vector2d(0.5, 0.25);
  const pipeline::Variant v = calibration::variant_of(by_density, set);
  CHECK(v.test.empty());
  CHECK(v.per_density == std::vector<std::pair<std::string, pipeline::Overrides>>{{"dense", {{"k", "0.5"}}}, {"medium", {{"k", "0.25"}}}});
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("g4.yaml", head + "parameters: [{name: a, keys: k, densities: [dense], uniform: [0, 1]}, "
                                                                    "{name: b, keys: k, uniform: [0, 1]}]\n"));
             }),
             Catch::Contains("'k' is set by two parameters in the test runs"));
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("g5.yaml", head + "parameters: [{name: a, keys: k, densities: [dense], applies_to: both, uniform: [0, 1]}]\n"));
             }),
             Catch::Contains("densities") && Catch::Contains("applies_to: test"));
  // Readings: each value a named set of keys; the parameter's keys are all of theirs.
  const auto readings = calibration::read_calibration(
      write("r1.yaml", head + "parameters: [{name: d, readings: [{name: body, set: {t: 0.05, c: 0.0}}, "
                              "{name: dashpots, set: {c: 0.05, t: 0.0}}]}]\n"));
  const calibration::Parameter& d = readings.parameters[0];
  CHECK(d.keys == std::vector<std::string>{"t", "c"});
  CHECK(d.values == std::vector<std::string>{"body", "dashpots"});
  CHECK(d.overrides(0.9) == std::vector<std::pair<std::string, std::string>>{{"c", "0.05"}, {"t", "0.0"}});
  calibration::ParameterSet first;
  first.u = Eigen::VectorXd::Constant(1, 0.1);
  CHECK(calibration::variant_of(readings, first).test == pipeline::Overrides{{"t", "0.05"}, {"c", "0.0"}});
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("r2.yaml", head + "parameters: [{name: d, keys: t, readings: [{name: a, set: {t: 1}}, {name: b, set: {t: 2}}]}]\n"));
             }),
             Catch::Contains("keys: is given beside readings"));
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("r3.yaml", head + "parameters: [{name: d, readings: [{name: a, set: {t: 1}}, {name: b, set: {t: 2}}]}, "
                                                                    "{name: e, keys: t, uniform: [0, 1]}]\n"));
             }),
             Catch::Contains("'t' is set by two parameters"));
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("r4.yaml", head + "parameters: [{name: d, readings: [{name: a, set: {t: 1}}]}]\n"));
             }),
             Catch::Contains("at least 2 readings"));
  CHECK_THAT(error_of([&] {
               calibration::read_calibration(write("r5.yaml", head + "parameters: [{name: d, values: [1, 2], readings: [{name: a, set: {t: 1}}, {name: b, set: {t: 2}}]}]\n"));
             }),
             Catch::Contains("exactly one prior"));
  CHECK_THAT(error_of([&] { calibration::read_calibration(write("h.yaml", head + "parameters: [{name: a, keys: k, values: [1]}]\n")); }),
             Catch::Contains("at least 2 values"));
  CHECK_THAT(error_of([&] { calibration::read_calibration(write("i.yaml", head + "parameters: [{name: a, keys: k, uniform: [0, 1], applies: test}]\n")); }),
             Catch::Contains("applies"));
  const auto ok = calibration::read_calibration(write("j.yaml", head + "batch: 4\nparameters: [{name: a, keys: [k1, k2], applies_to: both, uniform: [0, 2]}]\n"));
  CHECK(ok.batch == 4);
  CHECK(ok.parameters[0].keys == std::vector<std::string>{"k1", "k2"});
  CHECK(ok.parameters[0].applies_to == "both");
}

TEST_CASE("a set is scored on its samples whose runs all finished, when at least two did", "[calibration]") {
  calibration::References refs;
  validation::Row row;
  row.name = "e0, loose", row.quantity = "e0", row.check = "within", row.density = "loose";
  row.reference = 0.73, row.tolerance = 0.02;
  refs.rows.push_back(row);
  const auto sample = [](const std::string& name, std::vector<std::string> missing) {
    validation::Sample s;
    s.name = name;
    s.densities["loose"].missing_runs = std::move(missing);
    return s;
  };
  const std::vector<validation::Sample> two_complete = {sample("seed1", {}), sample("seed2", {}), sample("seed3", {"prepare", "test1"})};
  const calibration::SetMisfit m = calibration::score_complete(refs, two_complete);
  CHECK(m.left_out == std::vector<std::string>{"seed3 (no loose prepare, loose test1)"});
  CHECK(m.rows.size() == 1);
  // One complete sample of three: scored on all, nothing left out (the row then says what is missing).
  const std::vector<validation::Sample> one_complete = {sample("seed1", {}), sample("seed2", {"test2"}), sample("seed3", {"prepare"})};
  CHECK(calibration::score_complete(refs, one_complete).left_out.empty());
  // Every sample complete: nothing left out.
  CHECK(calibration::score_complete(refs, {sample("seed1", {}), sample("seed2", {})}).left_out.empty());
}

TEST_CASE("a curve point no run could be scored against is refused up front, naming the file, the curve and the point", "[calibration]") {
  const auto refs = [](const std::string& csv, const std::string& curve_keys) {
    write("p.csv", csv);
    return error_of([&] {
      calibration::read_references(write("p.yaml", "source: typed\ncurves: [{name: qp, file: p.csv, x: strain_3, y: q_over_p, "
                                                   "density: dense, test: triaxial" + curve_keys + "}]\n"),
                                   "quick");
    });
  };
  // sd 0 at one point, no tolerance: its chi^2 divides by 0 (the whole curve without sd was refused before).
  const std::string zero = refs("x,y,sd\n0.002,0.8,0.1\n0.008,0.9,0\n", "");
  CHECK_THAT(zero, Catch::Contains("p.yaml") && Catch::Contains("curve 'qp'") && Catch::Contains("point 2 of") &&
                       Catch::Contains("p.csv (x = 0.008, y = 0.9, sd = 0) has sd 0"));
  CHECK(refs("x,y,sd\n0.002,0.8,0.1\n0.008,0.9,0\n", ", tolerance: 0.01") == "accepted");  // the tolerance stands for it
  // A row without its sd (the header has 3 columns).
  CHECK_THAT(refs("x,y,sd\n0.002,0.8,0.1\n0.008,0.9\n", ""), Catch::Contains("p.csv:3: 2 columns where the header has 3") &&
                                                                 Catch::Contains("give every point its sd"));
  // y = 1e300 against sd 0.1: (y / sd)^2 = 1e602 overflows, whatever the run gives.
  CHECK_THAT(refs("x,y,sd\n0.002,0.8,0.1\n0.008,1e300,0.1\n", ""), Catch::Contains("point 2 of") && Catch::Contains("would overflow"));
  // sd = 1e-300: its square, 1e-600, is 0 in double precision.
  CHECK_THAT(refs("x,y,sd\n0.002,0.8,1e-300\n", ""), Catch::Contains("point 1 of") && Catch::Contains("underflows to 0 or overflows"));
  CHECK(refs("x,y,sd\n0.002,0.8,1e-100\n", "") == "accepted");  // 1e-200: small, but a number
}

TEST_CASE("a row whose chi2 is not a number has no value", "[calibration]") {
  calibration::References r;
  r.curves = {calibration::CurveRow{"line", "", "x", "y", "dense", "triaxial", 1, 0.1, {{0.5, 1.0, 0.0}}}};
  validation::TestResult run = line_run();
  for (double& y : run.series["y"]) y = NAN;  // a run whose column is not finite
  const calibration::SetMisfit m = calibration::score(r, samples_of({run}));
  CHECK_FALSE(m.valued);
  CHECK_THAT(m.rows[0].note, Catch::Contains("not a number"));
}

TEST_CASE("a curve's columns are the engine's, checked when the references are read (before any run)", "[calibration]") {
  write("col.csv", "x,y,sd\n0.002,0.8,0.1\n");
  const auto refs = [](const std::string& x, const std::string& y) {
    return error_of([&] {
      calibration::read_references(write("col.yaml", "source: typed\ncurves: [{name: qp, file: col.csv, x: " + x + ", y: " + y +
                                                         ", density: dense, test: triaxial}]\n"),
                                   "quick");
    });
  };
  CHECK(refs("strain_3", "q_over_p") == "accepted");
  CHECK_THAT(refs("strain_3", "q_over_P"), Catch::Contains("col.yaml") && Catch::Contains("y") &&
                                                Catch::Contains("'q_over_P' is not a column of the runs' time series") &&
                                                Catch::Contains("q_over_p"));  // the list names the right one
  CHECK_THAT(refs("axial_strain", "q_over_p"), Catch::Contains("'axial_strain' is not a column"));
}

TEST_CASE("a kept misfit is checked against its own values: an edited chi2 is caught", "[calibration]") {
  calibration::References r;
  r.curves = {calibration::CurveRow{"line", "", "x", "y", "dense", "triaxial", 4, 0.1, {{0.5, 1.2, 0.2}, {0.8, 1.5, 0.2}}}};
  calibration::SetMisfit m;
  m.rows = {calibration::score(r, samples_of({line_run(), line_run(), line_run()})).rows[0]};  // the curve alone
  validation::Row row;
  row.name = "trend", row.rule = "majority";
  r.rows = {row};
  calibration::RowMisfit trend{"trend", -2 * std::log((2 + 0.5) / (3 + 1.0)), 1, "", true, {0.4}, {0.1}, 3};  // holds in 2 of 3
  m.rows.push_back(trend);
  m.chi2 = m.rows[0].chi2 + m.rows[1].chi2;
  REQUIRE(m.rows[0].chi2 > 0);
  CHECK(calibration::recheck(r, m).empty());
  calibration::SetMisfit forged = m;
  forged.chi2 = 0;  // the total alone
  CHECK_THAT(calibration::recheck(r, forged), Catch::Contains("is not the sum of its rows'"));
  forged = m;
  forged.rows[0].chi2 = 0, forged.chi2 = forged.rows[1].chi2;  // a curve's chi2 and the total, consistently
  CHECK_THAT(calibration::recheck(r, forged), Catch::Contains("'line': its chi^2 0.000000 is not the"));
  forged = m;
  forged.rows[1].chi2 = 0.1, forged.chi2 = m.rows[0].chi2 + 0.1;  // no whole count of samples gives 0.1
  CHECK_THAT(calibration::recheck(r, forged), Catch::Contains("'trend'") && Catch::Contains("count of samples"));
  forged = m;
  forged.rows[0].name = "other";
  CHECK_THAT(calibration::recheck(r, forged), Catch::Contains("row 1 is 'other'"));
}
