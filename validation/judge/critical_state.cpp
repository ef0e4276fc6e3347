#include "judge/critical_state.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "analysis/fabric.hpp"
#include "study/series.hpp"
#include "study/columns.hpp"

namespace validation {

namespace {

constexpr double degrees = 180 / std::numbers::pi;

}  // namespace

dem::Vec3 principal_stresses(const dem::Mat3& stress_Pa) {
  const dem::Vec3 ascending = Eigen::SelfAdjointEigenSolver<dem::Mat3>(stress_Pa, Eigen::EigenvaluesOnly).eigenvalues();
  return {ascending[2], ascending[1], ascending[0]};
}

double mobilised_friction_deg(const dem::Vec3& s) {
  return s[0] + s[2] > 0 ? std::asin((s[0] - s[2]) / (s[0] + s[2])) * degrees : std::nan("");
}

double intermediate_stress_ratio(const dem::Vec3& s) { return s[0] > s[2] ? (s[1] - s[2]) / (s[0] - s[2]) : std::nan(""); }

PiPoint pi_point(const dem::Vec3& s) {
  const double p = s.sum() / 3;
  if (!(p > 0)) return {};
  const Eigen::Vector2d xy = dem::pi_plane(s) / p;
  // The angle from the s1 axis (0, 1) towards -s3 (-x): s1 >= s2 >= s3 puts the point at x <= 0.
  return {xy.x(), xy.y(), xy.norm(), std::atan2(-xy.x(), xy.y()) * degrees};
}

dem::Vec3 stresses_at(double p, double radius, double lode) {
  const double a = std::sqrt(2.0 / 3.0) * radius, third = 2 * std::numbers::pi / 3;
  return {p + a * std::cos(lode), p + a * std::cos(lode - third), p + a * std::cos(lode - 2 * third)};
}

const char* to_string(Criterion c) {
  switch (c) {
    case Criterion::MohrCoulomb: return "Mohr–Coulomb";
    case Criterion::LadeDuncan: return "Lade–Duncan";
    case Criterion::MatsuokaNakai: return "Matsuoka–Nakai";
  }
  throw std::logic_error("to_string: not a Criterion");
}

double criterion_value(Criterion c, const dem::Vec3& s) {
  const double i1 = s.sum(), i2 = s[0] * s[1] + s[1] * s[2] + s[2] * s[0], i3 = s.prod();
  switch (c) {
    case Criterion::MohrCoulomb: return (s.maxCoeff() - s.minCoeff()) / (s.maxCoeff() + s.minCoeff());
    case Criterion::LadeDuncan: return i1 * i1 * i1 / i3;
    case Criterion::MatsuokaNakai: return i1 * i2 / i3;
  }
  return std::nan("");
}

double criterion_radius(Criterion c, const dem::Vec3& through, double lode) {
  const double p = through.sum() / 3, target = criterion_value(c, through);
  if (!(p > 0) || !std::isfinite(target)) throw std::invalid_argument("criterion_radius: the stress must be compressive, with every principal value > 0");
  // The radius where the smallest principal value reaches 0 (at least one cosine is <= -1/2).
  const dem::Vec3 unit = stresses_at(0, 1, lode);
  double low = 0, high = -p / unit.minCoeff();
  // 200 halvings take the bracket below the last bit of a double; stop there.
  for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
    const double mid = 0.5 * (low + high);
    (criterion_value(c, stresses_at(p, mid, lode)) < target ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double predicted_friction_deg(Criterion c, const dem::Vec3& through, double b) {
  const double lode = std::atan2(std::sqrt(3.0) * b, 2 - b);
  dem::Vec3 s = stresses_at(through.sum() / 3, criterion_radius(c, through, lode), lode);
  std::sort(s.data(), s.data() + 3, std::greater<>());
  return mobilised_friction_deg(s);
}

// The peak is taken on stresses averaged over a centred window of axial strain (smoothing_strain
// wide, 1 % by default: 5 rows at the scene's output every 2,000 steps of 1e-6 s at 1/s): a
// maximum over single rows picks the largest row-to-row fluctuation of a finite sample and so
// sits above the curve; the window removes that while lowering a peak that spans several percent
// of strain little. The largest single-row value is kept (peak_phi_raw_deg) to show the difference:
// in the critical-state study (8,000 spheres) it is 0.06 to 0.59 deg above the smoothed peak.
ShearSummary summarise_shear(const Columns& series, double cs_from, double cs_to, double smoothing_strain) {
  const std::vector<double>& stage = column(series, "stage");
  const std::vector<double>& axial = column(series, "strain_3");
  const std::vector<double>& e = column(series, col::void_ratio);
  const std::vector<double>& cn = column(series, col::coordination_number);
  const std::vector<double>& cnm = column(series, col::coordination_number_mechanical);
  const double last_stage = stage.empty() ? 0 : *std::max_element(stage.begin(), stage.end());
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < stage.size(); ++i)
    if (stage[i] == last_stage) rows.push_back(i);
  ShearSummary out;
  out.rows = rows.size();
  if (rows.empty()) return out;
  std::vector<dem::Vec3> principal;
  for (std::size_t i : rows) principal.push_back(principal_stresses(stress_of({series, i})));
  std::vector<double> phi, e_cs, cn_cs, cnm_cs, qp_cs, p_cs, b_cs;
  dem::Vec3 cs_principal = dem::Vec3::Zero();  // summed over the critical-state rows
  double best = -std::numeric_limits<double>::infinity();
  out.peak_phi_raw_deg = best;
  out.p_min_Pa = std::numeric_limits<double>::infinity(), out.p_max_Pa = -out.p_min_Pa;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double strain = std::abs(axial[rows[k]]);
    out.max_axial_strain = std::max(out.max_axial_strain, strain);
    out.peak_phi_raw_deg = std::max(out.peak_phi_raw_deg, mobilised_friction_deg(principal[k]));
    if (principal[k][2] > 0) out.peak_ratio_raw = std::max(out.peak_ratio_raw, principal[k][0] / principal[k][2]);
    out.p_min_Pa = std::min(out.p_min_Pa, principal[k].sum() / 3), out.p_max_Pa = std::max(out.p_max_Pa, principal[k].sum() / 3);
    dem::Vec3 mean = dem::Vec3::Zero();
    int n = 0;
    for (std::size_t j = 0; j < rows.size(); ++j)
      if (std::abs(std::abs(axial[rows[j]]) - strain) <= smoothing_strain / 2) mean += principal[j], ++n;
    mean /= n;
    if (const double smoothed = mobilised_friction_deg(mean); smoothed > best) {
      best = smoothed;
      out.peak_phi_deg = smoothed, out.peak_axial_strain = strain, out.peak_principal_Pa = mean;
    }
    if (strain >= cs_from && strain <= cs_to) {
      const double f = mobilised_friction_deg(principal[k]);
      phi.push_back(f);
      cs_principal += principal[k];
      e_cs.push_back(e[rows[k]]);
      cn_cs.push_back(cn[rows[k]]);
      cnm_cs.push_back(cnm[rows[k]]);
      qp_cs.push_back(q_over_p(stress_of({series, rows[k]})));  // the engine's q and p of the tensor
      p_cs.push_back(principal[k].sum() / 3);
      b_cs.push_back(intermediate_stress_ratio(principal[k]));
    }
  }
  out.peak_b = intermediate_stress_ratio(out.peak_principal_Pa);
  out.peak_pi = pi_point(out.peak_principal_Pa);
  out.peak_p_Pa = out.peak_principal_Pa.sum() / 3;
  out.cs_rows = phi.size();
  // The critical-state angle is that of the mean principal stresses over the window, as the peak's
  // is of its window's mean: one definition wherever an angle is quoted (the rate series' too); the
  // sd and the interval stay the row-to-row scatter of the single rows' angles, about it.
  out.phi_deg = spread(phi);
  if (!phi.empty()) {
    const double shift = mobilised_friction_deg(cs_principal / static_cast<double>(phi.size())) - out.phi_deg.mean;
    out.phi_deg.mean += shift;
    if (out.phi_deg.low) *out.phi_deg.low += shift, *out.phi_deg.high += shift;
  }
  out.void_ratio = spread(e_cs), out.coordination = spread(cn_cs);
  out.coordination_mechanical = spread(cnm_cs), out.q_over_p = spread(qp_cs), out.p_Pa = spread(p_cs), out.b = spread(b_cs);
  return out;
}

ShearEnsemble shear_ensemble(const std::vector<ShearSummary>& samples) {
  ShearEnsemble out;
  out.samples = static_cast<int>(samples.size());
  std::vector<double> phi, qp, e, cn, peak;
  for (const ShearSummary& s : samples) {
    peak.push_back(s.peak_phi_deg);
    if (s.cs_rows == 0) continue;
    phi.push_back(s.phi_deg.mean), qp.push_back(s.q_over_p.mean), e.push_back(s.void_ratio.mean), cn.push_back(s.coordination.mean);
  }
  out.phi_cs_deg = spread(phi), out.q_over_p_cs = spread(qp), out.void_ratio_cs = spread(e), out.coordination_cs = spread(cn);
  out.peak_phi_deg = spread(peak);
  return out;
}

double inertial_number(double rate_per_s, double diameter_m, double density_kg_per_m3, double p_Pa) {
  return p_Pa > 0 ? std::abs(rate_per_s) * diameter_m * std::sqrt(density_kg_per_m3 / p_Pa) : std::nan("");
}

}  // namespace validation
