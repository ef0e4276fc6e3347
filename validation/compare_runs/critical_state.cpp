// compare-runs critical-state: the critical-state study (drained shear at constant p of the dense
// sample). Peak and critical-state friction angle, void ratio and coordination number of each
// run, and the peaks in the pi-plane beside Mohr-Coulomb, Lade-Duncan and Matsuoka-Nakai through
// the compression peak. Writes OUT/table.md, critical_state.dat, pi_plane.dat and values.gp (what
// reports/gnuplot/critical_state_*.gp need).
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
#include "markdown_table.hpp"

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

// One run of the critical-state study, as its name says: compression_mu<μ>, extension_mu<μ>, b<b>.
struct ShearRun {
  std::string run, loading;  // loading: compression, extension or "b series" (true triaxial)
  double mu = NAN, b = NAN;  // μ; b the target of the constraint (principal b: 1 in extension)
  double p_target_Pa = NAN;  // the constraint's mean stress
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
  if (test.rfind("b", 0) == 0)
    if (const auto b = whole_number(test.substr(1))) {
      r.loading = "b series", r.b = *b;
      return true;
    }
  return false;
}

// The critical-state analysis of the runs of a study's manifest; cs_to the axial strain the
// critical state is averaged up to (a run that stops short of it is noted).
std::vector<ShearRun> shear_runs(const Manifest& manifest, double cs_to) {
  std::vector<ShearRun> runs;
  for (const ManifestLine& l : manifest.lines) {
    if (l.test == "-") continue;  // the preparation
    ShearRun& r = runs.emplace_back();
    r.run = l.run;
    if (!parse_shear_test(l.test, r)) {
      r.note = "not analysed: test '" + l.test + "' is none of compression_mu<μ>, extension_mu<μ>, b<b>";
      continue;
    }
    if (!validation::is_complete(l.result)) {
      r.note = "missing: " + fs::path(l.result).filename().string() + " is not finished";
      continue;
    }
    try {
      const RunFile f = read_run(l.result);
      r.summary = validation::summarise_shear(f.series, 0.3, cs_to);
      if (f.scene) {  // μ, p and b as run: the scene's; a name that says otherwise is noted
        const double mu = dem::friction_coefficient(f.scene->material.law);
        if (std::isfinite(r.mu) && std::abs(mu - r.mu) > 1e-9) r.note += "the scene's friction is " + number(mu) + ", not the name's; ";
        r.mu = mu;
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

std::string critical_state_table(const std::vector<ShearRun>& runs, const ShearRun* through, const std::string& settings) {
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

}  // namespace

int critical_state(const Manifest& manifest, const std::string& results, const std::string& out) {
  constexpr double cs_to = 0.4;
  const std::vector<ShearRun> runs = shear_runs(manifest, cs_to);
  const ShearRun* through = compression_peak(runs);
  std::size_t finished = 0;
  for (const ShearRun& r : runs) finished += r.summary.has_value();
  // The settings the table quotes, from a finished run's resolved scene.
  std::string settings = "Drained shear at constant p of the dense sample (`scenes/tests/constant_p_shear.yaml`).";
  for (const ManifestLine& l : manifest.lines)
    if (l.test != "-" && validation::is_complete(l.result)) {
      const RunFile f = read_run(l.result);
      if (!f.scene) continue;
      const dem::StageConfig& st = f.scene->stages.back();
      settings = "Drained shear of the dense sample at constant p = " + number(st.control.constraint.mean_stress_Pa / 1e3) +
                 " kPa (`scenes/tests/constant_p_shear.yaml`), axial strain rate " + number(std::abs(st.control.component[2].strain_rate_per_s)) +
                 " s⁻¹ to |ε3| = " + number(st.until.strain) + ", shear stresses held at zero; " + std::to_string(finished) + " of " +
                 std::to_string(runs.size()) + " runs finished.";
      break;
    }
  validation::GnuplotValues values;
  values.number("has_compression_peak", through ? 1 : 0);
  double largest = 0.1;  // the pi-plane's half-width: the largest radius drawn, with a margin
  const validation::Table pi = pi_plane_data(runs, through);
  for (std::size_t i = 0; i < pi.size(); ++i) largest = std::max(largest, pi.rows[i][3]);
  values.number("pi_r", std::ceil(11 * largest) / 10);
  values.number("runs_finished", static_cast<double>(finished));
  values.number("runs_total", static_cast<double>(runs.size()));
  try {
    fs::create_directories(out);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), critical_state_table(runs, through, settings));
    dem::write_file_atomically((fs::path(out) / "critical_state.dat").string(), critical_state_data(runs).text());
    dem::write_file_atomically((fs::path(out) / "pi_plane.dat").string(), pi.text());
    dem::write_file_atomically((fs::path(out) / "values.gp").string(),
                               values.text_file("Written by compare-runs critical-state from " + relative_paths(results, results)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  for (const ShearRun& r : runs)
    if (!r.summary) std::fprintf(stderr, "note: %s: %s\n", r.run.c_str(), r.note.c_str());
  std::printf("critical-state: %zu of %zu runs finished -> %s\n", finished, runs.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}
}  // namespace compare_runs
