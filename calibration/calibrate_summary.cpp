// The calibration loop's account of an iteration: what it scored, where its posterior comes from,
// whether it has settled (and why not).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "config/yaml_section.hpp"
#include "loop.hpp"
#include "study/format.hpp"

namespace calibration {

namespace {

double largest_move(const std::vector<Marginal>& a, const std::vector<Marginal>& b) {
  double moved = 0;
  for (std::size_t j = 0; j < a.size(); ++j)
    moved = std::max({moved, std::abs(a[j].unit_mean - b[j].unit_mean), std::abs(a[j].unit_sd - b[j].unit_sd)});
  return moved;
}

// The first row of the last set that has no value, and why ("no rows" when it has none).
std::string why_unscored(const ParameterSet& s) {
  if (!s.stopped.empty()) return "the engine stopped a run of it: " + s.stopped;
  if (s.misfit.rows.empty()) return "no rows";
  for (const RowMisfit& m : s.misfit.rows)
    if (!m.valued) return m.name + ": " + m.note;
  if (!s.misfit.left_out.empty()) return "too few samples with every run finished (" + s.misfit.left_out.front() + ")";
  return "no row says why";
}

// " (2 not scored: they weigh nothing; i1s002: ...)", or "" when every set is scored.
std::string unscored_text(const Outcome& out) {
  if (out.unscored.empty()) return "";
  return " (" + std::to_string(out.unscored.size()) + " not scored: they weigh nothing; " + out.unscored.front() +
         (out.unscored.size() > 1 ? "; ..." : "") + ")";
}

std::string posterior_source(const Outcome& out) {
  if (out.posterior_from.empty()) return "the sets' weights";
  std::string text = "a response surface over " + std::to_string(out.surface_sets) + " sets";
  for (std::size_t k = 1; k < out.sizes.size(); ++k)
    text += out.sizes[k].discrepancy_pairs > 0 ? " plus a discrepancy to " + out.sizes[k].label() + " over " +
                                                     std::to_string(out.sizes[k].discrepancy_pairs) + " sets"
                                             : " (" + out.sizes[k].label() + ": too few sets for a discrepancy yet)";
  return text;
}

}  // namespace

IterationSummary summarize(Loop& l, int it, bool after_named) {
  const Outcome& out = l.out;
  const Calibration& c = l.c;
  const std::vector<ParameterSet>& sets = out.first().sets;
  IterationSummary summary;
  summary.number = it;
  summary.sets = c.batch;
  summary.valued = static_cast<int>(std::count_if(sets.begin(), sets.end(), [](const auto& s) { return s.misfit.valued; }));
  if (summary.valued == 0)
    throw dem::ConfigError("no parameter set of iteration " + std::to_string(it) + " could be scored: " + why_unscored(sets.back()));
  l.out.unscored.clear();
  for (const ParameterSet& s : sets)
    if (!s.misfit.valued) l.out.unscored.push_back(s.name + ": " + why_unscored(s));
  summary.ess = effective_sample_size(out.posterior_w);
  summary.sets_ess = effective_sample_size(out.weights);
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    summary.marginals.push_back(marginal(c.parameters[j], j, out.posterior_u, out.posterior_w));
  // On a surface, the posterior's mean +- 2 sd must lie inside the region it was fitted in.
  summary.contained = true;
  if (!out.posterior_from.empty())
    for (std::size_t j = 0; j < c.parameters.size(); ++j) {
      const Eigen::Index k = static_cast<Eigen::Index>(j);
      summary.contained &= std::abs(summary.marginals[j].unit_mean - out.region_centre(k)) + 2 * summary.marginals[j].unit_sd <=
                           out.region_sd(k);
    }
  // The named sets change the last iteration's posterior, not how far the iteration moved it.
  summary.moved = after_named ? out.iterations.back().moved : l.before.empty() ? 1 : largest_move(l.before, summary.marginals);
  l.before = summary.marginals;
  const std::string step = after_named ? "iteration " + std::to_string(it) + " with the named sets" : "iteration " + std::to_string(it);
  std::printf("[calibrate] %s: %d of %zu sets scored%s; posterior from %s (effective sample size %.1f), moved %.3f of "
              "the prior ranges;", step.c_str(), summary.valued, sets.size(), unscored_text(out).c_str(), posterior_source(out).c_str(),
              summary.ess, summary.moved);
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    std::printf(" %s %.4g +- %.3g", c.parameters[j].name.c_str(), summary.marginals[j].mean, summary.marginals[j].sd);
  std::printf("\n");
  std::fflush(stdout);
  return summary;
}

// Whether the posterior has settled after iteration `it` (then out.stop_reason says why). With
// larger sizes, only once each has spent its sets and has its discrepancy.
bool settled(Loop& l, int it, const IterationSummary& summary) {
  const Calibration& c = l.c;
  if (it < c.min_iterations || summary.moved > c.tolerance || summary.ess < c.min_effective_sets || !summary.contained) return false;
  for (std::size_t k = 1; k < l.out.sizes.size(); ++k)
    if (static_cast<int>(l.out.sizes[k].sets.size()) < l.out.sizes[k].sets_in_iterations() || l.out.sizes[k].discrepancy_pairs == 0)
      return false;
  l.out.converged = true;
  l.out.stop_reason = "no posterior mean or sd moved by more than " + validation::significant(c.tolerance, 3) + " of its prior range (" +
                      validation::significant(summary.moved, 2) + ") in iteration " + std::to_string(it) +
                      ", and the posterior rests on " + validation::significant(summary.ess, 3) + " effective points (at least " +
                      validation::significant(c.min_effective_sets, 3) + " asked)" +
                      (l.out.posterior_from.empty() ? "" : " inside the region of its response surface");
  return true;
}

std::string unsettled_reason(const Calibration& c, const Outcome& out) {
  const IterationSummary& last = out.iterations.back();
  return "max_iterations (" + std::to_string(c.max_iterations) + ") reached before the posterior settled (it moved " +
         validation::significant(last.moved, 2) + " of a prior range in the last iteration and rests on " +
         validation::significant(last.ess, 3) + " effective points, " + validation::significant(c.min_effective_sets, 3) + " asked" +
         (last.contained ? "" : "; its mean +- 2 sd reaches out of its response surface's region") + ")";
}

}  // namespace calibration
