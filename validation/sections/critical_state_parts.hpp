#pragma once
// The runs of the critical-state studies as compare-runs critical-state reads them, and the parts
// of its section that other studies feed: the ensemble (--ensemble, critical_state_ensemble.cpp)
// and the rates taken to I -> 0 (--rates, critical_state_rates.cpp). The main table and the
// pi-plane are critical_state_section.cpp's.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "judge/critical_state.hpp"
#include "judge/rows.hpp"
#include "sections/study_folder.hpp"
#include "study/ensemble.hpp"
#include "study/line_fit.hpp"
#include "study/section_doc.hpp"
#include "study/series.hpp"

namespace sections {

// One run of the critical-state study, as its name says: compression_mu<μ>, extension_mu<μ>, b<b>
// (or the rates study's rate<rate>_mu<μ>, a compression).
struct ShearRun {
  std::string run, loading;  // loading: compression, extension or "b series" (true triaxial)
  double mu = NAN, b = NAN;  // μ; b the target of the constraint (principal b: 1 in extension)
  double p_target_Pa = NAN;  // the constraint's mean stress
  double rate_per_s = NAN;   // |axial strain rate| of the leading component (the resolved scene's)
  double diameter_m = NAN;   // mean diameter of the run's spheres
  double density_kg_per_m3 = NAN;  // particle density (the resolved scene's)
  std::optional<validation::ShearSummary> summary;
  bool held = true;          // p and b as the name says (see held_as_named)
  std::string note;          // why it has no values, or what to know of them
};

// One (loading, μ) of the ensemble study: its samples' runs.
struct EnsembleGroup {
  std::string loading;
  double mu = NAN;
  std::vector<const ShearRun*> runs;  // every sample's run, finished or not
  std::vector<validation::ShearSummary> used;  // the finished ones that held their p and b
  validation::ShearEnsemble stats;
};

struct RatePoint {
  const ShearRun* run;
  std::string study;  // which folder it came from
  double inertial = NAN;
};

struct RateSeries {
  double mu = NAN;
  std::vector<RatePoint> points;  // fastest first
  std::optional<validation::LineFit> fit;  // q/p against sqrt(I)
  // The quasi-static φ, from the same line through sin φ (of the rows' mean principal stresses, the
  // tables' φ) at I = 0, and its se to first order.
  double phi_deg = NAN, phi_se_deg = NAN;
  std::string problems;           // why the fit is poor, or why there is none
};

// "mean ± sd" of a spread; "—" without rows.
std::string mean_sd(const validation::Spread& s, int digits);

// The critical-state analysis of the runs of a study's manifest (its folder `results`); cs_to the
// axial strain the critical state is averaged up to (a run that stops short of it is noted).
std::vector<ShearRun> shear_runs(const Manifest& manifest, const std::string& results, double cs_to);

std::vector<EnsembleGroup> ensemble_groups(const std::vector<ShearRun>& runs);

validation::Table ensemble_data(const std::vector<EnsembleGroup>& groups);

// The ensemble's part of the section (its heading one level below the section's).
validation::SectionDoc ensemble_section(const std::vector<EnsembleGroup>& groups, const std::vector<ShearRun>& main_runs, const std::string& folder,
                                        std::size_t samples, double cs_from, double cs_to);

// Every μ of the rates study's compression runs, with the main study's compression run at that μ.
std::vector<RateSeries> rate_series(const std::vector<ShearRun>& rates, const std::vector<ShearRun>& main_runs, const std::string& rates_name,
                                    const std::string& main_name);

validation::Table rates_data(const std::vector<RateSeries>& series);

validation::Table rates_quasi_static_data(const std::vector<RateSeries>& series);

// The rates study's part of the section (its heading one level below the section's), with its figure.
validation::SectionDoc rates_section(const std::vector<RateSeries>& series, const std::string& folder, const std::vector<validation::Row>& rows);

}  // namespace sections
