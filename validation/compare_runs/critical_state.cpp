// compare-runs critical-state: the critical-state study (drained shear at constant p of the dense
// sample). Peak and critical-state friction angle, void ratio and coordination number of each
// run, and the peaks in the pi-plane beside Mohr-Coulomb, Lade-Duncan and Matsuoka-Nakai through
// the compression peak. With --ensemble, the mean and sd over samples of the ensemble study's runs
// (pipeline/studies/critical_state_ensemble.yaml); with --rates, the critical q/p of compression
// against the inertial number over the rates study's runs and the main study's own (1/s), fitted
// linearly in sqrt(I) and taken to I -> 0. Writes OUT/table.md, critical_state.dat, pi_plane.dat,
// ensemble.dat, rates.dat, rates_qs.dat and values.gp (what reports/gnuplot/critical_state_*.gp need).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "compare_runs/modes.hpp"
#include "contact/contact_law.hpp"
#include "critical_state.hpp"
#include "figures.hpp"
#include "format.hpp"
#include "io/atomic_file.hpp"
#include "line_fit.hpp"
#include "markdown_table.hpp"
#include "rows.hpp"

namespace fs = std::filesystem;

namespace compare_runs {
namespace {

using validation::cell;
using validation::fixed;
using validation::number;

// A number that is the whole of `s` ("0.25"), or none.
std::optional<double> whole_number(const std::string& s) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
  return x;
}

// "mean ± sd" of a spread; "—" without rows.
std::string mean_sd(const validation::Spread& s, int digits) {
  return s.n == 0 ? "—" : fixed(s.mean, digits) + (s.n > 1 ? " ± " + fixed(s.sd, digits) : "");
}

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

// Whether a shear was the test its name says: p at the peak and at the critical state within 5 %
// of the constraint's, b at the critical state within 0.05 of the target. The consolidation holds
// the stresses within 0.5 %; the constant-p servo, a proportional one, holds p within a few % at
// the critical state (its followers move at a steady rate only on an error), but it can lose p
// altogether when they reach their strain-rate cap (a cap of 1/s: p up to 68 MPa at b = 1). A run
// outside these bounds is kept in the table with its values, and a note that says why they are
// not those of its test. Appends the reasons to r.note.
void held_as_named(ShearRun& r) {
  const validation::ShearSummary& s = *r.summary;
  const auto off = [&](double p) { return std::abs(p / r.p_target_Pa - 1) > 0.05; };
  if (std::isfinite(r.p_target_Pa) && (off(s.peak_p_Pa) || (s.p_Pa.n && off(s.p_Pa.mean)))) {
    r.held = false;
    r.note += "⚠ p not held at " + number(r.p_target_Pa / 1e3) + " kPa: " + fixed(s.peak_p_Pa / 1e3, 1) + " kPa at the peak, " +
              fixed(s.p_Pa.mean / 1e3, 1) + " at the critical state, " + fixed(s.p_min_Pa / 1e3, 1) + " – " + fixed(s.p_max_Pa / 1e3, 1) +
              " over the shear; ";
  }
  if (s.b.n && std::abs(s.b.mean - r.b) > 0.05) {
    r.held = false;
    r.note += "⚠ b not held: " + fixed(s.b.mean, 3) + " at the critical state for " + number(r.b) + "; ";
  }
}

bool parse_shear_test(const std::string& test, ShearRun& r) {
  for (const char* loading : {"compression", "extension"}) {
    const std::string prefix = std::string(loading) + "_mu";
    if (test.rfind(prefix, 0) == 0)
      if (const auto mu = whole_number(test.substr(prefix.size()))) {
        r.loading = loading, r.mu = *mu, r.b = r.loading == "compression" ? 0 : 1;
        return true;
      }
  }
  // The rates study's rate<rate>_mu<μ>: compression at that axial strain rate (the scene's is used).
  if (const auto at = test.find("_mu"); test.rfind("rate", 0) == 0 && at != std::string::npos)
    if (whole_number(test.substr(4, at - 4)))
      if (const auto mu = whole_number(test.substr(at + 3))) {
        r.loading = "compression", r.mu = *mu, r.b = 0;
        return true;
      }
  if (test.rfind("b", 0) == 0)
    if (const auto b = whole_number(test.substr(1))) {
      r.loading = "b series", r.b = *b;
      return true;
    }
  return false;
}

// The critical-state analysis of the runs of a study's manifest (its folder `results`); cs_to the
// axial strain the critical state is averaged up to (a run that stops short of it is noted).
std::vector<ShearRun> shear_runs(const Manifest& manifest, const std::string& results, double cs_to) {
  std::vector<ShearRun> runs;
  for (const ManifestLine& l : manifest.lines) {
    if (l.test == "-") continue;  // the preparation
    ShearRun& r = runs.emplace_back();
    r.run = l.run;
    if (!parse_shear_test(l.test, r)) {
      r.note = "not analysed: test '" + l.test + "' is none of compression_mu<μ>, extension_mu<μ>, b<b>, rate<rate>_mu<μ>";
      continue;
    }
    const std::string result = validation::result_under(results, l);  // wherever the folder is now
    if (!validation::is_complete(result)) {
      r.note = "missing: " + fs::path(result).filename().string() + " is not finished";
      continue;
    }
    try {
      const RunFile f = read_run(result);
      if (!f.radius_m.empty()) {
        double sum = 0;
        for (double radius : f.radius_m) sum += 2 * radius;
        r.diameter_m = sum / static_cast<double>(f.radius_m.size());  // the engine's mean_diameter
      }
      r.summary = validation::summarise_shear(f.series, 0.3, cs_to);
      if (f.scene) {  // μ, p and b as run: the scene's; a name that says otherwise is noted
        const double mu = dem::friction_coefficient(f.scene->material.law);
        if (std::isfinite(r.mu) && std::abs(mu - r.mu) > 1e-9) r.note += "the scene's friction is " + number(mu) + ", not the name's; ";
        r.mu = mu;
        r.density_kg_per_m3 = f.scene->material.density_kg_per_m3;
        r.rate_per_s = std::abs(f.scene->stages.back().control.component[2].strain_rate_per_s);
        const dem::CellConstraint& c = f.scene->stages.back().control.constraint;
        if (c.kind == dem::CellConstraint::Kind::ConstantMeanStress) r.p_target_Pa = c.mean_stress_Pa;
        if (r.loading == "b series" && c.b != r.b) r.note += "the scene's b is " + number(c.b) + ", not the name's; ";
      }
      held_as_named(r);
      if (r.summary->max_axial_strain < cs_to) {
        const std::string why = f.scene && f.stage_end.count(f.scene->stages.back().name) ? f.stage_end.at(f.scene->stages.back().name) : "no stage_end";
        r.note += "reached |ε3| = " + fixed(r.summary->max_axial_strain, 3) + " only (" + why + "); critical state over " +
                  std::to_string(r.summary->cs_rows) + " rows; ";
      }
    } catch (const std::exception& e) {
      r.summary.reset();
      r.note = "unreadable: " + std::string(e.what());
    }
  }
  return runs;
}

// The run the pi-plane's surfaces go through: the b series' b = 0 (its μ), else the compression
// run of the b series' μ (the study's b0 is a copy of compression_mu0.5).
const ShearRun* compression_peak(const std::vector<ShearRun>& runs) {
  double mu = NAN;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" && std::isfinite(r.mu)) mu = r.mu;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" && r.b == 0 && r.summary) return &r;
  for (const ShearRun& r : runs)
    if (r.loading == "compression" && r.summary && r.mu == mu) return &r;
  return nullptr;
}

// The pi-plane runs: the b series and the extension run at the b series' μ.
std::vector<const ShearRun*> pi_plane_runs(const std::vector<ShearRun>& runs, const ShearRun* through) {
  std::vector<const ShearRun*> out;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" || (through && r.loading == "extension" && r.mu == through->mu)) out.push_back(&r);
  return out;
}

constexpr validation::Criterion criteria[] = {validation::Criterion::MohrCoulomb, validation::Criterion::LadeDuncan,
                                               validation::Criterion::MatsuokaNakai};

validation::Table critical_state_data(const std::vector<ShearRun>& runs) {
  validation::Table t;
  t.comments = {"compare-runs critical-state: one row per finished run; loading 1 compression, 2 extension, 3 true triaxial (b series);",
                "the critical state is the mean (and row-to-row sd) over the rows with 0.3 <= |axial strain| <= 0.4 (NaN without such rows)"};
  t.columns = {"mu [1]", "loading [1]", "b_target [1]", "peak_phi [deg]", "peak_phi_single_row [deg]", "peak_axial_strain [1]",
               "phi_cs [deg]", "phi_cs_sd [deg]", "e_cs [1]", "e_cs_sd [1]", "cn_cs [1]", "cn_cs_sd [1]", "cn_mechanical_cs [1]",
               "cn_mechanical_cs_sd [1]", "q_over_p_cs [1]", "q_over_p_cs_sd [1]", "b_at_peak [1]", "max_axial_strain [1]", "cs_rows [1]",
               "peak_radius_over_p [1]", "peak_lode [deg]", "p_at_peak [kPa]", "p_cs [kPa]", "b_cs [1]", "p_min [kPa]", "p_max [kPa]",
               "held_as_named [1]"};
  const auto mean = [](const validation::Spread& s) { return s.n ? s.mean : NAN; };
  const auto sd = [](const validation::Spread& s) { return s.n > 1 ? s.sd : NAN; };
  for (const ShearRun& r : runs) {
    if (!r.summary) continue;
    const validation::ShearSummary& s = *r.summary;
    const double loading = r.loading == "compression" ? 1 : r.loading == "extension" ? 2 : 3;
    t.labels.push_back(r.run);
    t.rows.push_back({r.mu, loading, r.b, s.peak_phi_deg, s.peak_phi_raw_deg, s.peak_axial_strain, mean(s.phi_deg), sd(s.phi_deg),
                      mean(s.void_ratio), sd(s.void_ratio), mean(s.coordination), sd(s.coordination), mean(s.coordination_mechanical),
                      sd(s.coordination_mechanical), mean(s.q_over_p), sd(s.q_over_p), s.peak_b, s.max_axial_strain,
                      static_cast<double>(s.cs_rows), s.peak_pi.radius, s.peak_pi.lode_deg, s.peak_p_Pa / 1e3, mean(s.p_Pa) / 1e3, mean(s.b),
                      s.p_min_Pa / 1e3, s.p_max_Pa / 1e3, r.held ? 1.0 : 0.0});
  }
  return t;
}

// pi_plane.dat: the measured peaks (set 0: b series, set 1: extension) and the three criteria
// through the compression peak over every angle (sets 2-4), one block each.
validation::Table pi_plane_data(const std::vector<ShearRun>& runs, const ShearRun* through) {
  validation::Table t;
  t.comments = {"compare-runs critical-state: the pi-plane normalised by p (s1 up, s2 lower left, s3 lower right; lode 0 = compression,",
                "60 = extension); set 0 the b series' peaks, 1 the extension peak at the same mu, 2 Mohr-Coulomb, 3 Lade-Duncan,",
                "4 Matsuoka-Nakai through the compression peak (" + (through ? through->run : std::string("none: not finished")) + ");",
                "held_as_named 0: the run did not hold its p or b (table.md)"};
  t.columns = {"set [1]", "x [1]", "y [1]", "radius [1]", "lode [deg]", "b [1]", "held_as_named [1]"};
  for (const ShearRun* r : pi_plane_runs(runs, through)) {
    if (!r->summary) continue;
    const validation::PiPoint& q = r->summary->peak_pi;
    t.labels.push_back(r->run);
    t.rows.push_back({r->loading == "extension" ? 1.0 : 0.0, q.x, q.y, q.radius, q.lode_deg, r->summary->peak_b, r->held ? 1.0 : 0.0});
  }
  if (!through) return t;
  const dem::Vec3& s = through->summary->peak_principal_Pa;
  const double p = s.sum() / 3;
  for (std::size_t k = 0; k < std::size(criteria); ++k) {
    t.block_starts.push_back(t.rows.size());
    for (int deg = 0; deg <= 360; ++deg) {  // every degree: the hexagon's corners (every 60) are met exactly
      const double lode = deg * std::numbers::pi / 180, radius = validation::criterion_radius(criteria[k], s, lode) / p;
      t.labels.push_back(validation::to_string(criteria[k]));
      t.rows.push_back({static_cast<double>(k + 2), -radius * std::sin(lode), radius * std::cos(lode), radius, static_cast<double>(deg), NAN, 1});
    }
  }
  return t;
}

// "+1.23": a difference of friction angles, signed.
std::string signed_fixed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.2f", x);
  return buf;
}

std::string critical_state_table(const std::vector<ShearRun>& runs, const ShearRun* through, const std::string& settings,
                                 const std::string& ensemble_and_rates) {
  validation::MarkdownTable runs_table({"run", "μ", "loading", "peak φ (°)", "at axial strain", "p at peak (kPa)", "b at peak", "critical φ (°)",
                                        "e_cs", "CN_cs (2Nc/Np)", "CN_cs mechanical", "q/p at cs", "p at cs (kPa)", "b at cs", "note"});
  for (const ShearRun& r : runs) {
    std::vector<std::string> cells = {r.run, fixed(r.mu, 2), r.loading + (r.loading == "b series" ? " b = " + number(r.b) : "")};
    if (!r.summary) {
      cells.resize(runs_table.columns() - 1, "—");
      cells.push_back(r.note);
      runs_table.row(cells);
      continue;
    }
    const validation::ShearSummary& s = *r.summary;
    std::string note = r.note;
    if (note.size() >= 2 && note.substr(note.size() - 2) == "; ") note.resize(note.size() - 2);
    cells.insert(cells.end(), {fixed(s.peak_phi_deg, 2), fixed(s.peak_axial_strain, 3), fixed(s.peak_p_Pa / 1e3, 1), fixed(s.peak_b, 3),
                               mean_sd(s.phi_deg, 2), mean_sd(s.void_ratio, 4), mean_sd(s.coordination, 3),
                               mean_sd(s.coordination_mechanical, 3), mean_sd(s.q_over_p, 3), fixed(s.p_Pa.n ? s.p_Pa.mean / 1e3 : NAN, 1),
                               mean_sd(s.b, 3), note});
    runs_table.row(cells);
  }
  double worst_p = 0;  // the largest offset of p at the critical state from the constraint's, over the runs
  for (const ShearRun& r : runs)
    if (r.summary && r.summary->p_Pa.n && std::isfinite(r.p_target_Pa))
      worst_p = std::max(worst_p, std::abs(r.summary->p_Pa.mean / r.p_target_Pa - 1));
  std::ostringstream md;
  md << settings << "\n\n" << runs_table.text();
  md << "\nPeak φ: the largest mobilised friction angle, sin φ = (σ1 − σ3)/(σ1 + σ3) of the principal stresses of the full tensor, "
        "after a centred mean of the principal stresses over 1 % of axial strain (the largest single row is in `critical_state.dat`). "
        "Critical state: mean ± sd over the rows with 0.3 ≤ |ε3| ≤ 0.4; the sd is the row-to-row scatter, not the error of the mean "
        "(the rows are correlated). CN mechanical = (2Nc − N1)/(Np − N0 − N1) (Thornton 2000) leaves out the rattlers, which carry no "
        "load and whose share changes with μ; it is the coordination of the network that carries the stress. ⚠: p at the peak or "
        "at the critical state more than 5 % from the constraint's, or b at the critical state more than 0.05 from the target: the "
        "run is not the test its name says (p at the critical state is at most " << fixed(100 * worst_p, 1)
     << " % from the constraint's in this study); its values are shown, but they are not that test's.\n";
  md << ensemble_and_rates;
  md << "\n![peak and critical-state friction angle against μ](phi_mu.png)\n\n![critical-state void ratio and coordination number against μ](e_cn_mu.png)\n";
  md << "\n### The peaks in the π-plane\n\n";
  if (!through) {
    md << "No compression peak at the b series' μ yet (its b = 0 run is not finished): no surfaces drawn.\n";
    return md.str();
  }
  validation::MarkdownTable peaks({"run", "b at peak", "Lode angle (°)", "ρ/p", "measured peak φ (°)", "Mohr–Coulomb φ (Δ)", "Lade–Duncan φ (Δ)",
                                   "Matsuoka–Nakai φ (Δ)", "note"});
  for (const ShearRun* r : pi_plane_runs(runs, through)) {
    std::vector<std::string> cells = {r->run};
    if (!r->summary) {
      cells.resize(peaks.columns() - 1, "—");
      cells.push_back(r->note);
      peaks.row(cells);
      continue;
    }
    const validation::ShearSummary& s = *r->summary;
    cells.insert(cells.end(), {fixed(s.peak_b, 3), fixed(s.peak_pi.lode_deg, 1), fixed(s.peak_pi.radius, 3), fixed(s.peak_phi_deg, 2)});
    for (validation::Criterion c : criteria) {
      const double predicted = std::isfinite(s.peak_b) ? validation::predicted_friction_deg(c, through->summary->peak_principal_Pa, s.peak_b) : NAN;
      cells.push_back(fixed(predicted, 2) + " (" + (std::isfinite(predicted) ? signed_fixed(s.peak_phi_deg - predicted) : "—") + ")");
    }
    cells.push_back(r->held ? "" : "⚠ not the test its name says (see above)");
    peaks.row(cells);
  }
  md << "The b series and the extension run at μ = " << number(through->mu) << "; the three criteria go through the compression peak ("
     << cell(through->run) << ", φ = " << fixed(through->summary->peak_phi_deg, 2) << "°). Each criterion's φ at the b measured at a "
     << "peak (at the same p), and Δ = measured − predicted:\n\n"
     << peaks.text();
  md << "\n![the peaks in the π-plane beside the failure criteria](pi_plane.png)\n";
  return md.str();
}

// ---- the ensemble (--ensemble): mean ± sd over samples --------------------------------------

// One (loading, μ) of the ensemble study: its samples' runs.
struct EnsembleGroup {
  std::string loading;
  double mu = NAN;
  std::vector<const ShearRun*> runs;  // every sample's run, finished or not
  std::vector<validation::ShearSummary> used;  // the finished ones that held their p and b
  validation::ShearEnsemble stats;
};

std::vector<EnsembleGroup> ensemble_groups(const std::vector<ShearRun>& runs) {
  std::vector<EnsembleGroup> groups;
  for (const ShearRun& r : runs) {
    if (r.loading != "compression" && r.loading != "extension") continue;  // the b series is one sample's (main study)
    auto g = std::find_if(groups.begin(), groups.end(), [&](const EnsembleGroup& x) { return x.loading == r.loading && x.mu == r.mu; });
    if (g == groups.end()) g = groups.insert(groups.end(), EnsembleGroup{r.loading, r.mu, {}, {}, {}});
    g->runs.push_back(&r);
    if (r.summary && r.held) g->used.push_back(*r.summary);
  }
  for (EnsembleGroup& g : groups) g.stats = validation::shear_ensemble(g.used);
  return groups;
}

// "mean ± sd" of a spread over samples: the sd to two significant digits, the mean to the same
// decimal (validation::mean_pm_sd); one sample: its value, said so.
std::string over_samples(const validation::Spread& s) {
  if (s.n == 0) return "—";
  return validation::mean_pm_sd(s.mean, s.sd) + (s.n == 1 ? " (one sample)" : "");
}

// The main study's run of the same loading and μ (seed 1's, the one the table above shows).
const ShearRun* main_run(const std::vector<ShearRun>& runs, const std::string& loading, double mu) {
  for (const ShearRun& r : runs)
    if (r.loading == loading && r.mu == mu && r.summary) return &r;
  return nullptr;
}

validation::Table ensemble_data(const std::vector<EnsembleGroup>& groups) {
  validation::Table t;
  t.comments = {"compare-runs critical-state --ensemble: one row per loading and mu of the ensemble study; mean and sample sd over",
                "its samples (each sample's critical state its window mean); loading 1 compression, 2 extension"};
  t.columns = {"mu [1]", "loading [1]", "samples [1]", "phi_cs [deg]", "phi_cs_sd [deg]", "q_over_p_cs [1]", "q_over_p_cs_sd [1]",
               "e_cs [1]", "e_cs_sd [1]", "cn_cs [1]", "cn_cs_sd [1]", "peak_phi [deg]", "peak_phi_sd [deg]"};
  const auto m = [](const validation::Spread& s) { return s.n ? s.mean : NAN; };
  const auto sd = [](const validation::Spread& s) { return s.n > 1 ? s.sd : NAN; };
  for (const EnsembleGroup& g : groups) {
    const validation::ShearEnsemble& e = g.stats;
    t.labels.push_back(g.loading + "_mu" + number(g.mu));
    t.rows.push_back({g.mu, g.loading == "compression" ? 1.0 : 2.0, static_cast<double>(e.samples), m(e.phi_cs_deg), sd(e.phi_cs_deg),
                      m(e.q_over_p_cs), sd(e.q_over_p_cs), m(e.void_ratio_cs), sd(e.void_ratio_cs), m(e.coordination_cs),
                      sd(e.coordination_cs), m(e.peak_phi_deg), sd(e.peak_phi_deg)});
  }
  return t;
}

// Whether the ensemble's samples resolve what the section reads from it: for each μ with both a
// compression and an extension group, the difference of their mean critical φ against its standard
// error, sqrt(sd_c^2 / n_c + sd_e^2 / n_e), and Welch's t against the two-sided quantile of the
// validation's prediction level at the smaller n - 1.
std::string samples_suffice(const std::vector<EnsembleGroup>& groups) {
  std::ostringstream md;
  for (const EnsembleGroup& c : groups) {
    if (c.loading != "compression") continue;
    for (const EnsembleGroup& e : groups) {
      if (e.loading != "extension" || e.mu != c.mu) continue;
      const validation::Spread &a = c.stats.phi_cs_deg, &b = e.stats.phi_cs_deg;
      if (a.n < 2 || b.n < 2) continue;
      const double diff = b.mean - a.mean, se = std::sqrt(a.sd * a.sd / a.n + b.sd * b.sd / b.n);
      const int dof = static_cast<int>(std::min(a.n, b.n)) - 1;
      const double tail = 1 - (1 - validation::prediction_level) / 2, t = diff / se, limit = validation::t_quantile(tail, dof);
      md << "\nSample size: at μ = " << number(c.mu) << " the extension's critical φ is " << (diff >= 0 ? "+" : "") << fixed(diff, 2)
         << "° from the compression's, with a standard error of " << fixed(se, 2) << "° from the samples' sd (" << a.n << " and " << b.n
         << " samples): t = " << fixed(t, 1) << " against t(" << number(tail) << ", " << dof << ") = " << fixed(limit, 2) << ", so "
         << (std::abs(t) > limit ? "these samples resolve the difference" : "these samples do not resolve the difference: more are needed")
         << ". The sd between samples (" << fixed(a.sd, 2) << "° and " << fixed(b.sd, 2)
         << "°) is the scatter a one-sample value in the table above carries.\n";
    }
  }
  return md.str();
}

std::string ensemble_section(const std::vector<EnsembleGroup>& groups, const std::vector<ShearRun>& main_runs, const std::string& folder,
                             std::size_t samples, double cs_from, double cs_to) {
  std::ostringstream md;
  md << "\n### The critical state on " << samples << " samples\n\n";
  std::size_t finished = 0, runs = 0, used = 0;
  for (const EnsembleGroup& g : groups) {
    runs += g.runs.size(), used += g.used.size();
    for (const ShearRun* r : g.runs) finished += r->summary.has_value();
  }
  md << "The ensemble study (`" << folder << "`, `pipeline/studies/critical_state_ensemble.yaml`): " << samples
     << " samples of the dense sample, each sheared as above; " << finished << " of " << runs << " runs finished, " << used
     << " of them held their p and b and are counted. Mean ± sd over the samples (the sample sd, n − 1; the sd to two significant "
        "digits, the mean to the same decimal); each sample's critical state is its mean over " << number(cs_from) << " ≤ |ε3| ≤ "
     << number(cs_to) << ". The last two columns are the one-sample study's run above, for comparison; the figure draws the "
        "ensemble's means with the samples' sd as error bars beside it.\n\n";
  validation::MarkdownTable t({"loading", "μ", "samples", "critical φ (°)", "q/p at cs", "e_cs", "CN_cs (2Nc/Np)", "peak φ (°)",
                               "one-sample critical φ (°)", "one-sample peak φ (°)", "note"});
  for (const EnsembleGroup& g : groups) {
    const validation::ShearEnsemble& e = g.stats;
    std::string note;
    for (const ShearRun* r : g.runs)
      if (!r->summary) note += r->run + ": " + r->note + "; ";
      else if (!r->held) note += r->run + ": left out, not the test its name says (" + r->note + "); ";
    if (note.size() >= 2) note.resize(note.size() - 2);
    const ShearRun* one = main_run(main_runs, g.loading, g.mu);
    t.row({g.loading, number(g.mu), std::to_string(e.samples), over_samples(e.phi_cs_deg), over_samples(e.q_over_p_cs),
           over_samples(e.void_ratio_cs), over_samples(e.coordination_cs), over_samples(e.peak_phi_deg),
           one && one->summary->phi_deg.n ? fixed(one->summary->phi_deg.mean, 2) : "—", one ? fixed(one->summary->peak_phi_deg, 2) : "—",
           note});
  }
  md << t.text();
  md << samples_suffice(groups);
  return md.str();
}

// ---- rate convergence (--rates): q/p against sqrt(I), taken to I -> 0 ----------------------

struct RatePoint {
  const ShearRun* run;
  std::string study;  // which folder it came from
  double inertial = NAN;
};

struct RateSeries {
  double mu = NAN;
  std::vector<RatePoint> points;  // fastest first
  std::optional<validation::LineFit> fit;
  double phi_deg = NAN, phi_se_deg = NAN;  // the quasi-static φ (compression) from the intercept, and its se
  std::string problems;           // why the fit is poor, or why there is none
};

double inertial_of(const ShearRun& r) {
  if (!r.summary || !r.summary->p_Pa.n) return NAN;
  return validation::inertial_number(r.rate_per_s, r.diameter_m, r.density_kg_per_m3, r.summary->p_Pa.mean);
}

// Every μ of the rates study's compression runs, with the main study's compression run at that μ.
std::vector<RateSeries> rate_series(const std::vector<ShearRun>& rates, const std::vector<ShearRun>& main_runs, const std::string& rates_name,
                                    const std::string& main_name) {
  std::vector<RateSeries> out;
  const auto add = [&](const ShearRun& r, const std::string& study) {
    if (r.loading != "compression") return;
    auto s = std::find_if(out.begin(), out.end(), [&](const RateSeries& x) { return x.mu == r.mu; });
    if (s == out.end()) s = out.insert(out.end(), RateSeries{r.mu, {}, std::nullopt, NAN, NAN, ""});
    s->points.push_back({&r, study, inertial_of(r)});
  };
  for (const ShearRun& r : rates) add(r, rates_name);
  for (RateSeries& s : out)
    for (const ShearRun& r : main_runs)
      if (r.loading == "compression" && r.mu == s.mu) s.points.push_back({&r, main_name, inertial_of(r)});
  for (RateSeries& s : out) {
    std::sort(s.points.begin(), s.points.end(), [](const RatePoint& a, const RatePoint& b) { return a.run->rate_per_s > b.run->rate_per_s; });
    std::vector<double> x, y;
    std::vector<std::string> unfinished, not_held, no_value;  // the runs left out, by why (each run's note is in the table)
    for (const RatePoint& p : s.points) {
      if (!p.run->summary) unfinished.push_back(p.run->run);
      else if (!p.run->held) not_held.push_back(p.run->run);
      else if (!std::isfinite(p.inertial) || !p.run->summary->q_over_p.n) no_value.push_back(p.run->run);
      else x.push_back(std::sqrt(p.inertial)), y.push_back(p.run->summary->q_over_p.mean);
    }
    const auto left_out = [&](const std::vector<std::string>& names, const std::string& why) {
      if (names.empty()) return;
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      s.problems += list + " left out (" + why + "); ";
    };
    left_out(unfinished, "not finished or unreadable");
    left_out(not_held, "not the test its name says: p or b not held, see its note");
    left_out(no_value, "no inertial number or no critical-state rows: radii or scene missing");
    if (x.size() < 2) {
      s.problems += "no fit: " + std::to_string(x.size()) + " usable point(s); ";
      continue;
    }
    s.fit = validation::fit_line(x, y);
    s.phi_deg = validation::compression_friction_deg(s.fit->intercept);
    s.phi_se_deg = validation::compression_friction_slope_deg(s.fit->intercept) * s.fit->intercept_se;
    if (!s.fit->monotonic) s.problems += "poor fit: q/p does not change monotonically with I; ";
    if (s.fit->slope < 0) s.problems += "q/p falls as I grows (slope " + validation::significant(s.fit->slope, 2) + "): the line is no rate effect of the usual sign; ";
    if (s.fit->n == 2) s.problems += "two points: the line goes through both, no standard error; ";
  }
  for (RateSeries& s : out)
    if (s.problems.size() >= 2) s.problems.resize(s.problems.size() - 2);
  return out;
}

validation::Table rates_data(const std::vector<RateSeries>& series) {
  validation::Table t;
  t.comments = {"compare-runs critical-state --rates: one row per compression run of a rate series (values.gp rate_mu_<k>);",
                "I = rate d sqrt(rho / p_cs); q/p at cs the window mean and its row-to-row sd; used 0: left out of the fit"};
  t.columns = {"series [1]", "mu [1]", "strain_rate [1/s]", "diameter [m]", "density [kg/m3]", "p_cs [kPa]", "inertial_number [1]",
               "sqrt_inertial_number [1]", "q_over_p_cs [1]", "q_over_p_cs_sd [1]", "used [1]"};
  for (std::size_t k = 0; k < series.size(); ++k)
    for (const RatePoint& p : series[k].points) {
      const ShearRun& r = *p.run;
      const bool has = r.summary && r.summary->q_over_p.n;
      t.labels.push_back(r.run);
      t.rows.push_back({static_cast<double>(k + 1), r.mu, r.rate_per_s, r.diameter_m, r.density_kg_per_m3,
                        has ? r.summary->p_Pa.mean / 1e3 : NAN, p.inertial, std::sqrt(p.inertial), has ? r.summary->q_over_p.mean : NAN,
                        has && r.summary->q_over_p.n > 1 ? r.summary->q_over_p.sd : NAN,
                        has && r.held && std::isfinite(p.inertial) ? 1.0 : 0.0});
    }
  return t;
}

validation::Table rates_quasi_static_data(const std::vector<RateSeries>& series) {
  validation::Table t;
  t.comments = {"compare-runs critical-state --rates: the quasi-static limit of each rate series, the fit of q/p against sqrt(I) at I = 0;",
                "phi from q/p in triaxial compression, sin phi = 3 eta / (6 + eta); its se to first order from the intercept's"};
  t.columns = {"mu [1]", "q_over_p [1]", "q_over_p_se [1]", "phi [deg]", "phi_se [deg]", "slope [1]", "points [1]", "monotonic [1]"};
  for (const RateSeries& s : series) {
    if (!s.fit) continue;
    t.labels.push_back("mu" + number(s.mu));
    t.rows.push_back({s.mu, s.fit->intercept, s.fit->intercept_se, s.phi_deg, s.phi_se_deg, s.fit->slope, static_cast<double>(s.fit->n),
                      s.fit->monotonic ? 1.0 : 0.0});
  }
  return t;
}

// A reference row of the critical-state angle that reads the series' run at the study's rate (its
// density_test is the run's name): its value beside the quasi-static φ, since the row's own verdict is
// at that rate and the reference holds at I -> 0. Empty when no row reads the run.
std::string against_reference(const RateSeries& s, const ShearRun& table_run, const std::vector<validation::Row>& rows) {
  if (!s.fit) return "";
  for (const validation::Row& row : rows) {
    if (row.quantity != "critical_state_friction_angle" || row.density + "_" + row.test != table_run.run) continue;
    const double off = s.phi_deg - row.reference;
    const double at_rate = validation::compression_friction_deg(table_run.summary->q_over_p.mean) - row.reference;
    std::ostringstream md;
    md << " The reference row \"" << row.name << "\" (" << row.source.substr(0, row.source.find(':')) << ") gives " << number(row.reference)
       << "° with a reading tolerance of " << number(row.tolerance) << "°: the quasi-static φ is " << (off >= 0 ? "+" : "") << fixed(off, 2)
       << "° from it (" << (std::abs(off) <= row.tolerance ? "within" : "beyond") << " the tolerance";
    if (s.fit->n > 2) md << "; its se " << fixed(s.phi_se_deg, 2) << "°";
    md << "), the " << number(table_run.rate_per_s) << " s⁻¹ run's " << (at_rate >= 0 ? "+" : "") << fixed(at_rate, 2)
       << "° (the literature section judges the row at that rate).";
    return md.str();
  }
  return "";
}

std::string rates_section(const std::vector<RateSeries>& series, const std::string& folder, const std::vector<validation::Row>& rows) {
  std::ostringstream md;
  md << "\n### Rate convergence: the critical state at I → 0\n\n";
  md << "The rates study (`" << folder << "`, `pipeline/studies/critical_state_rates.yaml`) shears the same sample in compression at "
        "slower axial strain rates; with the run of the table above at its own rate, each μ has a series. I = rate · d · √(ρ/p): "
        "the resolved scene's axial strain rate and particle density, d the mean diameter of the run's spheres, p its mean stress at "
        "the critical state; q/p at cs is the window mean ± the row-to-row sd, as above. A least-squares line of the window means "
        "against √I, taken to I → 0, gives the quasi-static q/p with "
        "the intercept's standard error (n − 2 degrees of freedom), and φ from it (triaxial compression: sin φ = 3η/(6 + η), η = q/p; "
        "its se to first order).\n\n";
  validation::MarkdownTable t({"μ", "run", "strain rate (s⁻¹)", "d (mm)", "ρ (kg/m³)", "p at cs (kPa)", "I", "√I", "q/p at cs",
                               "φ from q/p (°)", "note"});
  for (const RateSeries& s : series) {
    for (const RatePoint& p : s.points) {
      const ShearRun& r = *p.run;
      const bool has = r.summary && r.summary->q_over_p.n;
      t.row({number(s.mu), r.run + " (" + p.study + ")", number(r.rate_per_s), fixed(1e3 * r.diameter_m, 3), number(r.density_kg_per_m3),
             has ? fixed(r.summary->p_Pa.mean / 1e3, 1) : "—", std::isfinite(p.inertial) ? validation::significant(p.inertial, 3) : "—",
             std::isfinite(p.inertial) ? validation::significant(std::sqrt(p.inertial), 3) : "—", has ? mean_sd(r.summary->q_over_p, 3) : "—",
             has ? fixed(validation::compression_friction_deg(r.summary->q_over_p.mean), 2) : "—",
             !r.summary ? r.note : r.held ? "" : "left out of the fit: " + r.note.substr(0, r.note.size() >= 2 ? r.note.size() - 2 : 0)});
    }
    if (s.fit)
      t.row({number(s.mu), "**I → 0** (fit of " + std::to_string(s.fit->n) + " points)", "0", "", "", "", "0", "0",
             "**" + (s.fit->n > 2 ? validation::mean_pm_sd(s.fit->intercept, s.fit->intercept_se) : fixed(s.fit->intercept, 3)) + "**",
             "**" + (s.fit->n > 2 ? validation::mean_pm_sd(s.phi_deg, s.phi_se_deg) : fixed(s.phi_deg, 2)) + "**", s.problems});
    else
      t.row({number(s.mu), "I → 0", "—", "", "", "", "", "", "—", "—", s.problems});
  }
  md << t.text() << "\n";
  for (const RateSeries& s : series) {
    if (!s.fit) {
      md << "μ = " << number(s.mu) << ": " << s.problems << ".\n\n";
      continue;
    }
    const validation::LineFit& f = *s.fit;
    const RatePoint* fastest = nullptr;  // the fastest point used (the rate the table above is at)
    for (const RatePoint& p : s.points)
      if (p.run->summary && p.run->held && std::isfinite(p.inertial) && p.run->summary->q_over_p.n) {
        fastest = &p;
        break;
      }
    md << "μ = " << number(s.mu) << ": q/p = " << validation::significant(f.intercept, 3) << " + " << validation::significant(f.slope, 3)
       << " √I over " << f.n << " rates (R² = " << fixed(f.r_squared, 3) << ")";
    if (fastest) {
      const double at = fastest->run->summary->q_over_p.mean;
      md << "; the quasi-static q/p is " << fixed(100 * std::abs(f.intercept / at - 1), 1) << (f.intercept < at ? " % below" : " % above") << " the " << number(fastest->run->rate_per_s)
         << " s⁻¹ value (" << fixed(at, 3) << "), φ " << fixed(s.phi_deg, 2) << "° against "
         << fixed(validation::compression_friction_deg(at), 2) << "°";
    }
    if (f.n > 2) {
      const double quantile = validation::t_quantile(1 - (1 - validation::prediction_level) / 2, f.n - 2);
      md << ". The standard error rests on " << f.n - 2 << (f.n - 2 == 1 ? " degree" : " degrees") << " of freedom: a "
         << number(100 * validation::prediction_level) << " % interval is ± " << validation::significant(quantile, 3) << " se (± "
         << validation::significant(quantile * f.intercept_se, 2) << " in q/p)";
    }
    md << (s.problems.empty() ? ". q/p changes monotonically with I." : ". ⚠ " + s.problems + ".");
    if (fastest) md << against_reference(s, *fastest->run, rows);
    md << "\n\n";
  }
  md << "![critical q/p against the square root of the inertial number, with the fits](rates.png)\n";
  return md.str();
}

}  // namespace

int critical_state(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& ensemble,
                   const std::string& rates, const std::string& references) {
  constexpr double cs_from = 0.3, cs_to = 0.4;
  const std::vector<ShearRun> runs = shear_runs(manifest, results, cs_to);
  const ShearRun* through = compression_peak(runs);
  std::size_t finished = 0;
  for (const ShearRun& r : runs) finished += r.summary.has_value();
  // The settings the table quotes, from a finished run's resolved scene.
  std::string settings = "Drained shear at constant p of the dense sample (`scenes/tests/constant_p_shear.yaml`).";
  for (const ManifestLine& l : manifest.lines)
    if (l.test != "-" && validation::is_complete(validation::result_under(results, l))) {
      const RunFile f = read_run(validation::result_under(results, l));
      if (!f.scene) continue;
      const dem::StageConfig& st = f.scene->stages.back();
      settings = "Drained shear of the dense sample at constant p = " + number(st.control.constraint.mean_stress_Pa / 1e3) +
                 " kPa (`scenes/tests/constant_p_shear.yaml`), axial strain rate " + number(std::abs(st.control.component[2].strain_rate_per_s)) +
                 " s⁻¹ to |ε3| = " + number(st.until.strain) + ", shear stresses held at zero; " + std::to_string(finished) + " of " +
                 std::to_string(runs.size()) + " runs finished.";
      break;
    }
  // The ensemble and the rates studies, each from its own folder (a folder without a manifest is
  // an error: make_section.sh passes only folders that have one).
  std::vector<ShearRun> ensemble_runs, rate_runs;
  std::vector<EnsembleGroup> groups;
  std::vector<RateSeries> series;
  std::string extra;
  if (!ensemble.empty()) {
    const Manifest m = read_manifest(ensemble);
    ensemble_runs = shear_runs(m, ensemble, cs_to);
    groups = ensemble_groups(ensemble_runs);
    extra += ensemble_section(groups, runs, relative_paths(ensemble, ensemble), validation::samples_of(m.lines).size(), cs_from, cs_to);
  }
  if (!rates.empty()) {
    rate_runs = shear_runs(read_manifest(rates), rates, cs_to);
    series = rate_series(rate_runs, runs, "rates study", "table above");
    std::vector<validation::Row> rows;
    if (!references.empty()) try {
        rows = validation::load_references(references, "paper");
      } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
      }
    extra += rates_section(series, relative_paths(rates, rates), rows);
  }
  validation::GnuplotValues values;
  values.number("has_compression_peak", through ? 1 : 0);
  double largest = 0.1;  // the pi-plane's half-width: the largest radius drawn, with a margin
  const validation::Table pi = pi_plane_data(runs, through);
  for (std::size_t i = 0; i < pi.size(); ++i) largest = std::max(largest, pi.rows[i][3]);
  values.number("pi_r", std::ceil(11 * largest) / 10);
  values.number("runs_finished", static_cast<double>(finished));
  values.number("runs_total", static_cast<double>(runs.size()));
  values.number("has_ensemble", groups.empty() ? 0 : 1);
  values.number("ensemble_samples", ensemble.empty() ? 0 : static_cast<double>(validation::samples_of(read_manifest(ensemble).lines).size()));
  const validation::Table qs = rates_quasi_static_data(series);
  values.number("has_rates", qs.size() ? 1 : 0);
  values.number("rate_series_n", static_cast<double>(series.size()));
  for (std::size_t k = 0; k < series.size(); ++k) {
    const std::string i = std::to_string(k + 1);
    values.number("rate_mu_" + i, series[k].mu);
    values.number("rate_fitted_" + i, series[k].fit ? 1 : 0);
    values.number("rate_intercept_" + i, series[k].fit ? series[k].fit->intercept : NAN);
    values.number("rate_slope_" + i, series[k].fit ? series[k].fit->slope : NAN);
    values.number("rate_intercept_se_" + i, series[k].fit ? series[k].fit->intercept_se : NAN);
  }
  try {
    fs::create_directories(out);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), critical_state_table(runs, through, settings, extra));
    dem::write_file_atomically((fs::path(out) / "critical_state.dat").string(), critical_state_data(runs).text());
    dem::write_file_atomically((fs::path(out) / "pi_plane.dat").string(), pi.text());
    dem::write_file_atomically((fs::path(out) / "ensemble.dat").string(), ensemble_data(groups).text());
    dem::write_file_atomically((fs::path(out) / "rates.dat").string(), rates_data(series).text());
    dem::write_file_atomically((fs::path(out) / "rates_qs.dat").string(), qs.text());
    std::string from = relative_paths(results, results);
    if (!ensemble.empty()) from += ", --ensemble " + relative_paths(ensemble, ensemble);
    if (!rates.empty()) from += ", --rates " + relative_paths(rates, rates);
    dem::write_file_atomically((fs::path(out) / "values.gp").string(), values.text_file("Written by compare-runs critical-state from " + from));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  for (const std::vector<ShearRun>* set : std::vector<const std::vector<ShearRun>*>{&runs, &ensemble_runs, &rate_runs})
    for (const ShearRun& r : *set)
      if (!r.summary) std::fprintf(stderr, "note: %s: %s\n", r.run.c_str(), r.note.c_str());
  std::printf("critical-state: %zu of %zu runs finished -> %s\n", finished, runs.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}
}  // namespace compare_runs
