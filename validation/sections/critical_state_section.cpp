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

#include "sections/critical_state_parts.hpp"
#include "sections/modes.hpp"
#include "contact/contact_law.hpp"
#include "judge/critical_state.hpp"
#include "study/series.hpp"
#include "study/format.hpp"
#include "io/atomic_file.hpp"
#include "study/line_fit.hpp"
#include "study/markdown_table.hpp"
#include "judge/rows.hpp"

namespace fs = std::filesystem;

namespace sections {
namespace {

using validation::cell;
using validation::Bound;
using validation::Digits;
using validation::bound_text;
using validation::fixed;
using validation::number;

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

validation::SectionDoc critical_state_table(const std::vector<ShearRun>& runs, const ShearRun* through, const std::string& settings,
                                            const validation::SectionDoc& ensemble_and_rates) {
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
        "(the rows are correlated); φ is that of the rows' mean principal stresses, with the scatter of the rows' angles, "
        "the same φ every table of this section gives for a run. CN mechanical = (2Nc − N1)/(Np − N0 − N1) (Thornton 2000) leaves out the rattlers, which carry no "
        "load and whose share changes with μ; it is the coordination of the network that carries the stress. ⚠: p at the peak or "
        "at the critical state more than 5 % from the constraint's, or b at the critical state more than 0.05 from the target: the "
        "run is not the test its name says (p at the critical state is at most " << bound_text(100 * worst_p, Bound::at_most, 1, Digits::decimals)
     << " % from the constraint's in this study); its values are shown, but they are not that test's.\n";
  validation::SectionDoc doc;
  doc.text(md.str()).append(ensemble_and_rates).text("\n").figure("phi_mu.png", "peak and critical-state friction angle against μ");
  doc.text("\n").figure("e_cn_mu.png", "critical-state void ratio and coordination number against μ");
  doc.text("\n").heading(1, "The peaks in the π-plane").text("\n");
  md.str("");
  if (!through) return doc.text("No compression peak at the b series' μ yet (its b = 0 run is not finished): no surfaces drawn.\n");
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
     << peaks.text() << "\n";
  return doc.text(md.str()).figure("pi_plane.png", "the peaks in the π-plane beside the failure criteria");
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
  // an error: make critical-state-report passes only folders that have one).
  std::vector<ShearRun> ensemble_runs, rate_runs;
  std::vector<EnsembleGroup> groups;
  std::vector<RateSeries> series;
  validation::SectionDoc extra;
  if (!ensemble.empty()) {
    const Manifest m = read_manifest(ensemble);
    ensemble_runs = shear_runs(m, ensemble, cs_to);
    groups = ensemble_groups(ensemble_runs);
    extra.append(ensemble_section(groups, runs, relative_paths(ensemble, ensemble), validation::samples_of(m.lines).size(), cs_from, cs_to));
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
    extra.append(rates_section(series, relative_paths(rates, rates), rows));
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
    validation::write_section(out, critical_state_table(runs, through, settings, extra));
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
}  // namespace sections
