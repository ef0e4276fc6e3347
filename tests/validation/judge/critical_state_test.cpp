// The critical-state section's computations (validation/judge/critical_state.hpp) against analytic
// expectations: the friction angle, b and pi-plane point of a rotated tensor; the three failure
// criteria's radii in compression and extension; the peak and critical state of a synthetic shear.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/time_series.hpp"
#include "judge/critical_state.hpp"
#include "study/format.hpp"

using validation::Criterion;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180;

// A tensor with principal values (s1, s2, s3) along axes turned away from x, y, z, so that every
// shear component is non-zero: the principal values must come from the whole tensor.
dem::Mat3 rotated(const dem::Vec3& principal) {
  const dem::Mat3 r = (Eigen::AngleAxisd(0.4, dem::Vec3::UnitZ()) * Eigen::AngleAxisd(-0.7, dem::Vec3::UnitX()) *
                       Eigen::AngleAxisd(1.1, dem::Vec3::UnitY())).toRotationMatrix();
  return r * principal.asDiagonal() * r.transpose();
}

}  // namespace

TEST_CASE("friction angle, b and pi-plane point of a rotated stress tensor", "[critical-state][report-sections]") {
  // Principal 300, 200, 100 kPa: sin phi = 200/400 = 1/2, phi = 30 deg; b = 100/200 = 1/2;
  // p = 200 kPa, deviator (100, 0, -100) kPa, |s| = 100 sqrt(2) kPa, so radius = sqrt(2)/2;
  // tan(lode) = sqrt(3) b / (2 - b) = 1/sqrt(3): 30 deg, half-way from compression to extension.
  const dem::Mat3 s = rotated({3e5, 2e5, 1e5});
  REQUIRE(std::abs(s(0, 1)) > 1e4);  // the shear components are not small: the eigenvalues matter
  const dem::Vec3 principal = validation::principal_stresses(s);
  CHECK(principal[0] == Approx(3e5).epsilon(1e-12));
  CHECK(principal[1] == Approx(2e5).epsilon(1e-12));
  CHECK(principal[2] == Approx(1e5).epsilon(1e-12));
  CHECK(validation::mobilised_friction_deg(principal) == Approx(30).epsilon(1e-12));
  CHECK(validation::intermediate_stress_ratio(principal) == Approx(0.5).epsilon(1e-12));
  const validation::PiPoint q = validation::pi_point(principal);
  CHECK(q.radius == Approx(std::sqrt(2.0) / 2).epsilon(1e-12));
  CHECK(q.lode_deg == Approx(30).epsilon(1e-12));
  // Triaxial compression (b = 0) lies on the s1 axis, extension (b = 1) 60 deg from it.
  CHECK(validation::pi_point({3e5, 1e5, 1e5}).lode_deg == Approx(0).margin(1e-12));
  CHECK(validation::pi_point({3e5, 3e5, 1e5}).lode_deg == Approx(60).epsilon(1e-12));
  CHECK(std::isnan(validation::intermediate_stress_ratio({1e5, 1e5, 1e5})));
}

TEST_CASE("Mohr-Coulomb, Lade-Duncan and Matsuoka-Nakai through a compression point", "[critical-state][report-sections]") {
  // Through triaxial compression at phi = 30 deg: s1/s3 = (1 + sin)/(1 - sin) = 3, s = (300, 100,
  // 100) kPa, p = 500/3 kPa.
  const dem::Vec3 through{3e5, 1e5, 1e5};
  const double p = through.sum() / 3, sin_phi = 0.5;
  // Mohr-Coulomb in q/p: M_c = 6 sin/(3 - sin) in compression, M_e = 6 sin/(3 + sin) in
  // extension; the deviatoric radius is sqrt(2/3) q.
  const double rho_c = std::sqrt(2.0 / 3.0) * 6 * sin_phi / (3 - sin_phi) * p;
  const double rho_e = std::sqrt(2.0 / 3.0) * 6 * sin_phi / (3 + sin_phi) * p;
  // The bisection stops at a bracket of 1e-15 relative.
  for (Criterion c : {Criterion::MohrCoulomb, Criterion::LadeDuncan, Criterion::MatsuokaNakai}) {
    INFO(validation::to_string(c));
    CHECK(validation::criterion_radius(c, through, 0) == Approx(rho_c).epsilon(1e-12));  // all meet at the point itself
    // The surfaces have the pi-plane's threefold symmetry: 120 deg on is compression again.
    CHECK(validation::criterion_radius(c, through, 120 * deg) == Approx(rho_c).epsilon(1e-12));
    CHECK(validation::predicted_friction_deg(c, through, 0) == Approx(30).epsilon(1e-12));
  }
  CHECK(validation::criterion_radius(Criterion::MohrCoulomb, through, 60 * deg) == Approx(rho_e).epsilon(1e-12));
  // Matsuoka-Nakai: I1 I2 / I3 of (R, 1, 1) and of (R, R, 1) is the same, (R + 2)(2R + 1)/R, so
  // it has the same friction angle in extension: the Mohr-Coulomb corner.
  CHECK(validation::criterion_radius(Criterion::MatsuokaNakai, through, 60 * deg) == Approx(rho_e).epsilon(1e-12));
  CHECK(validation::predicted_friction_deg(Criterion::MatsuokaNakai, through, 1) == Approx(30).epsilon(1e-12));
  // Lade-Duncan: I1^3/I3 = (R_c + 2)^3 / R_c = 125/3 in compression (R_c = 3); in extension
  // (R, R, 1) it is (2R + 1)^3 / R^2, so R_e solves 24 R^3 - 89 R^2 + 18 R + 3 = 0 (x 3), whose
  // root above 1 is 3.48267582704313 (its others are below 1). sin phi_e = (R_e - 1)/(R_e + 1):
  // phi_e = 33.63 deg, more than in compression. At p the extension state is s3 = 3p/(2 R_e + 1),
  // s1 = s2 = R_e s3, and its radius sqrt(2/3) (R_e - 1) s3.
  const double r_e = 3.48267582704313;
  REQUIRE(std::abs(24 * r_e * r_e * r_e - 89 * r_e * r_e + 18 * r_e + 3) < 1e-11);
  const double s3 = 3 * p / (2 * r_e + 1);
  CHECK(validation::criterion_radius(Criterion::LadeDuncan, through, 60 * deg) == Approx(std::sqrt(2.0 / 3.0) * (r_e - 1) * s3).epsilon(1e-12));
  CHECK(validation::predicted_friction_deg(Criterion::LadeDuncan, through, 1) ==
        Approx(std::asin((r_e - 1) / (r_e + 1)) / deg).epsilon(1e-12));
  // Mohr-Coulomb predicts the same friction angle at every b.
  for (double b : {0.25, 0.5, 0.75, 1.0}) CHECK(validation::predicted_friction_deg(Criterion::MohrCoulomb, through, b) == Approx(30).epsilon(1e-12));
  // Between compression and extension the three are ordered: MC inside, LD outside MN.
  const double mid = 30 * deg;
  CHECK(validation::criterion_radius(Criterion::MohrCoulomb, through, mid) < validation::criterion_radius(Criterion::MatsuokaNakai, through, mid));
  CHECK(validation::criterion_radius(Criterion::MatsuokaNakai, through, mid) < validation::criterion_radius(Criterion::LadeDuncan, through, mid));
}

TEST_CASE("peak and critical state of a synthetic constant-p shear", "[critical-state][report-sections]") {
  // Axial strain 0 ... 0.4 every 0.002 (the scene's output spacing), compression along z at
  // p = 100 kPa: phi 30 deg except a plateau of 40 deg for 0.04 <= e <= 0.06 and a one-row spike
  // of 45 deg at e = 0.15. The smoothing window (1 %: the rows within 0.005) at e = 0.05 lies in
  // the plateau, so the peak is 40 deg there; the spike is the largest single row but, averaged
  // with its 30-deg neighbours, is far below 40. A row of an earlier stage (phi ~ 64 deg) is not
  // part of the shear. Every row of the shear is at p = 100 kPa (the earlier stage's at 900 kPa).
  validation::Columns c;
  for (const dem::SeriesColumn& col : dem::series_columns()) c[col.name] = {};
  const auto add = [&](double stage, double strain, double phi_deg, double e, double cn, double p = 1e5) {
    const double s = std::sin(phi_deg * deg), ratio = (1 + s) / (1 - s), lateral = 3 * p / (ratio + 2);
    for (auto& [name, v] : c) v.push_back(0.0);
    c["stage"].back() = stage;
    c["strain_3"].back() = strain;
    c["stress_11"].back() = lateral, c["stress_22"].back() = lateral, c["stress_33"].back() = ratio * lateral;
    c["void_ratio"].back() = e, c["coordination_number"].back() = cn, c["coordination_number_mechanical"].back() = cn + 0.5;
  };
  add(0, 0.9, 64, 9, 9, 9e5);
  for (int i = 0; i <= 200; ++i) {
    const double strain = 0.002 * i;
    const double phi = i == 75 ? 45 : (i >= 20 && i <= 30) ? 40 : 30;
    // In the critical-state window, e alternates 0.60 -/+ 0.01 and CN 4.0 -/+ 0.1 (51 rows, from -).
    const double sign = i % 2 ? 1 : -1;
    add(1, strain, phi, strain >= 0.3 ? 0.60 + 0.01 * sign : 0.7, strain >= 0.3 ? 4.0 + 0.1 * sign : 5);
  }
  const validation::ShearSummary s = validation::summarise_shear(c);
  CHECK(s.rows == 201);
  CHECK(s.max_axial_strain == Approx(0.4));
  CHECK(s.peak_phi_raw_deg == Approx(45).epsilon(1e-12));
  // The spike's sigma_1 / sigma_3 = (1 + sin 45)/(1 - sin 45) = 3 + 2 sqrt 2, unsmoothed; the
  // earlier stage's 64 deg row is not part of the shear.
  CHECK(s.peak_ratio_raw == Approx(3 + 2 * std::sqrt(2.0)).epsilon(1e-12));
  CHECK(s.peak_phi_deg == Approx(40).epsilon(1e-12));
  // The window (rows i-2 ... i+2) lies in the plateau for 0.044 <= e <= 0.056.
  CHECK(s.peak_axial_strain >= 0.044 - 1e-12);
  CHECK(s.peak_axial_strain <= 0.056 + 1e-12);
  CHECK(s.peak_b == Approx(0).margin(1e-12));
  CHECK(s.peak_pi.lode_deg == Approx(0).margin(1e-9));
  // 0.3 <= e <= 0.4: rows 150 ... 200 (0.002 x 150 and 0.002 x 200 are 0.3 and 0.4 exactly in doubles).
  REQUIRE(s.cs_rows == 51);
  CHECK(s.phi_deg.mean == Approx(30).epsilon(1e-12));
  CHECK(s.phi_deg.sd == Approx(0).margin(1e-9));
  // q/p of phi = 30 deg in compression: 6 sin/(3 - sin) = 1.2.
  CHECK(s.q_over_p.mean == Approx(1.2).epsilon(1e-12));
  CHECK(s.void_ratio.mean == Approx(0.60).margin(0.01 / static_cast<double>(s.cs_rows) + 1e-12));
  CHECK(s.void_ratio.sd == Approx(0.01).epsilon(0.03));  // alternating +-0.01: sd = 0.01 sqrt(n/(n-1))
  CHECK(s.coordination_mechanical.mean - s.coordination.mean == Approx(0.5));
  // p as held: at the peak, over the shear (the earlier stage's row left out) and at the critical state.
  CHECK(s.peak_p_Pa == Approx(1e5).epsilon(1e-12));
  CHECK(s.p_min_Pa == Approx(1e5).epsilon(1e-12));
  CHECK(s.p_max_Pa == Approx(1e5).epsilon(1e-12));
  CHECK(s.p_Pa.mean == Approx(1e5).epsilon(1e-12));
  CHECK(s.b.mean == Approx(0).margin(1e-12));  // compression: s2 = s3
}

TEST_CASE("critical state: the angle is that of the window's mean stresses, with the rows' scatter", "[critical-state][report-sections]") {
  // Compression at p = 100 kPa, the critical-state rows alternating 10 and 50 deg: the mean
  // stresses (sigma_1 and sigma_3 averaged over the rows) give asin((S1 - S3)/(S1 + S3)), computed
  // here from the same stress construction, which is not the mean of the rows' angles.
  const double deg = std::numbers::pi / 180;
  validation::Columns c;
  for (const dem::SeriesColumn& col : dem::series_columns()) c[col.name] = {};
  double s1 = 0, s3 = 0, angles = 0;
  int n = 0;
  for (int i = 0; i <= 200; ++i) {
    const double strain = 0.002 * i, phi = strain >= 0.3 ? (i % 2 ? 50 : 10) : 30, p = 1e5;
    const double s = std::sin(phi * deg), ratio = (1 + s) / (1 - s), lateral = 3 * p / (ratio + 2);
    for (auto& [name, v] : c) v.push_back(0.0);
    c["stage"].back() = 1, c["strain_3"].back() = strain;
    c["stress_11"].back() = lateral, c["stress_22"].back() = lateral, c["stress_33"].back() = ratio * lateral;
    if (strain >= 0.3) s1 += ratio * lateral, s3 += lateral, angles += phi, ++n;
  }
  const validation::ShearSummary s = validation::summarise_shear(c);
  REQUIRE(s.cs_rows == static_cast<std::size_t>(n));
  const double expected = std::asin((s1 - s3) / (s1 + s3)) / deg;
  CHECK(std::abs(expected - angles / n) > 0.2);  // the point of the test: not the rows' mean angle
  CHECK(s.phi_deg.mean == Approx(expected).epsilon(1e-12));
  // The scatter is the rows' (10 and 50 alternating, 26 of one and 25 of the other: sd about 20).
  CHECK(s.phi_deg.sd == Approx(20).epsilon(0.02));
  REQUIRE(s.phi_deg.low.has_value());
  CHECK((*s.phi_deg.low + *s.phi_deg.high) / 2 == Approx(expected).epsilon(1e-12));
}

TEST_CASE("mean ± sd over an ensemble's samples of the critical state", "[critical-state][report-sections]") {
  // Three samples: critical phi 30.1, 30.5, 30.9 (mean 30.5, deviations -0.4, 0, +0.4:
  // sample sd sqrt(0.32 / 2) = 0.4); q/p 0.55, 0.56, 0.60 (mean 0.57, deviations -0.02, -0.01,
  // +0.03: sd sqrt(0.0014 / 2) = 0.0264575...). A fourth sample without critical-state rows (it
  // stopped short) counts for its peak only: peak phi 40, 41, 42, 45 -> mean 42, sd sqrt(14/3).
  std::vector<validation::ShearSummary> s(4);
  const double phi[] = {30.1, 30.5, 30.9}, qp[] = {0.55, 0.56, 0.60}, peak[] = {40, 41, 42, 45};
  for (int k = 0; k < 4; ++k) {
    s[k].peak_phi_deg = peak[k];
    if (k == 3) continue;
    s[k].cs_rows = 51;
    s[k].phi_deg = validation::spread({phi[k] - 1, phi[k] + 1});  // a window mean with its row scatter
    s[k].q_over_p = validation::spread({qp[k]});
    s[k].void_ratio = validation::spread({0.6});
    s[k].coordination = validation::spread({4.0});
  }
  const validation::ShearEnsemble e = validation::shear_ensemble(s);
  CHECK(e.samples == 4);
  CHECK(e.phi_cs_deg.n == 3);
  CHECK(e.phi_cs_deg.mean == Approx(30.5).epsilon(1e-12));
  CHECK(e.phi_cs_deg.sd == Approx(0.4).epsilon(1e-12));  // the samples' sd, not the rows' (1.41 each)
  CHECK(e.q_over_p_cs.sd == Approx(std::sqrt(0.0007)).epsilon(1e-12));
  CHECK(e.void_ratio_cs.sd == Approx(0).margin(1e-15));
  CHECK(e.peak_phi_deg.n == 4);
  CHECK(e.peak_phi_deg.mean == Approx(42).epsilon(1e-12));
  CHECK(e.peak_phi_deg.sd == Approx(std::sqrt(14.0 / 3)).epsilon(1e-12));
  // As the table writes them: the sd to two significant digits, the mean to the same decimal.
  CHECK(validation::mean_pm_sd(e.phi_cs_deg.mean, e.phi_cs_deg.sd) == "30.50 ± 0.40");
  CHECK(validation::mean_pm_sd(e.q_over_p_cs.mean, e.q_over_p_cs.sd) == "0.570 ± 0.026");
  CHECK(validation::mean_pm_sd(e.peak_phi_deg.mean, e.peak_phi_deg.sd) == "42.0 ± 2.2");
}

TEST_CASE("inertial number", "[critical-state][report-sections]") {
  // I = rate d sqrt(rho / p): 4 /s x 2 mm x sqrt(2500 / 1e4) = 0.008 x 0.5 = 0.004.
  CHECK(validation::inertial_number(4, 0.002, 2500, 1e4) == Approx(0.004).epsilon(1e-14));
  CHECK(validation::inertial_number(-4, 0.002, 2500, 1e4) == Approx(0.004).epsilon(1e-14));  // extension: |rate|
  CHECK(std::isnan(validation::inertial_number(1, 0.002, 2500, 0)));
  // An order-of-magnitude check: 1 /s, d about 3.75 mm (the grading's middle), 2650 kg/m3, 100 kPa: ~6e-4.
  CHECK(validation::inertial_number(1, 3.75e-3, 2650, 1e5) == Approx(6.1e-4).epsilon(0.01));
}
