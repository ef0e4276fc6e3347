// compare-runs critical-state --rates: the critical q/p of compression against sqrt(I) over the
// rates study's runs and the main study's own, fitted and taken to I -> 0 (critical_state_parts.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
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

using validation::fixed;
using validation::number;

namespace {

double inertial_of(const ShearRun& r) {
  if (!r.summary || !r.summary->p_Pa.n) return NAN;
  return validation::inertial_number(r.rate_per_s, r.diameter_m, r.density_kg_per_m3, r.summary->p_Pa.mean);
}

// A point the fit uses: finished, the test its name says, with an inertial number and rows at cs.
bool usable(const RatePoint& p) {
  return p.run->summary && p.run->held && std::isfinite(p.inertial) && p.run->summary->q_over_p.n;
}

// What a quasi-static reference is judged on at I -> 0: at least this many rates, with at least
// this many samples (seeds) at each, so that the fit's interval rests on degrees of freedom and
// the samples' scatter rather than on one sample's line through three points.
constexpr std::size_t rates_to_judge = 4, samples_per_rate_to_judge = 2;

// A reference row of the critical-state angle that reads one of the series' runs (its density_test is
// the run's name, one of the critical-state table's): judged on the quasi-static φ when the series can
// judge it (above), else its distance given for information only. The literature section does not
// judge the row at the run's finite rate either. Empty when no row reads a run of the series.
std::string against_reference(const RateSeries& s, const std::vector<validation::Row>& rows) {
  if (!s.fit) return "";
  std::map<double, std::size_t> samples;  // usable points per rate
  for (const RatePoint& p : s.points)
    if (usable(p)) ++samples[p.run->rate_per_s];
  std::size_t fewest = samples.empty() ? 0 : samples.begin()->second, most = fewest;
  for (const auto& [rate, n] : samples) fewest = std::min(fewest, n), most = std::max(most, n);
  const double half_width = s.fit->n > 2 ? validation::t_quantile(1 - (1 - validation::prediction_level) / 2, s.fit->n - 2) * s.phi_se_deg : NAN;
  const std::string each = fewest == most ? std::to_string(fewest) : std::to_string(fewest) + "–" + std::to_string(most);
  for (const validation::Row& row : rows) {
    if (!validation::taken_to_quasi_static_limit(row.quantity)) continue;  // the angle: what the series takes to I -> 0
    const auto read = std::find_if(s.points.begin(), s.points.end(),
                                   [&](const RatePoint& p) { return usable(p) && p.run->run == row.density + "_" + row.test; });
    if (read == s.points.end()) continue;
    const ShearRun& table_run = *read->run;
    const auto signed_deg = [](double x) { return (x >= 0 ? "+" : "") + fixed(x, 2) + "°"; };
    const double off = s.phi_deg - row.reference;
    const double at_rate = table_run.summary->phi_deg.mean - row.reference;
    std::ostringstream md;
    md << " The reference row \"" << row.name << "\" (" << row.source.substr(0, row.source.find(':')) << ") gives " << number(row.reference)
       << "° with a reading tolerance of " << number(row.tolerance) << "°";
    const std::string interval = std::isfinite(half_width) ? "its " + number(100 * validation::prediction_level) + " % interval ± " + fixed(half_width, 2) + "°"
                                                           : "no interval: two points";
    if (samples.size() >= rates_to_judge && fewest >= samples_per_rate_to_judge) {
      const bool reaches = std::abs(off) <= row.tolerance + half_width;
      md << ". Judged at I → 0 on " << samples.size() << " rates of " << each << " samples each: the quasi-static φ is "
         << signed_deg(off) << " from it (" << interval << "), "
         << (reaches ? "✅ consistent: the interval reaches the reference's region" : "❌ inconsistent: the interval does not reach the reference's region");
    } else {
      md << ". ⚠ Not judged at I → 0: the fit has " << samples.size() << (samples.size() == 1 ? " rate" : " rates") << " of " << each
         << (fewest == 1 && most == 1 ? " sample" : " samples") << " each, and a judgement needs at least " << rates_to_judge
         << " rates with " << samples_per_rate_to_judge << " or more samples at each. For information only: the quasi-static φ is "
         << signed_deg(off) << " from it (" << interval << ")";
    }
    md << "; the " << number(table_run.rate_per_s) << " s⁻¹ run's is " << signed_deg(at_rate)
       << " (not quasi-static: the literature section does not judge the row on it).";
    return md.str();
  }
  return "";
}

}  // namespace

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
    std::vector<double> x, y, sin_phi;
    std::vector<std::string> unfinished, not_held, no_value;  // the runs left out, by why (each run's note is in the table)
    for (const RatePoint& p : s.points) {
      if (!p.run->summary) unfinished.push_back(p.run->run);
      else if (!p.run->held) not_held.push_back(p.run->run);
      else if (!std::isfinite(p.inertial) || !p.run->summary->q_over_p.n) no_value.push_back(p.run->run);
      else {
        x.push_back(std::sqrt(p.inertial)), y.push_back(p.run->summary->q_over_p.mean);
        sin_phi.push_back(std::sin(p.run->summary->phi_deg.mean * std::numbers::pi / 180));
      }
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
    // φ is extrapolated as itself, not converted from the q/p intercept: the tables' φ (and a
    // literature row's) is that of the principal stresses, which sin φ = 3η/(6 + η) equals only
    // when σ2 = σ3 exactly.
    const validation::LineFit phi = validation::fit_line(x, sin_phi);
    s.phi_deg = std::asin(phi.intercept) * 180 / std::numbers::pi;
    s.phi_se_deg = phi.intercept_se / std::sqrt(1 - phi.intercept * phi.intercept) * 180 / std::numbers::pi;
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
                "phi: the same fit of sin phi (the rows' mean principal stresses, sin phi = (s1 - s3) / (s1 + s3)) at I = 0; its se to first order"};
  t.columns = {"mu [1]", "q_over_p [1]", "q_over_p_se [1]", "phi [deg]", "phi_se [deg]", "slope [1]", "points [1]", "monotonic [1]"};
  for (const RateSeries& s : series) {
    if (!s.fit) continue;
    t.labels.push_back("mu" + number(s.mu));
    t.rows.push_back({s.mu, s.fit->intercept, s.fit->intercept_se, s.phi_deg, s.phi_se_deg, s.fit->slope, static_cast<double>(s.fit->n),
                      s.fit->monotonic ? 1.0 : 0.0});
  }
  return t;
}

validation::SectionDoc rates_section(const std::vector<RateSeries>& series, const std::string& folder, const std::vector<validation::Row>& rows) {
  std::ostringstream md;
  md << "\n";
  md << "The rates study (`" << folder << "`, `pipeline/studies/critical_state_rates.yaml`) shears the same sample in compression at "
        "slower axial strain rates; with the run of the table above at its own rate, each μ has a series. I = rate · d · √(ρ/p): "
        "the resolved scene's axial strain rate and particle density, d the mean diameter of the run's spheres, p its mean stress at "
        "the critical state; q/p at cs is the window mean ± the row-to-row sd, as above. A least-squares line of the window means "
        "against √I, taken to I → 0, gives the quasi-static q/p with "
        "the intercept's standard error (n − 2 degrees of freedom). The same line through sin φ (φ of the window's mean principal "
        "stresses, the φ of every table here and of the literature rows) gives the quasi-static φ, with its se to first order.\n\n";
  validation::MarkdownTable t({"μ", "run", "strain rate (s⁻¹)", "d (mm)", "ρ (kg/m³)", "p at cs (kPa)", "I", "√I", "q/p at cs",
                               "φ at cs (°)", "note"});
  for (const RateSeries& s : series) {
    for (const RatePoint& p : s.points) {
      const ShearRun& r = *p.run;
      const bool has = r.summary && r.summary->q_over_p.n;
      t.row({number(s.mu), r.run + " (" + p.study + ")", number(r.rate_per_s), fixed(1e3 * r.diameter_m, 3), number(r.density_kg_per_m3),
             has ? fixed(r.summary->p_Pa.mean / 1e3, 1) : "—", std::isfinite(p.inertial) ? validation::significant(p.inertial, 3) : "—",
             std::isfinite(p.inertial) ? validation::significant(std::sqrt(p.inertial), 3) : "—", has ? mean_sd(r.summary->q_over_p, 3) : "—",
             has ? fixed(r.summary->phi_deg.mean, 2) : "—",
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
      if (usable(p)) {
        fastest = &p;
        break;
      }
    md << "μ = " << number(s.mu) << ": q/p = " << validation::significant(f.intercept, 3) << " + " << validation::significant(f.slope, 3)
       << " √I over " << f.n << " rates (R² = " << fixed(f.r_squared, 3) << ")";
    if (fastest) {
      const double at = fastest->run->summary->q_over_p.mean;
      md << "; the quasi-static q/p is " << fixed(100 * std::abs(f.intercept / at - 1), 1) << (f.intercept < at ? " % below" : " % above") << " the " << number(fastest->run->rate_per_s)
         << " s⁻¹ value (" << fixed(at, 3) << "), φ " << fixed(s.phi_deg, 2) << "° against "
         << fixed(fastest->run->summary->phi_deg.mean, 2) << "°";
    }
    if (f.n > 2) {
      const double quantile = validation::t_quantile(1 - (1 - validation::prediction_level) / 2, f.n - 2);
      md << ". The standard error rests on " << f.n - 2 << (f.n - 2 == 1 ? " degree" : " degrees") << " of freedom: a "
         << number(100 * validation::prediction_level) << " % interval is ± " << validation::significant(quantile, 3) << " se (± "
         << validation::significant(quantile * f.intercept_se, 2) << " in q/p)";
    }
    md << (s.problems.empty() ? ". q/p changes monotonically with I." : ". ⚠ " + s.problems + ".");
    md << against_reference(s, rows);
    md << "\n\n";
  }
  validation::SectionDoc doc;
  return doc.text("\n").heading(1, "Rate convergence: the critical state at I → 0").text(md.str())
      .figure("rates.png", "critical q/p against the square root of the inertial number, with the fits");
}

}  // namespace sections
