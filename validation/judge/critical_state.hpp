#pragma once
// The critical-state section (compare-runs critical-state): what a drained shear at constant mean
// stress (scenes/tests/constant_p_shear.yaml) gives, the mobilised friction angle at its peak and
// at the critical state, and the failure criteria its peaks are set beside in the pi-plane.
// Compression positive throughout; principal stresses are sorted largest first (s1 >= s2 >= s3).
#include <string>
#include <vector>

#include "core/types.hpp"
#include "study/ensemble.hpp"
#include "study/results.hpp"

namespace validation {

// The principal stresses of a (symmetric) stress tensor, largest first [Pa].
dem::Vec3 principal_stresses(const dem::Mat3& stress_Pa);

// Mobilised friction angle [deg] of principal stresses (largest first): sin phi = (s1 - s3)/(s1 + s3).
double mobilised_friction_deg(const dem::Vec3& principal_Pa);

// Intermediate principal stress ratio b = (s2 - s3)/(s1 - s3); NaN for an isotropic stress.
double intermediate_stress_ratio(const dem::Vec3& principal_Pa);

// A stress in the pi-plane of its principal values, normalised by p: s1 up, s2 lower left, s3
// lower right (the engine's dem::pi_plane, as in the report's other pi-plane figures). radius is
// the deviatoric radius |s|/p = sqrt(2 J2)/p = sqrt(2/3) q/p; lode_deg the angle from the s1 axis
// towards -s3, tan(lode) = sqrt(3) b / (2 - b): 0 in triaxial compression (b = 0), 60 in
// triaxial extension (b = 1).
struct PiPoint {
  double x = 0, y = 0, radius = 0, lode_deg = 0;
};
PiPoint pi_point(const dem::Vec3& principal_Pa);

// The three principal values (axes 1, 2, 3 of the pi-plane, not sorted) at mean stress p,
// deviatoric radius `radius` [Pa] and angle `lode_rad` from axis 1 (towards -axis 3):
// s_k = p + sqrt(2/3) radius cos(lode - 2 pi (k - 1) / 3).
dem::Vec3 stresses_at(double p_Pa, double radius_Pa, double lode_rad);

// Isotropic failure criteria, each a function of the principal stresses held constant on its surface.
enum class Criterion {
  MohrCoulomb,    // sin phi = (s_max - s_min)/(s_max + s_min)
  LadeDuncan,     // I1^3 / I3 (Lade & Duncan 1975)
  MatsuokaNakai,  // I1 I2 / I3 (Matsuoka & Nakai 1974)
};
const char* to_string(Criterion c);
double criterion_value(Criterion c, const dem::Vec3& stresses_Pa);

// The deviatoric radius [Pa] at which criterion `c` through the stress `through` is met at the
// angle `lode_rad`, at the mean stress of `through`: found by bisection on the radius between 0
// (hydrostatic: every criterion at its least) and the radius where the smallest principal stress
// reaches 0 (each criterion grows without bound, or to sin phi = 1, towards it). Each of the three
// grows monotonically along a ray from the hydrostatic axis, so the root is unique.
double criterion_radius(Criterion c, const dem::Vec3& through_Pa, double lode_rad);

// The friction angle [deg] criterion `c` through `through` predicts at intermediate stress ratio b
// (at the same p): the mobilised friction angle of the point its surface reaches at that b.
double predicted_friction_deg(Criterion c, const dem::Vec3& through_Pa, double b);

// What one constant-p shear gives.
struct ShearSummary {
  std::size_t rows = 0;            // rows of the shear stage
  double max_axial_strain = 0;     // largest |strain_3| reached
  // The peak: the row where the smoothed mobilised friction angle is largest (see .cpp).
  double peak_phi_deg = 0, peak_phi_raw_deg = 0, peak_axial_strain = 0;
  double peak_ratio_raw = 0;  // the largest sigma_1 / sigma_3 of any row, unsmoothed
  dem::Vec3 peak_principal_Pa = dem::Vec3::Zero();  // smoothed, at the peak
  double peak_b = 0;
  PiPoint peak_pi;
  double peak_p_Pa = 0;              // the smoothed mean stress at the peak
  double p_min_Pa = 0, p_max_Pa = 0;  // over every row of the shear: how well p was held
  // The critical state: over the rows with cs_from <= |strain_3| <= cs_to. The sd is the
  // row-to-row scatter about the mean (the rows are correlated: it is not the error of the mean).
  // phi_deg's mean is the mobilised angle of the rows' mean principal stresses (not the mean of
  // the rows' angles, which a row-to-row scatter raises), its sd the scatter of the rows' angles.
  std::size_t cs_rows = 0;
  Spread phi_deg, void_ratio, coordination, coordination_mechanical, q_over_p, p_Pa, b;
};

// A shear's summary from its time series (the rows of its last stage). `smoothing_strain` is the
// width of the window of axial strain over which the peak's stresses are averaged.
ShearSummary summarise_shear(const Columns& series, double cs_from = 0.3, double cs_to = 0.4, double smoothing_strain = 0.01);

// The mean and the sample sd over an ensemble's samples of what a shear's critical state and peak
// give (each sample's critical state its window mean): compare-runs critical-state --ensemble.
// Samples whose critical state has no row are left out of every quantity but peak_phi_deg.
struct ShearEnsemble {
  int samples = 0;
  Spread phi_cs_deg, q_over_p_cs, void_ratio_cs, coordination_cs, peak_phi_deg;
};
ShearEnsemble shear_ensemble(const std::vector<ShearSummary>& samples);

// The inertial number of a shear at strain rate `rate_per_s` of grains of mean diameter
// `diameter_m` and particle density `density_kg_per_m3` under mean stress p (GDR MiDi 2004):
// I = rate d sqrt(rho / p). NaN for p <= 0.
double inertial_number(double rate_per_s, double diameter_m, double density_kg_per_m3, double p_Pa);

}  // namespace validation
