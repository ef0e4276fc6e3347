// section.md: a calibration's tables (posterior_parts.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "discrepancy.hpp"
#include "posterior_parts.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"

namespace calibration {
namespace fs = std::filesystem;

namespace {

std::string interval_text(const Marginal& m) {
  return validation::significant(m.mean, 3) + " ± " + validation::significant(m.sd, 2) + " [" + validation::significant(m.lower_95, 3) +
         ", " + validation::significant(m.upper_95, 3) + "]";
}

// The sets a larger size ran to confirm the posterior's best prediction there (the best scored set,
// or a probe: a new set at the reach's maximum): the probability it
// gave that one sample agrees with every row (its least likely row), and how many rows the set's
// samples then agreed with.
std::string confirmed_markdown(const SizeOutcome& s) {
  std::ostringstream md;
  for (const SizeOutcome::Confirmed& c : s.confirmed) {
    const std::size_t least = static_cast<std::size_t>(
        std::min_element(c.row_probability.begin(), c.row_probability.end()) - c.row_probability.begin());
    md << "To confirm the posterior at " << s.label() << ": set " << c.set
       << validation::chosen_words(c.chosen)
       << ", where it expected one sample to agree with all " << c.rows.size() << " of its rows with probability "
       << validation::significant(c.probability, 2);
    if (!c.rows.empty())
      md << " (the least likely: '" << c.rows[least] << "', " << validation::significant(c.row_probability[least], 2) << ")";
    const auto set = std::find_if(s.sets.begin(), s.sets.end(), [&](const ParameterSet& p) { return p.name == c.set; });
    if (set == s.sets.end() || !set->misfit.valued) {
      md << "; not scored yet.\n\n";
      continue;
    }
    int consistent = 0, judged = 0;
    for (const std::optional<bool>& v : s.verdicts(c))
      if (v) ++judged, consistent += *v;
    if (judged == 0)
      md << "; none of its rows is judged on " << s.seeds.size() << " sample(s) (validate judges a row on 2 or more).\n\n";
    else
      md << "; its samples agree with " << consistent << " of the " << judged << " rows they were judged on.\n\n";
  }
  return md.str();
}

// How far the posterior at a larger size lets its rows be reached (SizeOutcome::reach_*): all at
// once, and the row it reaches least.
std::string reach_markdown(const SizeOutcome& s) {
  if (s.reach_points == 0 || s.reach_most.empty()) return "";
  const std::size_t least =
      static_cast<std::size_t>(std::min_element(s.reach_most.begin(), s.reach_most.end()) - s.reach_most.begin());
  return "At " + std::to_string(s.reach_points) + " random points of the region its surface covers, the largest probability the "
         "posterior at " + s.label() + " gives one sample of agreeing with all " + std::to_string(s.reach_rows.size()) + " of its rows is " +
         validation::significant(s.reach_all, 2) + "; the row whose largest is least: '" + s.reach_rows[least] + "', " +
         validation::significant(s.reach_most[least], 2) + " (`posterior.json`: `sizes`, `reach`).\n\n";
}

// With larger sizes: each size's runs and cost, what the largest changed in each parameter, and
// the discrepancy of each reference row at the posterior's mean.
std::string sizes_markdown(const Report& r) {
  const Outcome& o = r.o;
  const Calibration& c = o.calibration;
  std::ostringstream md;
  validation::MarkdownTable sizes({"size (profile)", "spheres", "samples a set", "sets", "runs", "core-min", "engine", "sets from the ledger"});
  for (const SizeOutcome& s : o.sizes)
    sizes.row({s.label(), s.stamp.spheres > 0 ? std::to_string(s.stamp.spheres) : "not recorded", std::to_string(s.seeds.size()),
               std::to_string(s.sets.size()), std::to_string(s.runs), validation::significant(s.core_seconds / 60, 3),
               s.stamp.engine_source.empty() ? "not recorded" : s.stamp.engine_source,
               std::to_string(s.ledger_sets) + (s.other_engine_sets > 0 ? " (" + std::to_string(s.other_engine_sets) + " scored by engine " +
                                                                               s.other_engine + ")" : "")});
  md << sizes.text() << "\n";
  std::size_t first_sets = o.first().sets.size(), all_sets = 0;
  for (const SizeOutcome& s : o.sizes) all_sets += s.sets.size();
  md << validation::fixed(100.0 * static_cast<double>(first_sets) / static_cast<double>(all_sets), 0) << " % of the "
     << all_sets << " sets run were run at " << o.first().profile << ".\n\n";
  if (o.first_size_only.empty()) return md.str();
  std::vector<std::string> head{"parameter", "at " + o.first().profile + " alone: mean ± sd [95 %]", "at " + o.largest().profile + ": mean ± sd [95 %]"};
  if (!r.truth.empty()) head.push_back("truth");
  validation::MarkdownTable changed(head);
  for (std::size_t k = 0; k < c.parameters.size(); ++k) {
    std::vector<std::string> cells{c.parameters[k].name, interval_text(o.first_size_only[k]), interval_text(r.last.marginals[k])};
    if (const auto t = r.truth.find(c.parameters[k].name); t != r.truth.end()) cells.push_back(validation::significant(t->second, 3));
    else if (!r.truth.empty()) cells.push_back("");
    changed.row(cells);
  }
  md << "What the larger size changed:\n\n" << changed.text() << "\n";
  for (std::size_t k = 1; k < o.sizes.size(); ++k) {
    const SizeOutcome& s = o.sizes[k];
    if (s.discrepancy_pairs == 0) {
      md << "No discrepancy from " << o.sizes[o.base_of(k)].label() << " to " << s.label() << " yet: " << s.sets.size() << " set(s) scored at both, "
         << "at least " << min_discrepancy_pairs << " are needed.\n\n";
      continue;
    }
    md << "The discrepancy from " << o.sizes[o.base_of(k)].label() << " to " << s.label() << " (" << (s.discrepancy_linear ? "linear" : "a constant")
       << " in the parameters, fitted to " << s.discrepancy_pairs << " sets run at both), at the posterior's mean:\n\n";
    validation::MarkdownTable t({"reference", "largest |shift| over its points ± its sd", "at point"});
    for (const SizeOutcome::Change& ch : s.changes) {
      std::size_t at = 0;
      for (std::size_t j = 1; j < ch.shift.size(); ++j)
        if (std::abs(ch.shift[j]) > std::abs(ch.shift[at])) at = j;
      t.row({ch.row, validation::significant(ch.shift[at], 3) + " ± " + validation::significant(ch.shift_sd[at], 2), std::to_string(at + 1)});
    }
    md << t.text() << "\n" << reach_markdown(s) << confirmed_markdown(s);
  }
  return md.str();
}

std::string parameters_markdown(const Report& r) {
  const Outcome& o = r.o;
  const Calibration& c = o.calibration;
  std::vector<std::string> head{"parameter", "prior", "posterior mean ± sd", "95 % interval", "prior sd / posterior sd", "identified"};
  if (!r.truth.empty()) head.insert(head.begin() + 2, "truth");
  validation::MarkdownTable t(head);
  for (std::size_t k = 0; k < c.parameters.size(); ++k) {
    const Parameter& p = c.parameters[k];
    const Marginal& m = r.last.marginals[k];
    // A parameter of values: the posterior's share of each value (its mean of indices means nothing).
    std::vector<std::string> cells{p.name, prior_text(p),
                                   p.discrete() ? value_shares(p, k, o)
                                                : validation::significant(m.mean, 3) + " ± " + validation::significant(m.sd, 2),
                                   p.discrete() ? "—" : "[" + validation::significant(m.lower_95, 3) + ", " + validation::significant(m.upper_95, 3) + "]",
                                   validation::significant(m.narrowing, 2),
                                   m.identified ? "yes" : "no: the references barely narrow its prior"};
    if (!r.truth.empty()) {
      const auto tr = r.truth.find(p.name);
      cells.insert(cells.begin() + 2, tr == r.truth.end() ? "" :
                   validation::significant(tr->second, 3) + (tr->second >= m.lower_95 && tr->second <= m.upper_95 ? " (inside)" : " (OUTSIDE)"));
    }
    t.row(cells);
  }
  std::string text = t.text() + "\n";
  if (c.parameters.size() > 1) {
    std::vector<std::string> ch{"correlation"};
    for (const Parameter& p : c.parameters) ch.push_back(p.name);
    validation::MarkdownTable ct(ch);
    for (std::size_t a = 0; a < c.parameters.size(); ++a) {
      std::vector<std::string> cells{c.parameters[a].name};
      for (std::size_t b = 0; b < c.parameters.size(); ++b)
        cells.push_back(validation::fixed(r.correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)), 2));
      ct.row(cells);
    }
    text += ct.text() + "\n";
  }
  return text;
}

std::string best_set_markdown(const Calibration& c, const ParameterSet& best, const std::string& where) {
  std::ostringstream md;
  md << "Best set" << where << " " << best.name << " (χ² " << validation::significant(best.misfit.chi2, 3) << "):";
  for (std::size_t k = 0; k < c.parameters.size(); ++k)
    md << " " << c.parameters[k].name << " = "
       << (c.parameters[k].discrete() ? c.parameters[k].value_text(best.u(static_cast<Eigen::Index>(k)))
                                      : validation::significant(c.parameters[k].value(best.u(static_cast<Eigen::Index>(k))), 4))
       << (k + 1 < c.parameters.size() ? "," : ".");
  md << "\n";
  validation::MarkdownTable rows({"reference", "points", "χ² at the best set", "χ² per point"});
  for (const RowMisfit& m : best.misfit.rows)
    rows.row({m.name, std::to_string(m.points), validation::significant(m.chi2, 3),
              m.points > 0 ? validation::significant(m.chi2 / m.points, 2) : ""});
  md << "\n" << rows.text();
  return md.str();
}

}  // namespace

std::string section_markdown(const Report& r) {
  const Outcome& o = r.o;
  const Calibration& c = o.calibration;
  const std::vector<ParameterSet>& sets = o.first().sets;
  int runs = 0, ledger_sets = 0;
  for (const SizeOutcome& s : o.sizes) runs += s.runs, ledger_sets += s.ledger_sets;
  std::ostringstream md;
  md << "Calibration `" << c.name << "` of the study `" << fs::path(c.study).filename().string() << "` (";
  if (o.sizes.size() == 1) md << "profile " << o.first().profile << ", " << o.first().seeds.size() << " sample(s) per set";
  else
    for (std::size_t k = 0; k < o.sizes.size(); ++k)
      md << (k ? "; " : "sizes: ") << o.sizes[k].label() << ", " << o.sizes[k].seeds.size() << " sample(s) per set";
  md << ") against " << o.references.source << ". Engine " << o.engine << ".\n\n";
  md << sets.size() << " parameter sets in " << o.iterations.size() << (o.iterations.size() == 1 ? " iteration of " : " iterations of ")
     << c.batch << " (" << runs << " runs, " << validation::significant(o.core_seconds() / 60, 3) << " core-min recorded); effective sample size "
     << validation::significant(r.last.ess, 3) << ".\n\n" << (o.converged ? "Converged: " : "Not converged: ") << o.stop_reason << ".\n\n";
  if (ledger_sets > 0)
    md << ledger_sets << " of the sets were scored in earlier calls whose runs' results are not kept here: their scores come "
       << "from the ledgers (`scored_sets*.json`), which record each set's run hashes and misfit.\n\n";
  for (const SizeOutcome& s : o.sizes)
    if (s.verified_sets > 0)
      md << s.verified_sets << " of them" << (o.sizes.size() > 1 ? " (at " + s.profile + ")" : "") << " were " << s.verified_by << ".\n\n";
  const auto short_of = std::count_if(sets.begin(), sets.end(), [](const ParameterSet& s) { return !s.misfit.left_out.empty(); });
  if (short_of > 0)
    md << short_of << " of the sets " << (short_of == 1 ? "was" : "were")
       << " scored without a sample some run of which did not finish (`posterior.json`: `samples_left_out`).\n\n";
  if (!o.posterior_from.empty()) {
    md << "The posterior is sampled on a response surface (a quadratic in the parameters per curve point and per scalar row) fitted "
          "to the "
       << o.surface_sets << " sets nearest it, at " << o.posterior_u.size() << " points: the sets' own misfits carry the noise of "
       << "their samples";
    if (o.surface_noise > 0)
      md << " (their scatter about the surface is " << validation::significant(o.surface_noise, 2) << " times the reference mean's sd, on average)";
    md << ", which would let the luckiest set carry the posterior.\n\n";
  }
  if (o.sizes.size() > 1) md << sizes_markdown(r);
  md << parameters_markdown(r);
  validation::MarkdownTable it({"iteration", "sets", "scored (all so far)", "effective points of the posterior", "largest move"});
  for (const IterationSummary& s : o.iterations)
    it.row({std::to_string(s.number), std::to_string(s.sets), std::to_string(s.valued), validation::significant(s.ess, 3),
            s.number == 1 ? "" : validation::fixed(s.moved, 3)});
  md << it.text() << "\n";
  md << best_set_markdown(c, sets[r.best], o.sizes.size() > 1 ? " at " + o.first().profile : "");
  if (r.verdicts.rows > 0) md << "\n" << rows_markdown(r.verdicts, sets);
  for (const Report::Part& part : r.parts) {
    const SizeOutcome& size = o.sizes[part.size];
    if (!part.best) continue;
    md << "\n" << best_set_markdown(c, size.sets[*part.best], " at " + size.label());
    if (part.verdicts.rows > 0) md << "\n" << rows_markdown(part.verdicts, size.sets);
  }
  if (r.best_largest) {
    md << "\n" << best_set_markdown(c, o.largest().sets[*r.best_largest], " at " + o.largest().profile);
    if (r.largest_verdicts.rows > 0) md << "\n" << rows_markdown(r.largest_verdicts, o.largest().sets);
  }
  return md.str();
}

}  // namespace calibration
