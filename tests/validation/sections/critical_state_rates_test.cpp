// compare-runs critical-state with --rates, --references and --ensemble on hand-made results: the
// quasi-static q/p of a rate series is the intercept of its line against sqrt(I), its φ is set beside
// the literature row that reads the same run (judged only on 4 rates of 2 samples or more), and the
// ensemble's compression and extension are told apart by Welch's t. Every expected number is
// computed here from the stresses the files are given.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/compare-runs";
constexpr double p0 = 1e5, radius = 0.002, rho = 2650;  // the files' p, every sphere's radius, the scene's density

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
}

// A finished constant-p shear (the shipped scene with its friction and axial rate set) whose rows
// from |ε3| = 0 to 0.4 all hold q/p = eta at p = p0: compression (σ3 major) or extension (σ3 minor).
void write_shear(const fs::path& file, double mu, double rate, double eta, bool extension) {
  fs::create_directories(file.parent_path());
  std::string scene = read_file(std::string(DEM_SOURCE_DIR) + "/scenes/tests/constant_p_shear.yaml");
  std::ostringstream f, r;
  f << "friction: " << mu << "}";
  r << "{strain_rate: " << (extension ? -rate : rate) << "}";
  replace_once(scene, "friction: 0.5}", f.str());
  replace_once(scene, "{strain_rate: 1.0}", r.str());
  dem::h5::Handle h = dem::h5::create_file(file.string());
  dem::test::mark_complete(h);
  dem::h5::write_text(h, "scene_yaml", scene);
  const double axial = extension ? p0 * (1 - 2 * eta / 3) : p0 * (1 + 2 * eta / 3);
  const double lateral = extension ? p0 * (1 + eta / 3) : p0 * (1 - eta / 3);
  std::vector<double> stage, strain, e, cn, s11, s22, s33, zero;
  for (int i = 0; i <= 40; ++i) {
    stage.push_back(0), strain.push_back((extension ? 0.01 : -0.01) * i), e.push_back(0.6), cn.push_back(4);
    s11.push_back(lateral), s22.push_back(lateral), s33.push_back(axial), zero.push_back(0);
  }
  dem::h5::Handle g = dem::h5::create_group(h, "timeseries");
  dem::h5::write<double>(g, "stage", stage, 1, "1");
  dem::h5::write<double>(g, "strain_3", strain, 1, "1");
  dem::h5::write<double>(g, "void_ratio", e, 1, "1");
  dem::h5::write<double>(g, "coordination_number", cn, 1, "1");
  dem::h5::write<double>(g, "coordination_number_mechanical", cn, 1, "1");
  for (const auto& [name, v] : {std::pair{"stress_11", &s11}, {"stress_22", &s22}, {"stress_33", &s33}, {"stress_12", &zero},
                                {"stress_13", &zero}, {"stress_23", &zero}})
    dem::h5::write<double>(g, name, *v, 1, "Pa");
  dem::h5::Handle p = dem::h5::create_group(dem::h5::create_group(h, "particles"), "all");
  dem::h5::write<double>(p, "radius", std::vector<double>(8, radius), 1, "m");
}

// A study folder: runs.tsv naming each run `dense_<test>` of one seed (seed 0: a study without
// seeds, its results in the folder itself and "-" in the manifest's seed column).
void write_manifest(const fs::path& dir, const std::vector<std::pair<int, std::string>>& runs) {
  fs::create_directories(dir);
  std::ofstream m(dir / "runs.tsv");
  m << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  for (const auto& [seed, test] : runs) {
    const std::string folder = seed ? "seed" + std::to_string(seed) + "/" : "";
    m << "-\tdense\t" << test << "\t" << folder << "dense_" << test << "\t/elsewhere/" << folder << "dense_" << test << ".h5\t" << folder
      << "dense_prepare\t0\tas written\t" << (seed ? std::to_string(seed) : "-") << "\n";
  }
}

// A reference file with the literature row of the frictionless critical angle (5.76 deg) at `tolerance`.
std::string write_references(const fs::path& file, double tolerance) {
  std::ofstream r(file);
  r << "source: \"test\"\nrows:\n  - name: \"critical angle\"\n    quantity: critical_state_friction_angle\n    density: dense\n"
    << "    test: compression_mu0\n    reference: 5.76\n    check: within\n    tolerance: " << tolerance << "\n    resolution: 0.01\n"
    << "    source: \"Peyneau & Roux: the quasi-static limit\"\n    reason: \"a hand-made row\"\n";
  return file.string();
}

// sin φ of a compression at stress ratio η with σ2 = σ3 (the fixture's runs): σ1 = p + 2q/3,
// σ3 = p - q/3, so (σ1 - σ3)/(σ1 + σ3) = 3η/(6 + η).
double compression_sin_phi(double eta) { return 3 * eta / (6 + eta); }

// Ordinary least squares of y on x, worked out here: the intercept and its standard error
// s sqrt(1/n + mean(x)^2 / Sxx), s^2 = SSR / (n - 2).
struct Intercept {
  double value = 0, se = 0;
};
Intercept least_squares_intercept(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0, sxx = 0, sxy = 0, ssr = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  for (std::size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  const double slope = sxy / sxx, intercept = my - slope * mx;
  for (std::size_t i = 0; i < x.size(); ++i) ssr += std::pow(y[i] - intercept - slope * x[i], 2);
  return {intercept, std::sqrt(ssr / (n - 2) * (1 / n + mx * mx / sxx))};
}

double degrees_of_sin(double s) { return std::asin(s) * 180 / std::numbers::pi; }

std::string run(const std::string& args, const fs::path& log) {
  const int rc = std::system((bin + " critical-state " + args + " > " + log.string() + " 2>&1").c_str());
  INFO(read_file(log));
  REQUIRE(rc == 0);
  return read_file(log);
}

}  // namespace

TEST_CASE("compare-runs critical-state: the quasi-static φ beside the literature row, and the ensemble's t", "[critical-state][compare-runs]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_critical_state";
  fs::remove_all(dir);
  // μ = 0 at 1, 0.5 and 0.25 /s: q/p = 0.2 + 4 sqrt(I) exactly, I = rate d sqrt(rho / p), so the
  // q/p fit's intercept is 0.2 with no scatter. φ is fitted as itself: the line through the runs'
  // sin φ (not quite straight in sqrt(I)) taken to I = 0.
  const auto sqrt_i = [](double rate) { return std::sqrt(rate * 2 * radius * std::sqrt(rho / p0)); };
  const auto eta_at = [&](double rate) { return 0.2 + 4 * sqrt_i(rate); };
  write_manifest(dir / "main", {{0, "compression_mu0"}});
  write_shear(dir / "main" / "dense_compression_mu0.h5", 0, 1, eta_at(1), false);
  write_manifest(dir / "rates", {{0, "rate0.5_mu0"}, {0, "rate0.25_mu0"}});
  write_shear(dir / "rates" / "dense_rate0.5_mu0.h5", 0, 0.5, eta_at(0.5), false);
  write_shear(dir / "rates" / "dense_rate0.25_mu0.h5", 0, 0.25, eta_at(0.25), false);
  // The ensemble at μ = 0.5: three samples in compression (q/p 0.74, 0.75, 0.76) and extension
  // (0.62, 0.64, 0.63): each sample's critical φ from its principal stresses, sin φ = (σ1 - σ3)/(σ1 + σ3).
  const double comp[] = {0.74, 0.75, 0.76}, ext[] = {0.62, 0.64, 0.63};
  write_manifest(dir / "ensemble", {{1, "compression_mu0.5"}, {2, "compression_mu0.5"}, {3, "compression_mu0.5"}, {1, "extension_mu0.5"},
                                    {2, "extension_mu0.5"}, {3, "extension_mu0.5"}});
  for (int s = 0; s < 3; ++s) {
    const fs::path seed = dir / "ensemble" / ("seed" + std::to_string(s + 1));
    write_shear(seed / "dense_compression_mu0.5.h5", 0.5, 1, comp[s], false);
    write_shear(seed / "dense_extension_mu0.5.h5", 0.5, 1, ext[s], true);
  }
  // The literature row of the frictionless critical angle, at two tolerances.
  const auto references = [&](const std::string& name, double tolerance) { return write_references(dir / name, tolerance); };
  const std::string wide = references("wide.yaml", 1.0), narrow = references("narrow.yaml", 0.1);

  std::vector<double> x, sin_phi;
  for (const double rate : {1.0, 0.5, 0.25}) x.push_back(sqrt_i(rate)), sin_phi.push_back(compression_sin_phi(eta_at(rate)));
  const double phi_qs = degrees_of_sin(least_squares_intercept(x, sin_phi).value);
  REQUIRE(std::abs(phi_qs - degrees_of_sin(compression_sin_phi(0.2))) < 0.05);  // near asin(0.6 / 6.2) = 5.55°, not it
  std::ostringstream off, at_rate;
  off << std::fixed;
  off.precision(2);
  off << phi_qs - 5.76;
  at_rate << std::fixed;
  at_rate.precision(2);
  at_rate << "+" << degrees_of_sin(compression_sin_phi(eta_at(1))) - 5.76;

  run((dir / "main").string() + " " + (dir / "out").string() + " --rates " + (dir / "rates").string() + " --references " + wide + " --ensemble " +
          (dir / "ensemble").string(),
      dir / "log1.txt");
  const std::string table = read_file(dir / "out" / "table.md");
  INFO(table);
  // rates_qs.dat: label, μ, the intercept (q/p at I -> 0), its se, φ, ... (exactly collinear: se ~ 0).
  std::istringstream qs(read_file(dir / "out" / "rates_qs.dat"));
  std::string line, label;
  double mu = -1, intercept = 0, se = 1, phi = 0;
  while (std::getline(qs, line))
    if (!line.empty() && line[0] != '#') std::istringstream(line) >> label >> mu >> intercept >> se >> phi;
  CHECK(label == "\"mu0\"");
  CHECK(intercept == Approx(0.2).margin(1e-12));
  CHECK(se < 1e-12);
  CHECK(phi == Approx(phi_qs).margin(1e-9));
  // Three rates of one sample each: too few to judge a quasi-static reference; the distance is given.
  CHECK(table.find("gives 5.76° with a reading tolerance of 1°. ⚠ Not judged at I → 0: the fit has 3 rates of 1 sample each") !=
        std::string::npos);
  CHECK(table.find("For information only: the quasi-static φ is " + off.str() + "° from it") != std::string::npos);
  CHECK(table.find("the 1 s⁻¹ run's is " + at_rate.str() + "°") != std::string::npos);

  // Welch's t of extension - compression from the samples' critical φ.
  const auto phi_of = [](double s1, double s3) { return std::asin((s1 - s3) / (s1 + s3)) * 180 / std::numbers::pi; };
  double mc = 0, me = 0, vc = 0, ve = 0;
  std::vector<double> pc, pe;
  for (int s = 0; s < 3; ++s) {
    pc.push_back(phi_of(p0 * (1 + 2 * comp[s] / 3), p0 * (1 - comp[s] / 3)));
    pe.push_back(phi_of(p0 * (1 + ext[s] / 3), p0 * (1 - 2 * ext[s] / 3)));
    mc += pc.back() / 3, me += pe.back() / 3;
  }
  for (int s = 0; s < 3; ++s) vc += (pc[s] - mc) * (pc[s] - mc) / 2, ve += (pe[s] - me) * (pe[s] - me) / 2;
  std::ostringstream t;
  t << std::fixed;
  t.precision(1);
  t << "t = " << (me - mc) / std::sqrt(vc / 3 + ve / 3) << " against t(0.975, 2) = 4.30";
  CHECK(table.find(t.str()) != std::string::npos);

  // A tolerance of 0.1° changes nothing: still not judged.
  run((dir / "main").string() + " " + (dir / "out2").string() + " --rates " + (dir / "rates").string() + " --references " + narrow,
      dir / "log2.txt");
  CHECK(read_file(dir / "out2" / "table.md").find("Not judged at I → 0") != std::string::npos);
}

TEST_CASE("compare-runs critical-state: a quasi-static row judged at I to 0 on 4 rates of 2 or more samples", "[critical-state][compare-runs]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "compare_runs_critical_state_judged";
  fs::remove_all(dir);
  // μ = 0: the main study's one run at 1/s on the line q/p = 0.2 + 4 sqrt(I); the rates study's two
  // samples at each of 1, 0.5, 0.25 and 0.125/s at the line ± delta. φ is judged on the line
  // through the 9 runs' sin φ (7 degrees of freedom), worked out below from the points alone.
  constexpr double delta = 0.001;
  const auto sqrt_i = [](double rate) { return std::sqrt(rate * 2 * radius * std::sqrt(rho / p0)); };
  const auto eta_at = [&](double rate) { return 0.2 + 4 * sqrt_i(rate); };
  std::vector<double> x{sqrt_i(1)}, y{compression_sin_phi(eta_at(1))};
  write_manifest(dir / "main", {{0, "compression_mu0"}});
  write_shear(dir / "main" / "dense_compression_mu0.h5", 0, 1, eta_at(1), false);
  std::vector<std::pair<int, std::string>> rate_runs;
  for (const double rate : {1.0, 0.5, 0.25, 0.125})
    for (int seed = 1; seed <= 2; ++seed) {
      std::ostringstream name;
      name << "rate" << rate << "_mu0";
      rate_runs.push_back({seed, name.str()});
      const double eta = eta_at(rate) + (seed == 1 ? delta : -delta);
      write_shear(dir / "rates" / ("seed" + std::to_string(seed)) / ("dense_" + name.str() + ".h5"), 0, rate, eta, false);
      x.push_back(sqrt_i(rate)), y.push_back(compression_sin_phi(eta));
    }
  write_manifest(dir / "rates", rate_runs);
  // φ = asin(intercept of sin φ): dφ = d(sin φ) / cos φ, in degrees; t(0.975, 7) = 2.3646.
  const Intercept fit = least_squares_intercept(x, y);
  const double phi_qs = degrees_of_sin(fit.value);
  const double half = 2.3646 * fit.se / std::sqrt(1 - fit.value * fit.value) * 180 / std::numbers::pi;
  std::ostringstream half_text;
  half_text << std::fixed;
  half_text.precision(2);
  half_text << "95 % interval ± " << half << "°";
  const auto references = [&](const std::string& name, double tolerance) { return write_references(dir / name, tolerance); };
  // |φ - 5.76| = 0.21°: within 1° (consistent); beyond 0.1° plus the interval's half-width (inconsistent).
  REQUIRE(std::abs(phi_qs - 5.76) < 1);
  REQUIRE(std::abs(phi_qs - 5.76) > 0.1 + half);
  run((dir / "main").string() + " " + (dir / "out").string() + " --rates " + (dir / "rates").string() + " --references " +
          references("wide.yaml", 1.0),
      dir / "log1.txt");
  const std::string wide = read_file(dir / "out" / "table.md");
  INFO(wide);
  CHECK(wide.find("Judged at I → 0 on 4 rates of 2–3 samples each") != std::string::npos);
  CHECK(wide.find(half_text.str()) != std::string::npos);
  CHECK(wide.find("✅ consistent: the interval reaches the reference's region") != std::string::npos);
  run((dir / "main").string() + " " + (dir / "out2").string() + " --rates " + (dir / "rates").string() + " --references " +
          references("narrow.yaml", 0.1),
      dir / "log2.txt");
  CHECK(read_file(dir / "out2" / "table.md").find("❌ inconsistent: the interval does not reach") != std::string::npos);
}
