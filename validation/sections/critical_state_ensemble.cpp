// compare-runs critical-state --ensemble: the mean and sd over the samples of the ensemble study's
// runs, per loading and μ (critical_state_parts.hpp).
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

using validation::fixed;
using validation::number;

namespace {

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

}  // namespace

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

validation::SectionDoc ensemble_section(const std::vector<EnsembleGroup>& groups, const std::vector<ShearRun>& main_runs, const std::string& folder,
                                        std::size_t samples, double cs_from, double cs_to) {
  std::ostringstream md;
  md << "\n";
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
  validation::SectionDoc doc;
  return doc.text("\n").heading(1, "The critical state on " + std::to_string(samples) + " samples").text(md.str());
}

}  // namespace sections
