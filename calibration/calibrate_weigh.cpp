// Weighing the sets: the first size's response surface and posterior; the larger sizes' sets,
// chosen where they inform the posterior most, and their discrepancies (discrepancy.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "discrepancy.hpp"
#include "loop.hpp"
#include "config/yaml_section.hpp"
#include "study/format.hpp"
#include "study/series.hpp"

namespace calibration {

namespace {

// A posterior with no finite weight is no posterior: every set's likelihood is 0 (its chi^2
// infinite) or not a number. Reported, the zeros would show a corner of the prior as the
// posterior, sd 0, "identified": an error instead, naming a set's row whose chi^2 is not finite.
void require_weight(const Outcome& out) {
  const auto positive = [](const std::vector<double>& w) {
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    return std::isfinite(total) && total > 0;
  };
  if (positive(out.weights) && positive(out.posterior_w)) return;
  std::string example;
  for (const ParameterSet& s : out.first().sets)
    for (const RowMisfit& m : s.misfit.rows)
      if (example.empty() && m.valued && !std::isfinite(m.chi2))
        example = " (set " + s.name + ": '" + m.name + "' has chi^2 " + validation::format_number(m.chi2) + ")";
  throw dem::ConfigError("no parameter set has a finite weight: the chi^2 of every set scored is infinite or not a number" + example +
                         ", so there is no posterior; check the sd and tolerances of " + out.references.file +
                         " (a point or row whose sd and tolerance are 0 cannot be missed by any run); nothing was reported");
}

// Every set of the first size weighted again; the posterior: on a response surface fitted to the
// sets near it (surrogate.hpp), when enough sets are scored; else the sets' own weights. The
// surface's region: the Gaussian this iteration drew from (the first: one fitted to the best sets).
}  // namespace

void weigh(Loop& l, int it) {
  Outcome& out = l.out;
  std::vector<Eigen::VectorXd> u;
  std::vector<double> log_likelihood;
  for (const ParameterSet& s : out.first().sets) u.push_back(s.u), log_likelihood.push_back(s.drawn_log_likelihood());
  out.weights = importance_weights(u, log_likelihood, l.proposals, l.drawn);
  const Proposal region = it > 1 ? l.proposals.back()
                                 : fit_proposal(u, proposal_weights(u, log_likelihood, l.proposals, l.drawn, 2.0 * quadratic_terms(l.dimensions())), 0);
  out.posterior_from.clear();
  out.posterior_u = u, out.posterior_w = out.weights;
  l.surface = fit_surface(out.references, out.first().sets, region);
  if (l.surface) {
    std::vector<Eigen::VectorXd> pu;
    std::vector<double> pw;
    sample_surface(*l.surface, out.references, 4000, pu, pw);
    if (!pu.empty()) {
      out.posterior_u = std::move(pu), out.posterior_w = std::move(pw);
      out.surface_sets = l.surface->sets;
      out.surface_noise = l.surface->noise_to_reference;
      out.posterior_from = "response surface";
      out.region_centre = l.surface->centre;
      out.region_sd = l.surface->scale * l.surface->radius;
    } else {
      l.surface.reset();
    }
  }
  require_weight(out);
  l.first_u = out.posterior_u, l.first_w = out.posterior_w;
}


namespace {

Eigen::VectorXd mean_of(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(u.front().size());
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (std::size_t i = 0; i < u.size(); ++i) m += w[i] / total * u[i];
  return m;
}

// Each reference row's discrepancy at u, point by point, with its prediction sd.
std::vector<SizeOutcome::Change> changes_at(const Outcome& out, const Discrepancy& delta, const Eigen::VectorXd& u) {
  std::vector<SizeOutcome::Change> changes;
  const Eigen::VectorXd x = delta.features(u);
  const auto add = [&](const std::string& row, const std::vector<Quadratic>& qs) {
    if (std::none_of(qs.begin(), qs.end(), covers)) return;  // outside a part of a size
    SizeOutcome::Change c{row, {}, {}};
    for (const Quadratic& q : qs) c.shift.push_back(q.value(x)), c.shift_sd.push_back(std::sqrt(q.variance(x)));
    changes.push_back(std::move(c));
  };
  for (std::size_t c = 0; c < out.references.curves.size(); ++c) add(out.references.curves[c].name, delta.curves[c]);
  for (std::size_t r = 0; r < out.references.rows.size(); ++r) add(out.references.rows[r].name, {delta.rows[r]});
  return changes;
}

// The scalar rows (indices into the references) a discrepancy covers: those of its part of a size.
std::vector<std::size_t> rows_covered(const References& refs, const Discrepancy& delta) {
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < refs.rows.size(); ++r)
    if (covers(delta.rows[r])) rows.push_back(r);
  return rows;
}

// Whether the posterior at size k predicts its rows: the first size has its surface and size k its
// discrepancy. Then each larger size's discrepancy fitted so far, and the names of `rows`.
bool predicts(const Loop& l, std::size_t k) { return l.surface && k < l.deltas.size() && l.deltas[k]; }
std::vector<Discrepancy> fitted_deltas(const Loop& l) {
  std::vector<Discrepancy> out;
  for (const std::optional<Discrepancy>& d : l.deltas)
    if (d) out.push_back(*d);
  return out;
}
std::vector<std::string> row_names(const References& refs, const std::vector<std::size_t>& rows) {
  std::vector<std::string> names;
  for (const std::size_t r : rows) names.push_back(refs.rows[r].name);
  return names;
}

// After its budget, size k's next set to confirm the posterior's best prediction there, once the
// size has its discrepancy and the first size its surface (discrepancy.hpp, choose_to_confirm).
std::vector<std::size_t> choose_to_confirm(Loop& l, std::size_t k, const std::vector<const ParameterSet*>& candidates,
                                           const std::vector<Eigen::VectorXd>& candidate_u) {
  SizeOutcome& so = l.out.sizes[k];
  if (so.confirmed_of_kind(validation::Choice::best) >= so.confirm || !predicts(l, k)) return {};
  const std::vector<std::size_t> rows = rows_covered(l.out.references, *l.deltas[k]);
  const std::optional<Confirmation> c = choose_to_confirm(*l.surface, fitted_deltas(l), candidate_u, rows);
  if (!c) return {};
  so.confirmed.push_back({candidates[c->index]->name, c->probability, row_names(l.out.references, rows), c->row_probability,
                          validation::Choice::best});
  return {c->index};
}

// Set s as a confirmed set of size k, chosen as `chosen`: the probability the posterior at size k
// gives that one sample of it agrees with each of the size's rows, and with all (their product).
SizeOutcome::Confirmed predicted(const Loop& l, std::size_t k, const ParameterSet& s, validation::Choice chosen) {
  const std::vector<std::size_t> rows = rows_covered(l.out.references, *l.deltas[k]);
  SizeOutcome::Confirmed c{s.name, 1, row_names(l.out.references, rows), {}, chosen};
  const std::vector<double> p = l.surface->row_probabilities(s.u, fitted_deltas(l));
  for (const std::size_t r : rows) c.row_probability.push_back(p[r]), c.probability *= p[r];
  return c;
}

// The uniform points a reach draws (those inside the surface's region count).
constexpr int reach_points = 20000;

// After its confirm sets, size k's next probe, once the size has its discrepancy and the first size
// its surface: a new set at the reach's maximum (discrepancy.hpp), added to the first size's sets
// too, where it runs for its discrepancy pair. False when there is none yet.
bool probe(Loop& l, std::size_t k, int it) {
  SizeOutcome& so = l.out.sizes[k];
  if (so.confirmed_of_kind(validation::Choice::probe) >= so.probe || !predicts(l, k)) return false;
  const std::vector<Discrepancy> larger = fitted_deltas(l);
  const std::vector<std::size_t> rows = rows_covered(l.out.references, *l.deltas[k]);
  const Reach reached = reach(*l.surface, larger, rows, reach_points);
  if (reached.all_best.size() == 0) return false;
  ParameterSet s;
  s.name = probe_set_name(it, k), s.u = reached.all_best, s.iteration = it, s.drawn = false;
  const SizeOutcome::Confirmed c = predicted(l, k, s, validation::Choice::probe);
  std::printf("[calibrate] iteration %d: size %s runs the new set %s at the reach's maximum, where the posterior expects one sample to "
              "agree with all %zu of its rows with probability %.3g (best of %d points; %zu of at most %d there); the first size runs it too\n",
              it, so.label().c_str(), s.name.c_str(), rows.size(), reached.all_most, reached.points, so.sets.size() + 1, so.sets_at_most());
  std::fflush(stdout);
  so.confirmed.push_back(std::move(c));
  l.out.first().sets.push_back(s);
  so.sets.push_back(std::move(s));
  return true;
}

}  // namespace

void choose_larger_sets(Loop& l, std::size_t k, int it) {
  SizeOutcome& so = l.out.sizes[k];
  const int room = std::min(l.c.sizes[k].per_iteration, so.budget - static_cast<int>(so.sets.size()));
  if (room <= 0 && so.confirmed_of_kind(validation::Choice::best) >= so.confirm) {
    probe(l, k, it);
    return;
  }
  std::vector<const ParameterSet*> candidates;
  std::vector<Eigen::VectorXd> candidate_u, chosen_u;
  for (const ParameterSet& s : so.sets) chosen_u.push_back(s.u);
  for (const ParameterSet& s : l.out.sizes[base_of(l.out, k)].sets)
    if (s.misfit.valued && std::none_of(so.sets.begin(), so.sets.end(), [&](const ParameterSet& t) { return t.name == s.name; }))
      candidates.push_back(&s), candidate_u.push_back(s.u);
  // Near the posterior at the largest size so far, else the first size's; after the budget, the
  // sets to confirm.
  const bool larger = !l.larger_u.empty();
  const std::vector<std::size_t> picked =
      room > 0 ? choose_for_larger_size(candidate_u, chosen_u, larger ? l.larger_u : l.out.posterior_u,
                                        larger ? l.larger_w : l.out.posterior_w, room)
               : choose_to_confirm(l, k, candidates, candidate_u);
  if (room <= 0 && picked.empty()) return;
  std::string names;
  for (const std::size_t i : picked) {
    ParameterSet s;
    s.name = candidates[i]->name, s.u = candidates[i]->u, s.iteration = it;
    so.sets.push_back(std::move(s));
    names += (names.empty() ? "" : ", ") + candidates[i]->name;
  }
  if (room <= 0)
    std::printf("[calibrate] iteration %d: size %s runs %s to confirm the posterior there, which expects it to agree with all %zu "
                "of its rows with probability %.3g (%zu of at most %d there)\n", it, so.label().c_str(), names.c_str(),
                so.confirmed.back().rows.size(), so.confirmed.back().probability, so.sets.size(), so.sets_at_most());
  else
    std::printf("[calibrate] iteration %d: size %s runs %s (%zu of at most %d there)\n", it, so.label().c_str(),
                names.empty() ? "no set" : names.c_str(), so.sets.size(), so.sets_at_most());
  std::fflush(stdout);
}

bool choose_named(Loop& l, std::size_t k, int it) {
  SizeOutcome& so = l.out.sizes[k];
  bool added = false;
  for (const std::string& name : so.named) {
    if (std::any_of(so.sets.begin(), so.sets.end(), [&](const ParameterSet& s) { return s.name == name; })) continue;
    const std::vector<ParameterSet>& base = l.out.sizes[base_of(l.out, k)].sets;
    const auto found = std::find_if(base.begin(), base.end(), [&](const ParameterSet& s) { return s.name == name; });
    if (found == base.end() || !found->misfit.valued)
      throw dem::ConfigError(l.c.file + ": sizes[" + std::to_string(k) + "].named: '" + name + "' is not a set " +
                             l.out.sizes[base_of(l.out, k)].label() + " scored in the " + std::to_string(it) +
                             " iterations (its sets are named i<iteration>s<number> and i<iteration>p<size>)");
    ParameterSet s;
    s.name = found->name, s.u = found->u, s.iteration = it;
    if (predicts(l, k)) {
      so.confirmed.push_back(predicted(l, k, s, validation::Choice::named));
      std::printf("[calibrate] after the iterations: size %s runs %s, named in the calibration file; the posterior there expects it to "
                  "agree with all %zu of its rows with probability %.3g\n", so.label().c_str(), name.c_str(),
                  so.confirmed.back().rows.size(), so.confirmed.back().probability);
    } else {
      std::printf("[calibrate] after the iterations: size %s runs %s, named in the calibration file\n", so.label().c_str(), name.c_str());
    }
    std::fflush(stdout);
    so.sets.push_back(std::move(s));
    added = true;
  }
  return added;
}

void weigh_larger(Loop& l) {
  Outcome& out = l.out;
  if (out.sizes.size() < 2) return;
  out.first_size_only.clear();
  for (std::size_t j = 0; j < l.c.parameters.size(); ++j)
    out.first_size_only.push_back(marginal(l.c.parameters[j], j, l.first_u, l.first_w));
  std::vector<Discrepancy> deltas;
  l.deltas.assign(out.sizes.size(), std::nullopt);
  for (std::size_t k = 1; k < out.sizes.size(); ++k) {
    SizeOutcome& so = out.sizes[k];
    so.discrepancy_pairs = 0, so.discrepancy_linear = false, so.changes.clear();
    // A part's discrepancy: on its own curves and rows (the base's sets' misfits cut to them),
    // then extended to every reference, covering nothing outside the part.
    const References& part = l.at[k].refs;
    std::vector<ParameterSet> base = out.sizes[base_of(out, k)].sets;
    if (!so.densities.empty())
      for (ParameterSet& s : base) s.misfit = projected(s.misfit, out.references, part);
    std::optional<Discrepancy> delta = fit_discrepancy(part, base, so.sets);
    if (delta && !so.densities.empty()) delta = extended(*delta, part, out.references);
    if (delta) {
      so.discrepancy_pairs = delta->pairs, so.discrepancy_linear = delta->linear;
      so.changes = changes_at(out, *delta, mean_of(l.first_u, l.first_w));
      deltas.push_back(*delta);
      l.deltas[k] = delta;
    }
  }
  // Until every size has its discrepancy the posterior stays the first size's (posterior_source says so).
  if (!l.surface || deltas.size() + 1 < out.sizes.size()) return;
  for (std::size_t k = 1; k < out.sizes.size(); ++k) {
    SizeOutcome& so = out.sizes[k];
    const std::vector<std::size_t> rows = rows_covered(out.references, *l.deltas[k]);
    so.reach_rows = row_names(out.references, rows);
    const Reach reached = reach(*l.surface, deltas, rows, reach_points);
    so.reach_points = reached.points, so.reach_most = reached.row_most, so.reach_all = reached.all_most;
  }
  std::vector<Eigen::VectorXd> pu;
  std::vector<double> pw;
  sample_surface(*l.surface, deltas, out.references, 4000, pu, pw);
  if (pu.empty()) return;
  out.posterior_u = pu, out.posterior_w = pw;
  l.larger_u = std::move(pu), l.larger_w = std::move(pw);
  require_weight(out);
}

}  // namespace calibration
