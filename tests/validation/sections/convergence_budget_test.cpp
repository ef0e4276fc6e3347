// The convergence study's error budget on values made from known laws: a quantity that depends on
// the time step as c h^2, on the rate as a line, on the size as 1/N. Each factor's error and the
// converged value are worked out by hand from the law; the intervals from the samples' scatter.
// Then compare-runs convergence --summary on a summary.json made from the same laws: the table
// prints the converged value the law gives.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "sections/convergence_budget.hpp"
#include "study/ensemble.hpp"

namespace fs = std::filesystem;
using namespace validation;

TEST_CASE("time step: Richardson's extrapolation recovers a second-order error", "[convergence]") {
  // Q_s(h) = q_s + c_s h^2 with h in us: the error at h0 = 1 is c_s exactly, whatever q_s.
  const std::map<int, double> q = {{1, 0.70}, {2, 0.72}, {3, 0.71}}, c = {{1, 0.010}, {2, 0.012}, {3, 0.011}};
  PerSeed h1, h2, h4;
  for (const auto& [s, qs] : q) {
    h1[s] = qs + c.at(s) * 1.0;
    h2[s] = qs + c.at(s) * 0.25;
    h4[s] = qs + c.at(s) * 0.0625;
  }
  const FactorError f = time_step_error(h1, h2, h4, 2);
  CHECK(f.extrapolated);
  CHECK(f.error.value == Approx(0.011).epsilon(1e-9));  // mean of c_s
  // sd of {0.010, 0.012, 0.011} = 0.001; half-width t(0.975, 2) 0.001 / sqrt(3)
  CHECK(f.error.half_width == Approx(4.302652729 * 0.001 / std::sqrt(3.0)).epsilon(1e-6));
  CHECK(f.how.find("observed 2.0") != std::string::npos);  // (c - c/4) / (c/4 - c/16) = 4 = 2^2
}

TEST_CASE("time step: a sequence that is not monotone is not extrapolated", "[convergence]") {
  const FactorError f = time_step_error({{1, 1.00}, {2, 2.00}}, {{1, 1.10}, {2, 2.10}}, {{1, 1.02}, {2, 2.02}}, 2);
  CHECK_FALSE(f.extrapolated);
  CHECK(f.error.value == Approx(-0.02));  // Q(h0) - Q(h0/4)
  CHECK(f.how.find("not monotone") != std::string::npos);
  // A sample missing from one step is left out; none left: no estimate.
  CHECK(std::isnan(time_step_error({{1, 1.0}}, {{2, 1.0}}, {{1, 1.0}}).error.value));
}

TEST_CASE("rate: the line to rate 0 over the paper's rate and slower ones", "[convergence]") {
  // Q_s(r) = a_s + b r over r <= 2 MPa/s; the value at 4 MPa/s is off the line and must not count.
  const double b = 0.05;
  std::map<double, PerSeed> by_rate;
  for (double r : {0.5, 1.0, 2.0})
    for (int s : {1, 2, 3}) by_rate[r][s] = 0.3 + 0.01 * s + b * r;
  for (int s : {1, 2, 3}) by_rate[4.0][s] = 9.9;
  const FactorError f = rate_error(by_rate, 2.0);
  CHECK(f.error.value == Approx(b * 2.0).epsilon(1e-9));
  // Every sample gives the same error (sd 0): the half-width is the distance to the same
  // extrapolation in sqrt(r), worked out here by least squares on (sqrt r, Q).
  const double x[3] = {std::sqrt(0.5), 1.0, std::sqrt(2.0)}, y[3] = {b * 0.5, b * 1.0, b * 2.0};
  const double mx = (x[0] + x[1] + x[2]) / 3, my = (y[0] + y[1] + y[2]) / 3;
  double sxy = 0, sxx = 0;
  for (int k = 0; k < 3; ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  const double intercept = my - sxy / sxx * mx;
  CHECK(f.error.half_width == Approx(std::abs((b * 2.0 - intercept) - b * 2.0)).epsilon(1e-6));
  CHECK(std::isnan(rate_error({{2.0, {{1, 1.0}}}}, 2.0).error.value));  // one rate: no line
}

TEST_CASE("size: two sizes' means taken to 1/N -> 0, the scatter pooled over the sizes", "[convergence]") {
  // Q(N) = Q* + k/N: m0 - m1 = k (1/N0 - 1/N1), and the error at N0 is k/N0 = (m0 - m1) / (1 - N0/N1).
  const FactorError f = size_error({{8000, {{1, 1.0}, {2, 1.1}, {3, 0.9}}}, {27000, {{1, 0.9}, {2, 1.0}, {3, 0.8}}}}, 8000);
  CHECK(f.error.value == Approx(0.1 * 27.0 / 19.0).epsilon(1e-9));
  // Two points: the line passes through both means, so var(error) = (var m0 + var m1) / (1 - N0/N1)^2,
  // var m_i = s^2 (N0/N_i) / n_i, with s^2 pooled at the paper's size: each size's sd is 0.1 on 2 dof,
  // scaled by N_i/N0: s^2 = (0.01 * 2 + 0.01 * 27/8 * 2) / 4; t with the pooled 4 dof.
  const double s2 = (0.02 + 0.02 * 27.0 / 8.0) / 4;
  const double se = std::sqrt(s2 / 3 + s2 * (8.0 / 27.0) / 3) * 27.0 / 19.0;
  CHECK(f.error.half_width == Approx(2.776445105 * se).epsilon(1e-6));
  CHECK(f.across_sizes);
  CHECK(f.how.find("two: the 1/N form assumed") != std::string::npos);
  CHECK(std::isnan(size_error({{8000, {{1, 1.0}}}}, 8000).error.value));                       // one size
  CHECK(std::isnan(size_error({{8000, {{1, 1.0}}}, {27000, {{1, 2.0}}}}, 8000).error.value));  // no scatter to weigh by
}

TEST_CASE("size: four sizes on the 1/N line give its error exactly, and the means about it are tested", "[convergence]") {
  // Q_s(N) = 0.6 + 40/N + o_s, o_s = +-0.01 sqrt(8000/N) (a scatter that shrinks as 1/sqrt(N)):
  // every size's mean is on the line, chi^2 = 0, and the error at 8,000 is 40/8000 = 0.005.
  std::map<long, PerSeed> by_size;
  for (long n : {1000L, 3375L, 8000L, 27000L}) {
    const double o = 0.01 * std::sqrt(8000.0 / n);
    by_size[n] = {{1, 0.6 + 40.0 / n + o}, {2, 0.6 + 40.0 / n - o}};
  }
  const FactorError f = size_error(by_size, 8000);
  CHECK(f.error.value == Approx(0.005).epsilon(1e-9));
  CHECK(f.lack_of_fit == Approx(0).margin(1e-9));
  CHECK(f.sd == Approx(0.01 * std::sqrt(2.0)).epsilon(1e-9));  // each size: two values +-o, sd o sqrt 2, scaled to 8,000
  // One size's mean 0.05 off the line (5 sds of that mean): chi^2/dof > 1, the interval widens by its root.
  std::map<long, PerSeed> kinked = by_size;
  for (auto& [seed, x] : kinked.at(3375)) x += 0.05;
  const FactorError g = size_error(kinked, 8000);
  CHECK(g.lack_of_fit > 1);
  CHECK(g.error.half_width > f.error.half_width);
}

TEST_CASE("paired settings: the difference, its scatter and the pairs' correlation", "[convergence]") {
  // b = a - 0.2 on every sample: the difference 0.2 with no scatter, the pairs perfectly correlated.
  const PerSeed a = {{1, 1.0}, {2, 1.5}, {3, 0.7}}, b = {{1, 0.8}, {2, 1.3}, {3, 0.5}, {4, 9.0}};
  const FactorError f = paired_difference(a, b);
  CHECK(f.error.value == Approx(0.2));
  CHECK(f.error.half_width == Approx(0).margin(1e-12));
  CHECK(f.samples == 3);  // seed 4 has no pair
  CHECK(f.correlation == Approx(1.0));
  // Opposite orders: correlation -1 (computed by hand: x = 1, 2, 3 against y = 3, 2, 1).
  CHECK(paired_correlation({{1, 1}, {2, 2}, {3, 3}}, {{1, 3}, {2, 2}, {3, 1}}) == Approx(-1.0));
  CHECK(std::isnan(paired_correlation({{1, 1}, {2, 2}}, {{1, 3}, {2, 2}})));  // two pairs: no correlation said
}

TEST_CASE("samples needed: the smallest n whose t interval fits the tolerance", "[convergence]") {
  FactorError f;
  f.error = {0.5, 3.0};
  f.samples = 3;
  f.sd = 1.0;
  // t(0.975, 5)/sqrt(6) = 2.5706/2.4495 = 1.049 > 1; t(0.975, 6)/sqrt(7) = 2.4469/2.6458 = 0.925 <= 1.
  CHECK(samples_needed(f, 1.0) == 7);
  CHECK(samples_needed(f, 3.0) == 0);  // today's interval is within
  f.across_sizes = true;
  f.samples = 20;
  CHECK(samples_needed(f, 1.5) == 80);  // 20 (3/1.5)^2
}

TEST_CASE("the converged value: the factors' errors removed, intervals in quadrature", "[convergence]") {
  const FactorError dt{{0.1, 0.04}, "", true}, rate{{-0.2, 0.12}, "", true}, no_interval{{0, std::nan("")}, "", false},
      not_measured{{std::nan(""), std::nan("")}, "", false};
  const Estimate c = converged_value({1.0, 0.03}, {&dt, &rate, &no_interval});
  CHECK(c.value == Approx(1.1));
  CHECK(std::isnan(c.half_width));  // a factor without an interval leaves none
  const Estimate d = converged_value({1.0, 0.03}, {&dt, &rate, &not_measured});
  CHECK(d.half_width == Approx(std::sqrt(0.03 * 0.03 + 0.04 * 0.04 + 0.12 * 0.12)));  // a factor not measured adds nothing
  const Estimate e = relative_error_to({1.05, 0.03}, {1.0, 0.04});
  CHECK(e.value == Approx(0.05));
  CHECK(e.half_width == Approx(0.05));
}

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/compare-runs";

std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("compare-runs convergence --summary: the section from a summary made by known laws", "[convergence][compare-runs]") {
  // e0 of sample s: 0.7 + 0.001 s + 0.01 (dt/1us)^2 + 0.02 (rate/2MPa/s) + 80/N. At the paper's
  // settings (1 us, 2 MPa/s, 8000) the factors' errors are 0.01 (Richardson), 0.02 (line to 0) and
  // 0.01 (80/8000), so the converged value is 0.7 + 0.002 (the seeds' mean offset) = 0.702.
  const fs::path dir = fs::temp_directory_path() / ("convergence_summary_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ostringstream runs;
  const auto add = [&](const std::string& variant, double dt_us, double rate, long n) {
    for (int s = 1; s <= 3; ++s) {
      const double e0 = 0.7 + 0.001 * s + 0.01 * dt_us * dt_us + 0.02 * rate / 2e6 + 80.0 / n;
      runs << (runs.tellp() > 0 ? ",\n" : "") << R"({"variant": ")" << variant << R"(", "density": "loose", "seed": )" << s
           << R"(, "time_step_s": )" << dt_us * 1e-6 << R"(, "rate_Pa_s": )" << rate << R"(, "spheres": )" << n
           << R"(, "core_s": )" << 100 * n / 8000.0 / dt_us * (2e6 / rate) << R"(, "status": "", "engine": "E", "quantities": {"e0": )" << e0 << "}}";
    }
  };
  add("reference", 1, 2e6, 8000);
  add("dt0p5", 0.5, 2e6, 8000);
  add("dt0p25", 0.25, 2e6, 8000);
  add("rate1", 1, 1e6, 8000);
  add("rate0p5", 1, 5e5, 8000);
  add("n27k", 1, 2e6, 27000);
  std::ofstream(dir / "summary.json") << R"({"schema": 1, "results": "r", "engine": "E", "baseline": "B", "date": "D", )"
                                      << R"("threads_per_run": 1, "runs": [)" << runs.str() << "]}";
  const std::string cmd = bin + " convergence --summary " + (dir / "summary.json").string() + " " + dir.string() + " > " +
                          (dir / "log").string() + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string table = read(dir / "table.md");
  INFO(table);
  CHECK(table.find("engine `E`, baseline `B`") != std::string::npos);  // the stamp
  // e0's row: the paper's settings' mean 0.7 + 0.002 + 0.04 (half-width t(0.975, 2) 0.001 / sqrt 3),
  // converged 0.702 (4 significant digits).
  CHECK(table.find("| e0 | 0.742 ± 0.002484 |") != std::string::npos);
  CHECK(table.find("| 0.702 ± ") != std::string::npos);
  // Each factor's error in % of the converged value: 0 (e0 is the prepared sample's: the test's step
  // does not touch it), 0.01/0.702 (these variants change the preparation's and the test's step),
  // 0.02/0.702, 0.01/0.702. The time step's is the same on every sample (half-width 0); the rate's
  // half-width is the distance to the line in sqrt(rate) through the same three points, 0.010607
  // (1.51 %); the size's comes from two sds of 0.001 pooled at 8,000 spheres (s^2 = (2e-6 + 2e-6
  // 27/8) / 4), var = s^2/3 (1 + 8/27), times 27/19 and t(0.975, 4): 0.003836 (0.55 %).
  CHECK(table.find("+0.000 ± 0.000 % | +1.42 ± 0.000 % | +2.85 ± 1.51 % | +1.42 ± 0.55 %") != std::string::npos);
  CHECK(table.find("Richardson, order 2 (observed 2.0)") != std::string::npos);

  // A file that is not a summary: exit 1, the message names the file and the key.
  std::ofstream(dir / "bad.json") << R"({"schema": 1, "results": "r"})";
  const std::string bad = bin + " convergence --summary " + (dir / "bad.json").string() + " " + dir.string() + " > " +
                          (dir / "log").string() + " 2>&1";
  CHECK(std::system(bad.c_str()) != 0);
  const std::string log = read(dir / "log");
  CHECK(log.find("bad.json") != std::string::npos);
  CHECK(log.find("'engine'") != std::string::npos);

  // Without results but with its summary.json: re-drawn from it (the same table), said so, and with
  // --draw its figure drawn by reports/gnuplot/convergence_error_vs_time.gp; --draw naming no folder: exit 2.
  fs::rename(dir / "table.md", dir / "table_from_summary.md");
  const std::string again = bin + " convergence " + (dir / "no_results").string() + " " + dir.string() + " --draw '" + DEM_SOURCE_DIR +
                            "/reports/gnuplot' > " + (dir / "log").string() + " 2>&1";
  const int drawn = std::system(again.c_str());
  INFO(read(dir / "log"));
  CHECK_THAT(read(dir / "log"), Catch::Contains("no results in " + (dir / "no_results").string() + "; the convergence section re-drawn from"));
  CHECK(read(dir / "table.md") == read(dir / "table_from_summary.md"));
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    CHECK(drawn == 0);
    CHECK(fs::file_size(dir / "error_vs_time.png") > 1000);
  }
  const std::string nowhere = bin + " convergence --summary " + (dir / "summary.json").string() + " " + dir.string() + " --draw " +
                              (dir / "no_such_folder").string() + " > " + (dir / "log").string() + " 2>&1";
  CHECK(WEXITSTATUS(std::system(nowhere.c_str())) == 2);
  fs::remove_all(dir);
}

TEST_CASE("compare-runs convergence: the test's step paired on the same samples, the preparation's apart", "[convergence][compare-runs]") {
  // The q/p slope of sample s: 1.4 + 0.01 s + 0.002 (dt_test/1us)^2 + 0.004 (dt_prep/1us), and a
  // preparation at another step is another packing: r_s = +0.001, -0.001, 0 added. The test's step
  // alone (on the reference's samples) shrinks by 4 per halving: Richardson gives 0.002 on every
  // sample (half-width 0, the pairs correlated 1). The preparation's: the same seeds prepared at 1
  // and 0.25 us, sheared at 0.25 us, differ by 0.004 (1 - 0.25) - r_s: 0.003, half-width
  // t(0.975, 2) 0.001 / sqrt 3 = 0.002484. Paper: 1.42 + 0.006; converged: 1.426 - 0.002 - 0.003 = 1.421.
  const fs::path dir = fs::temp_directory_path() / ("convergence_paired_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const double r[4] = {0, 0.001, -0.001, 0};
  std::ostringstream runs;
  runs.precision(17);
  const auto add = [&](const std::string& variant, double dt_test, double dt_prep, bool own_preparation) {
    for (int s = 1; s <= 3; ++s) {
      const double q = 1.4 + 0.01 * s + 0.002 * dt_test * dt_test + 0.004 * dt_prep + (own_preparation ? r[s] : 0);
      runs << (runs.tellp() > 0 ? ",\n" : "") << R"({"variant": ")" << variant << R"(", "density": "dense", "seed": )" << s
           << R"(, "time_step_s": )" << dt_test * 1e-6 << R"(, "preparation_time_step_s": )" << dt_prep * 1e-6
           << R"(, "rate_Pa_s": 2e6, "spheres": 8000, "core_s": 100, "status": "", "engine": "E", "quantities": {"qp_slope": )" << q << "}}";
    }
  };
  add("reference", 1, 1, false);
  add("dt0p5_test", 0.5, 1, false);
  add("dt0p25_test", 0.25, 1, false);
  add("dt0p5", 0.5, 0.5, true);
  add("dt0p25", 0.25, 0.25, true);
  std::ofstream(dir / "summary.json") << R"({"schema": 2, "results": "r", "engine": "E", "baseline": "B", "date": "D", )"
                                      << R"("threads_per_run": 1, "runs": [)" << runs.str() << "]}";
  // The paper study's row on the slope: inconsistent (1.42 against 1 +- 0.25), tolerance 0.25.
  std::ofstream(dir / "validation.json") << R"({"rows": [{"name": "slope, dense", "quantity": "qp_strong_fabric_slope", )"
                                         << R"("density": "dense", "check": "within", "reference": 1.0, "tolerance": 0.25, )"
                                         << R"("verdict": "inconsistent", "mean": 1.42}, )"
                                         // Two planted misses: 0.002, reached even by the near end of the budget (0.002 +
                                         // 0.003 - 0.002484 = 0.002516); 0.004, between the near end and the far end.
                                         << R"({"name": "near", "quantity": "qp_strong_fabric_slope", "density": "dense", "check": "within", )"
                                         << R"("reference": 1.0, "tolerance": 0.25, "verdict": "inconsistent", "mean": 1.252}, )"
                                         << R"({"name": "between", "quantity": "qp_strong_fabric_slope", "density": "dense", "check": "within", )"
                                         << R"("reference": 1.0, "tolerance": 0.25, "verdict": "inconsistent", "mean": 1.254}]})";
  const std::string cmd = bin + " convergence --summary " + (dir / "summary.json").string() + " " + dir.string() + " --validation " +
                          (dir / "validation.json").string() + " > " + (dir / "log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  INFO(read(dir / "log"));
  REQUIRE(rc == 0);
  const std::string table = read(dir / "table.md");
  INFO(table);
  // 0.002 / 1.421 = 0.14 %, 0.003 / 1.421 = 0.21 % +- 0.002484 / 1.421 = 0.17 %; rate and size not run.
  CHECK_THAT(table, Catch::Contains("| q/p slope | 1.426 ± 0.02484 | +0.14 ± 0.000 % | +0.21 ± 0.17 % | — | — |"));
  CHECK_THAT(table, Catch::Contains("Δt of the test: Richardson, order 2 (observed 2.0): q/p slope"));
  CHECK_THAT(table, Catch::Contains("the same seeds prepared at dt0p25_test's and dt0p25's step: finest step: q/p slope"));
  CHECK_THAT(table, Catch::Contains("| q/p slope | 1.00 |"));  // the test's step: the pairs correlated 1
  // The precision table: the widest half-width 0.002484 (the preparation's) within 0.25; the miss,
  // 1.42 - 1.25 = 0.17, beyond the budget's far end 0.002 + 0.003 + 0.002484.
  CHECK_THAT(table, Catch::Contains("| slope, dense | 0.25 | 0.002484 | Δt of the preparation | yes | — |"));
  CHECK_THAT(table, Catch::Contains("| slope, dense | 0.17 | 0.005 (≤ 0.007484) | larger than the budget"));
  CHECK_THAT(table, Catch::Contains("| near | 0.002 | 0.005 (≤ 0.007484) | within the budget even at the near end"));
  CHECK_THAT(table, Catch::Contains("| between | 0.004 | 0.005 (≤ 0.007484) | within the intervals of the settings' errors"));
  fs::remove_all(dir);
}
