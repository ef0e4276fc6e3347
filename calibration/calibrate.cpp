#include "calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <set>
#include <utility>

#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "exec/slurm.hpp"
#include "loop.hpp"
#include "plan/plan_cost.hpp"
#include "study/format.hpp"
#include "study/series.hpp"
#include "sets.hpp"

namespace calibration {
namespace fs = std::filesystem;

namespace {

// What a run cost, from its result: its core-seconds (wall time x threads) and particle-steps;
// a copy, or a run not finished: nothing.
struct RunCost {
  double core_seconds = 0, particle_steps = 0;
};
RunCost recorded_cost(const pipeline::PlannedRun& r, int threads) {
  if (r.copy_of >= 0) return {};
  const auto cost = pipeline::result_cost(r.result);
  if (!cost || !cost->wall_s) return {};
  return {*cost->wall_s * threads, cost->particle_steps};
}

double recorded_core_seconds(const std::vector<pipeline::PlannedRun>& runs, int threads) {
  double seconds = 0;
  for (const pipeline::PlannedRun& r : runs) seconds += recorded_cost(r, threads).core_seconds;
  return seconds;
}

// Each set's share of the runs it needs and of their recorded cost: a run shared by k sets counts
// 1/k for each, so that the shares add up to the plan's runs and cost.
struct RunShare {
  double runs = 0;
  RunCost cost;
};
std::map<std::string, RunShare> run_shares(const std::vector<pipeline::PlannedRun>& runs, int threads) {
  std::map<std::string, RunShare> out;
  for (const pipeline::PlannedRun& r : runs) {
    const RunCost cost = recorded_cost(r, threads);
    const double k = static_cast<double>(r.variants.size());
    for (const std::string& v : r.variants) {
      RunShare& share = out[v];
      share.runs += 1 / k, share.cost.core_seconds += cost.core_seconds / k, share.cost.particle_steps += cost.particle_steps / k;
    }
  }
  return out;
}

// Each set is a variant of the study: its parameters' keys obey the rules of a variant's (no `name`,
// no seed of an ensemble, ...), checked as the pipeline checks a study's, naming the parameter.
void check_parameter_keys(const Calibration& c, const pipeline::Study& study) {
  const bool ensemble = std::any_of(study.profiles.begin(), study.profiles.end(), [](const auto& p) { return !p.seeds.empty(); });
  for (std::size_t j = 0; j < c.parameters.size(); ++j) {
    const Parameter& p = c.parameters[j];
    const std::string scope = p.applies_to == "both" ? "set" : p.applies_to;
    for (const std::string& key : p.keys)
      if (const std::string why = pipeline::override_key_refusal(key, scope, ensemble, !study.tests.empty()); !why.empty())
        throw dem::ConfigError(c.file + ": parameters[" + std::to_string(j) + "] (" + p.name + "): keys: '" + key + "' " + why +
                               " (in the study " + c.study + ", applies_to: " + p.applies_to + ")");
  }
}

// Check every parameter's densities and every curve row's density and test are the study's
// before anything runs.
void check_inputs(const Calibration& c, const pipeline::Study& study, const References& refs) {
  check_parameter_keys(c, study);
  for (const Parameter& p : c.parameters)
    for (const std::string& density : p.densities)
      if (std::none_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == density; }))
        throw dem::ConfigError(c.file + ": parameters: " + p.name + ": densities: '" + density + "' is not a density of the study " +
                               c.study);
  for (const Size& size : c.sizes)
    for (const std::string& density : size.densities)
      if (std::none_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == density; }))
        throw dem::ConfigError(c.file + ": sizes: " + size.profile + ": densities: '" + density + "' is not a density of the study " + c.study);
  for (const CurveRow& row : refs.curves) {
    const bool density = std::any_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == row.density; });
    const bool test = std::any_of(study.tests.begin(), study.tests.end(), [&](const auto& t) { return t.name == row.test; });
    if (!density || !test)
      throw dem::ConfigError(refs.file + ": curve '" + row.name + "' reads " + row.density + " " + row.test +
                             ", which the study " + c.study + " does not run");
  }
}

// The ledger of size k: scored_sets.json for the first size (or the only one), scored_sets.<profile>.json
// for a larger one.
std::string ledger_file(const Calibration& c, std::size_t k, const std::string& profile) {
  return (fs::path(c.report) / (k == 0 ? std::string("scored_sets.json") : "scored_sets." + profile + ".json")).string();
}

void start(Loop& l) {
  const Calibration& c = l.c;
  l.out.calibration = c;
  l.study = pipeline::load_study(c.study);
  if (!l.study.variants.empty())
    throw dem::ConfigError(c.file + ": study: " + c.study + " has variants; a calibration's sets are its variants, so its study has none");
  if (!c.sizes.empty() && !l.o.profile.empty())
    throw dem::ConfigError("--profile " + l.o.profile + " is given, but " + c.file + " names its profiles in sizes: leave --profile out");
  std::vector<Size> sizes = c.sizes;
  if (sizes.empty()) sizes.emplace_back().profile = l.o.profile.empty() ? l.study.default_profile().name : l.o.profile;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const pipeline::Profile* profile = nullptr;
    try {
      profile = &l.study.profile(sizes[k].profile);
    } catch (const std::exception& e) {
      if (c.sizes.empty()) throw;
      throw dem::ConfigError(c.file + ": sizes[" + std::to_string(k) + "].profile: " + e.what());
    }
    SizeOutcome so;
    so.profile = profile->name;
    so.densities = sizes[k].densities;
    so.seeds = profile->seeds;
    so.budget = sizes[k].sets;
    so.confirm = sizes[k].confirm;
    so.probe = sizes[k].probe;
    so.named = sizes[k].named;
    // A part of a size has its own results folder and ledger: profile-dense-medium.
    std::string name = profile->name;
    for (const std::string& d : so.densities) name += "-" + d;
    so.results = (fs::path(l.study.output) / ("calibration_" + c.name) / name).lexically_normal().string();
    l.out.sizes.push_back(std::move(so));
    SizeState state;
    state.profile = profile;
    state.ledger_file = ledger_file(c, k, name);
    state.study = l.study;
    if (!sizes[k].densities.empty())
      std::erase_if(state.study.densities, [&](const auto& d) {
        return std::find(sizes[k].densities.begin(), sizes[k].densities.end(), d.name) == sizes[k].densities.end();
      });
    l.at.push_back(std::move(state));
  }
  // The references as judged at the largest size: a row's tolerance may be a profile's.
  l.out.references = read_references(c.references, l.out.largest().profile);
  l.out.engine = pipeline::engine_version(l.o.dem);
  if (l.out.engine.empty()) throw dem::ConfigError("cannot run the engine '" + l.o.dem + " --source-hash'");
  check_inputs(c, l.study, l.out.references);
  for (std::size_t k = 0; k < l.at.size(); ++k) {
    SizeState& state = l.at[k];
    state.refs = l.out.sizes[k].densities.empty() ? l.out.references : only_densities(l.out.references, l.out.sizes[k].densities);
    if (state.refs.curves.empty() && state.refs.rows.empty())
      throw dem::ConfigError(c.file + ": sizes: " + l.out.sizes[k].label() + ": the references have no curve or row of its densities");
    for (const auto& [key, n] : {std::pair{"confirm", l.out.sizes[k].confirm}, std::pair{"probe", l.out.sizes[k].probe}})
      if (n > 0 && state.refs.rows.empty())
        throw dem::ConfigError(c.file + ": sizes[" + std::to_string(k) + "]." + key + ": " + l.out.sizes[k].label() +
                               " has no scalar row of the references (such a set is chosen and judged on rows): give 0 or add rows");
    if (l.out.sizes[k].probe > 0 && l.out.base_of(k) != 0)
      throw dem::ConfigError(c.file + ": sizes[" + std::to_string(k) + "].probe: " + l.out.sizes[k].label() +
                             " chooses its sets from " + l.out.sizes[l.out.base_of(k)].label() + ", not from the first size, which runs "
                             "a probe for its pair: give 0, or probe at the second size or at a part of the largest");
    state.ledger = read_ledger(state.ledger_file, state.refs);
  }
}

// The iteration's batch, from the prior (the first) or from a proposal fitted after the sets so
// far: to the posterior on the response surface when there is one, else to the sets' weights
// tempered to span at least the best 2d + 2 sets.
void draw_batch(Loop& l, int it) {
  std::vector<Eigen::VectorXd> all_u;
  std::vector<double> all_ll;
  std::vector<ParameterSet>& sets = l.out.first().sets;
  for (const ParameterSet& s : sets) all_u.push_back(s.u), all_ll.push_back(s.drawn_log_likelihood());
  const Proposal q = it == 1                         ? Proposal{}
                     : !l.out.posterior_from.empty() ? fit_proposal(l.out.posterior_u, l.out.posterior_w, l.c.prior_share)
                                                     : fit_proposal(all_u, proposal_weights(all_u, all_ll, l.proposals, l.drawn,
                                                                                            2.0 * l.dimensions() + 2),
                                                                    l.c.prior_share);
  const std::vector<Eigen::VectorXd> batch = l.sampler.draw(q, l.c.batch);
  l.proposals.push_back(q);
  l.drawn.push_back(l.c.batch);
  for (int k = 0; k < l.c.batch; ++k) {
    ParameterSet s;
    s.name = drawn_set_name(it, k + 1);
    s.iteration = it;
    s.u = batch[static_cast<std::size_t>(k)];
    sets.push_back(std::move(s));
  }
}

// The ledger's entry of set `s` among runs of other hashes: the same scenes planned with the engine
// the ledger's stamp names (RunOptions::ledger_engine).
const ScoredSet* other_engine_entry(const Loop& l, std::size_t k, const ParameterSet& s) {
  const Ledger& ledger = l.at[k].ledger;
  if (!l.o.ledger_engine || ledger.stamp.engine_source.empty() || ledger.stamp.engine_source == l.out.engine) return nullptr;
  const auto runs = plan_sets(l.c, l.at[k].study, *l.at[k].profile, {s}, l.out.sizes[k].results, ledger.stamp.engine_source);
  const auto hashes = run_hashes_by_set(runs);
  const auto h = hashes.find(s.name);
  return h == hashes.end() ? nullptr : ledger.find(s.name, s.u, h->second);
}

// Size k's sets of this iteration the ledger has scored (their runs planned with the same hashes)
// are not run again; a set whose every run has its finished result here is scored on its runs.
// (Planned with every set of the size still to run: a run several sets share is named after the first.)
IterationPlan plan_iteration(Loop& l, std::size_t k, int it) {
  IterationPlan p;
  SizeState& size = l.at[k];
  SizeOutcome& so = l.out.sizes[k];
  for (const ParameterSet& s : so.sets)
    if (!size.from_ledger.count(s.name)) p.to_run.push_back(s);
  p.runs = p.to_run.empty() ? std::vector<pipeline::PlannedRun>{} : plan_sets(l.c, size.study, *size.profile, p.to_run, so.results, l.out.engine);
  p.hashes = run_hashes_by_set(p.runs);
  p.finished.resize(p.runs.size());
  for (std::size_t i = 0; i < p.runs.size(); ++i) {
    p.finished[i] = pipeline::up_to_date(p.runs[i].result, p.runs[i].hash);
    if (!p.finished[i]) p.unfinished.insert(p.runs[i].variants.begin(), p.runs[i].variants.end());
  }
  for (ParameterSet& s : so.sets) {
    if (s.iteration != it || !p.unfinished.count(s.name)) continue;
    const auto h = p.hashes.find(s.name);
    const ScoredSet* e = h == p.hashes.end() ? nullptr : size.ledger.find(s.name, s.u, h->second);
    const bool other_engine = !e && (e = other_engine_entry(l, k, s)) != nullptr;
    if (!e) continue;
    s.u = e->u, s.misfit = e->misfit;
    size.from_ledger.emplace(s.name, *e);
    p.in_ledger.insert(s.name);
    if (other_engine) ++so.other_engine_sets, so.other_engine = size.ledger.stamp.engine_source;
    if (!e->verified_by.empty()) ++so.verified_sets, so.verified_by = e->verified_by;
  }
  return p;
}

}  // namespace

std::size_t base_of(const Outcome& out, std::size_t k) { return out.base_of(k); }

void execute_sets(Loop& l, std::size_t k, const std::vector<ParameterSet>& sets, const std::vector<pipeline::PlannedRun>& runs) {
  SizeState& size = l.at[k];
  const SizeOutcome& so = l.out.sizes[k];
  if (!size.lock) size.lock = pipeline::lock_results_folder(so.results);
  pipeline::write_scenes(runs);
  pipeline::Study study = size.study;
  study.variants.clear();
  for (const ParameterSet& s : sets) study.variants.push_back(variant_of(l.c, s));
  pipeline::write_manifest(runs, study, so.results, l.out.engine);
  pipeline::Outcome ran;
  if (l.o.executor == "slurm")
    ran = pipeline::slurm::execute(runs, std::vector<pipeline::SlurmOptions>(runs.size(), l.study.slurm), l.o.dem);
  else
    ran = pipeline::execute(runs, l.o.dem, l.o.jobs, l.o.threads);
  if (ran.interrupted) throw dem::ConfigError("interrupted: start the calibration again to go on (finished runs are reused)");
}

namespace {

// Runs what the iteration needs at size k but the ledger's sets (the plan is made again without them).
void run_iteration(Loop& l, std::size_t k, int it, IterationPlan& p) {
  SizeState& size = l.at[k];
  SizeOutcome& so = l.out.sizes[k];
  if (!p.in_ledger.empty()) {
    p.to_run.erase(std::remove_if(p.to_run.begin(), p.to_run.end(), [&](const ParameterSet& s) { return size.from_ledger.count(s.name) > 0; }),
                   p.to_run.end());
    p.runs = p.to_run.empty() ? std::vector<pipeline::PlannedRun>{} : plan_sets(l.c, size.study, *size.profile, p.to_run, so.results, l.out.engine);
  }
  if (l.o.plan_only) return;  // replayed: every set it needs is in the ledger or finished here
  const int this_iteration = static_cast<int>(std::count_if(so.sets.begin(), so.sets.end(), [&](const ParameterSet& s) { return s.iteration == it; }));
  if (l.named_step)
    std::printf("[calibrate] after the iterations, size %s: %zu named set(s), %zu runs planned (finished ones are reused)\n",
                so.label().c_str(), so.named.size(), p.runs.size());
  else
    std::printf("[calibrate] iteration %d%s: %d sets (%zu scored in the ledger), %zu runs planned (finished ones are reused)\n", it,
                l.out.sizes.size() > 1 ? (", size " + so.label()).c_str() : "", this_iteration, p.in_ledger.size(), p.runs.size());
  std::fflush(stdout);
  if (p.runs.empty()) return;
  if (l.o.ledger_only) {  // a set whose runs all finished here is scored on them: nothing runs for it
    std::vector<std::string> missing;
    for (const ParameterSet& s : so.sets)
      if (s.iteration == it && !size.from_ledger.count(s.name) && p.unfinished.count(s.name)) missing.push_back(s.name);
    if (!missing.empty())
      throw dem::ConfigError("--ledger-only: the ledger " + size.ledger_file + " holds no score of set " + missing.front() + " (" + std::to_string(missing.size()) +
                             " of iteration " + std::to_string(it) + " lack one, and not all of their runs are finished here) and nothing may run");
    return;
  }
  execute_sets(l, k, p.to_run, p.runs);
}

// Scores size k's sets of this iteration not in the ledger on their samples; every set of it gets
// its log-likelihood.
void score_iteration(Loop& l, std::size_t k, int it, const IterationPlan& p) {
  SizeState& size = l.at[k];
  SizeOutcome& so = l.out.sizes[k];
  double ledger_runs = 0;
  for (const auto& [name, e] : size.from_ledger) ledger_runs += e.runs;
  so.runs = static_cast<int>(p.runs.size() + std::lround(ledger_runs));
  so.ledger_sets = static_cast<int>(size.from_ledger.size());
  so.samples = samples_of_sets(p.runs);
  std::map<std::string, std::string> stops;  // set -> the engine's message of a run of it that stopped
  for (const pipeline::PlannedRun& r : p.runs)
    if (const auto stop = pipeline::recorded_stop(r.result, r.hash))
      for (const std::string& v : r.variants) stops.emplace(v, stop->message);
  for (ParameterSet& s : so.sets) {
    if (s.iteration != it || size.from_ledger.count(s.name)) continue;
    if (const auto stop = stops.find(s.name); stop != stops.end()) s.stopped = stop->second;
    s.misfit = score_complete(size.refs, so.samples[s.name]);
    for (const std::string& left : s.misfit.left_out)
      std::printf("[calibrate] set %s scored without %s\n", s.name.c_str(), left.c_str());
  }
  for (ParameterSet& s : so.sets)
    if (s.iteration == it) s.log_likelihood = s.misfit.valued && !std::isnan(s.misfit.chi2) ? -0.5 * s.misfit.chi2 : -INFINITY;
  // The stamp: of the runs here when some ran, their date the latest of theirs and the ledger's.
  so.stamp = size.ledger.stamp;
  if (!p.to_run.empty()) try {
      validation::Stamp here = validation::stamp_of_results(so.results, p.to_run.front().name);
      if (size.ledger.stamp.recorded()) here.date = std::max(here.date, size.ledger.stamp.date);
      so.stamp = here;
    } catch (const std::exception&) {
    }
  double ledger_seconds = 0;
  for (const auto& [name, e] : size.from_ledger) ledger_seconds += e.core_seconds;
  so.core_seconds = recorded_core_seconds(p.runs, l.o.threads) + ledger_seconds;
}

// Size k's ledger: every set scored so far (with its share of the runs and their cost), and the
// entries of sets not drawn yet (a later iteration may draw them again).
void keep_scores(Loop& l, std::size_t k, const IterationPlan& p) {
  if (l.o.ledger_only || l.o.plan_only) return;  // a replay writes no ledger
  SizeState& size = l.at[k];
  const SizeOutcome& so = l.out.sizes[k];
  const std::map<std::string, RunShare> shares = run_shares(p.runs, l.o.threads);
  Ledger next;
  next.references_key = size.ledger.references_key;
  next.stamp = so.stamp;
  for (const ParameterSet& s : so.sets) {
    if (const auto e = size.from_ledger.find(s.name); e != size.from_ledger.end()) {
      next.sets.push_back(e->second);
      continue;
    }
    const auto found = shares.find(s.name);
    const RunShare share = found == shares.end() ? RunShare{} : found->second;
    const auto h = p.hashes.find(s.name);
    next.sets.push_back({s.name, s.u, h == p.hashes.end() ? std::vector<std::string>{} : h->second, s.misfit, share.runs,
                         share.cost.core_seconds, share.cost.particle_steps, ""});
  }
  for (const ScoredSet& e : size.ledger.sets)
    if (std::none_of(so.sets.begin(), so.sets.end(), [&](const ParameterSet& s) { return s.name == e.name; })) next.sets.push_back(e);
  if (const std::string kept = write_ledger(size.ledger_file, next, size.refs); !kept.empty())
    std::printf("[calibrate] the ledger %s held sets scored against other references or not among this calibration's: "
                "kept as %s, a new one written\n", size.ledger_file.c_str(), kept.c_str());
}

// The probes of every size: new sets the first size runs too.
int probes(const Calibration& c) {
  int n = 0;
  for (const Size& s : c.sizes) n += s.probe;
  return n;
}

// Whether size k's plan runs something: a set of it neither in the ledger nor with every run finished here.
bool needs_runs(const Loop& l, std::size_t k, const IterationPlan& p) {
  const SizeState& size = l.at[k];
  return std::any_of(p.unfinished.begin(), p.unfinished.end(), [&](const std::string& set) { return !size.from_ledger.count(set); });
}

// The sets size k may still score: its sets at most, less those scored so far.
int sets_left(const Loop& l, std::size_t k) {
  const SizeOutcome& so = l.out.sizes[k];
  const int at_most = k == 0 ? l.c.max_iterations * l.c.batch + probes(l.c) : so.sets_at_most();
  // Scored (its score or the reason it has none): rows judged; a set drawn, chosen or standing in: none yet.
  const int scored = static_cast<int>(std::count_if(so.sets.begin(), so.sets.end(), [](const ParameterSet& s) { return !s.misfit.rows.empty(); }));
  return std::max(0, at_most - scored);
}

// One size's part of an iteration: plan, run, score, keep. With --plan, nothing runs: an iteration
// the ledgers and the finished runs cover is replayed from them; at the first that needs runs, what
// it and the rest cost is printed and false returned.
bool step_size(Loop& l, std::size_t k, int it) {
  IterationPlan p = plan_iteration(l, k, it);
  if (l.o.plan_only && needs_runs(l, k, p)) {
    if (l.named_step) {  // the calibration's line first: every iteration replayed
      IterationPlan first = plan_iteration(l, 0, it);
      print_plan(l, 0, 0, first, 0);
    }
    print_plan(l, k, it, p, sets_left(l, k));
    return false;
  }
  l.ran_new |= needs_runs(l, k, p);
  run_iteration(l, k, it, p);
  score_iteration(l, k, it, p);
  keep_scores(l, k, p);
  return true;
}

// --plan, once size `from`'s step of iteration `it` needs runs: the cost of the sizes after it. A
// larger size with sets still to run but none chosen this iteration is costed on stand-ins, the
// first sets of the size it chooses from that it has not run.
void plan_rest(Loop& l, int it, std::size_t from) {
  for (std::size_t k = std::max<std::size_t>(from + 1, 1); k < l.out.sizes.size(); ++k) {
    SizeOutcome& so = l.out.sizes[k];
    const int left = sets_left(l, k);
    const bool chosen = std::any_of(so.sets.begin(), so.sets.end(), [&](const ParameterSet& s) { return s.iteration == it; });
    int stand_ins = chosen ? 0 : std::min(left, l.c.sizes[k].per_iteration);
    for (const ParameterSet& s : l.out.sizes[base_of(l.out, k)].sets) {
      if (stand_ins == 0) break;
      if (std::none_of(so.sets.begin(), so.sets.end(), [&](const ParameterSet& t) { return t.name == s.name; })) {
        ParameterSet stand_in = s;
        stand_in.iteration = it, stand_in.misfit = {};
        so.sets.push_back(stand_in), --stand_ins;
      }
    }
    IterationPlan p = plan_iteration(l, k, it);
    print_plan(l, k, it, p, left);
  }
}

}  // namespace

double Outcome::core_seconds() const {
  double total = 0;
  for (const SizeOutcome& s : sizes) total += s.core_seconds;
  return total;
}

std::optional<Outcome> run_calibration(const Calibration& c, const RunOptions& o) {
  Loop l(c, o);
  start(l);
  for (std::size_t k = 0; k < l.at.size(); ++k) verify_ledger(l, k);
  Outcome& out = l.out;
  // --plan: the iterations the ledgers and the finished runs cover replay; the first that needs
  // runs prints its cost and the rest's, each size's (plan_rest).
  const auto plan_from = [&](int it, std::size_t k) {
    plan_rest(l, it, k);
    return std::nullopt;
  };
  int it = 1;
  for (; it <= c.max_iterations; ++it) {
    draw_batch(l, it);
    if (!step_size(l, 0, it)) return plan_from(it, 0);
    weigh(l, it);
    const std::size_t first_sets = out.first().sets.size();
    for (std::size_t k = 1; k < out.sizes.size(); ++k) choose_larger_sets(l, k, it);
    // The probes' runs at the first size, for their pairs.
    if (out.first().sets.size() > first_sets && !step_size(l, 0, it)) return plan_from(it, 0);
    for (std::size_t k = 1; k < out.sizes.size(); ++k)
      if (!step_size(l, k, it)) return plan_from(it, k);
    weigh_larger(l);
    const IterationSummary summary = summarize(l, it);
    out.iterations.push_back(summary);
    if (settled(l, it, summary)) break;
    // The report so far, after an iteration that ran something (a replayed one leaves the report as it is).
    if (it < c.max_iterations && o.after_iteration && !o.plan_only && std::exchange(l.ran_new, false)) {
      out.stop_reason = "still iterating: iteration " + std::to_string(it) + " of at most " + std::to_string(c.max_iterations) +
                        " done (it moved " + validation::significant(summary.moved, 2) + " of a prior range); start it again to go on";
      o.after_iteration(out);
    }
  }
  // The sets named for a size run once the iterations end; the posterior is weighed again with them.
  const int last = std::min(it, c.max_iterations);
  bool named = false;
  for (std::size_t k = 1; k < out.sizes.size(); ++k) named = choose_named(l, k, last) || named;
  if (named) {
    l.named_step = true;
    for (std::size_t k = 1; k < out.sizes.size(); ++k)
      if (!out.sizes[k].named.empty() && !step_size(l, k, last)) return plan_from(last, k);
    l.named_step = false;
    weigh_larger(l);
    out.iterations.back() = summarize(l, last, true);
  }
  if (o.plan_only) {  // every iteration replayed: nothing left to run
    for (std::size_t k = 0; k < out.sizes.size(); ++k) {
      IterationPlan p = plan_iteration(l, k, std::min(it, c.max_iterations));
      print_plan(l, k, 0, p, 0);
    }
    return std::nullopt;
  }
  if (!out.converged) out.stop_reason = unsettled_reason(c, out);
  if (!out.unscored.empty())
    out.stop_reason += "; " + std::to_string(out.unscored.size()) + " of the " + std::to_string(out.first().sets.size()) +
                       " sets could not be scored and weigh nothing, so the posterior covers only the part of the prior the "
                       "others sample (" + out.unscored.front() + (out.unscored.size() > 1 ? "; ..." : "") + ")";
  return out;
}

}  // namespace calibration
