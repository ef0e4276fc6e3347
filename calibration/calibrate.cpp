#include "calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <set>

#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "exec/slurm.hpp"
#include "ledger.hpp"
#include "plan/plan_cost.hpp"
#include "study/format.hpp"
#include "study/series.hpp"
#include "surrogate.hpp"

namespace calibration {
namespace fs = std::filesystem;

namespace {

std::string set_name(int iteration, int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "i%ds%03d", iteration, index);
  return buf;
}

// The study with every set so far as its variants.
pipeline::Study with_sets(const Calibration& c, pipeline::Study study, const std::vector<ParameterSet>& sets) {
  study.variants.clear();
  for (const ParameterSet& s : sets) study.variants.push_back(variant_of(c, s));
  return study;
}

// Every set so far planned (copies joined) into the results folder.
std::vector<pipeline::PlannedRun> plan_sets(const Calibration& c, const pipeline::Study& study, const pipeline::Profile& profile,
                                            const std::vector<ParameterSet>& sets, const std::string& out,
                                            const std::string& engine) {
  const pipeline::Study s = with_sets(c, study, sets);
  return pipeline::join_studies({{s.name, pipeline::plan_study(s, profile, out, engine)}});
}

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

// The input hashes of the runs each set needs, sorted, by set name.
std::map<std::string, std::vector<std::string>> run_hashes_by_set(const std::vector<pipeline::PlannedRun>& runs) {
  std::map<std::string, std::vector<std::string>> out;
  for (const pipeline::PlannedRun& r : runs)
    for (const std::string& v : r.variants) out[v].push_back(r.hash);
  for (auto& [set, hashes] : out) std::sort(hashes.begin(), hashes.end());
  return out;
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

double largest_move(const std::vector<Marginal>& a, const std::vector<Marginal>& b) {
  double moved = 0;
  for (std::size_t j = 0; j < a.size(); ++j)
    moved = std::max({moved, std::abs(a[j].unit_mean - b[j].unit_mean), std::abs(a[j].unit_sd - b[j].unit_sd)});
  return moved;
}

// `results_root`: the folder the study's results folders are in, where this engine's finished runs
// of other studies give a throughput when none of the calibration's own has finished.
// `hashes`: the run hashes each set needs (run_hashes_by_set of `runs`); `finished`: per run,
// whether its finished result is here; `unfinished`: the sets some run of which is not;
// `in_ledger`: the first iteration's sets the ledger has scored. No iteration runs again any set
// of the ledger.
void print_plan(const Calibration& c, std::vector<pipeline::PlannedRun>& runs, int jobs, const std::string& results_root,
                const std::string& engine, const std::map<std::string, std::vector<std::string>>& hashes,
                const std::vector<bool>& finished, const std::set<std::string>& unfinished, const std::set<std::string>& in_ledger,
                const Ledger& ledger) {
  // The throughput: of this plan's finished runs; else of this engine's other runs on this
  // machine; else of the runs that scored the ledger's sets (on the machine that ran them); else
  // the make bench figure.
  const std::optional<double> recorded = pipeline::use_recorded_costs(runs);
  const std::optional<pipeline::MachineThroughput> machine =
      recorded ? std::nullopt : pipeline::recorded_throughput_under(results_root, engine);
  const std::optional<double> scored = ledger.throughput();
  const double throughput = recorded ? *recorded
                            : machine ? machine->particle_steps_per_s
                            : scored  ? *scored
                                      : pipeline::default_throughput;
  // The first iteration runs what has no result here and is needed by a set not in the ledger (a
  // copy of another run costs no engine time).
  std::vector<bool> done(runs.size()), todo(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const pipeline::PlannedRun& r = runs[i];
    done[i] = r.copy_of >= 0 || finished[i];
    todo[i] = !done[i] && std::any_of(r.variants.begin(), r.variants.end(), [&](const std::string& v) { return !in_ledger.count(v); });
  }
  const std::vector<double> cost = pipeline::run_costs(runs, todo);
  // A later iteration's set costs what a first-iteration set's own runs cost, whether they ran
  // here or not; the runs every set shares are run once, if they are not here.
  double shared = 0, first_own = 0, own_per_set = 0, shared_needed = 0;
  int shared_runs = 0, set_runs = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].variants.size() > 1) {
      shared += cost[i], shared_runs += todo[i];
      if (!done[i]) shared_needed += runs[i].cost;
    } else {
      first_own += cost[i], set_runs += todo[i];
      if (runs[i].copy_of < 0) own_per_set += runs[i].cost / c.batch;
    }
  }
  const double first = pipeline::estimated_wall_time_s(runs, cost, jobs, throughput);
  // Sets no iteration runs: the first iteration's finished here or in the ledger, and the ledger's
  // of later iterations (drawn again as they were, from the same scores) when its first-iteration
  // entries were scored on runs of this plan's inputs (an engine or a scene changed since: none).
  const bool current = std::all_of(ledger.sets.begin(), ledger.sets.end(), [&](const ScoredSet& e) {
    const auto h = hashes.find(e.name);
    return h == hashes.end() || h->second == e.run_hashes;
  });
  std::size_t scored_sets = 0;
  for (const auto& entry : hashes) scored_sets += !unfinished.count(entry.first) || in_ledger.count(entry.first);
  if (current)
    for (const ScoredSet& e : ledger.sets) scored_sets += !hashes.count(e.name);
  const double left = std::max(0.0, static_cast<double>(c.max_iterations) * c.batch - static_cast<double>(scored_sets));
  const double total = left > 0 ? shared_needed + own_per_set * left : 0;
  std::printf("calibration %s: %zu parameter(s), %d sets per iteration, at most %d iterations\n", c.name.c_str(),
              c.parameters.size(), c.batch, c.max_iterations);
  std::printf("first iteration: %zu runs (%d shared by every set, %d for its sets still to run), %.3g particle-steps, "
              "about %.1f min on %d core(s)\n", runs.size(), shared_runs, set_runs, shared + first_own, first / 60, jobs);
  if (ledger.other_sets > 0)
    std::printf("the ledger of scored sets (%s/scored_sets.json) holds %d set(s) scored against other references: none is "
                "taken, and a run keeps it aside (scored_sets.kept-N.json) before it writes its own\n", c.report.c_str(), ledger.other_sets);
  if (!ledger.sets.empty())
    std::printf("the ledger of scored sets (%s/scored_sets.json) holds %zu set(s), %zu of them of the first iteration: "
                "%s\n", c.report.c_str(), ledger.sets.size(), in_ledger.size(),
                current ? "they are not run again"
                        : "some were scored on runs of other inputs (an engine or a scene changed): those run again, "
                          "and the later iterations' are counted as still to score");
  std::printf("all %d iterations at most (%.0f sets still to score): %.3g particle-steps, %.1f core-min, about %.1f min on %d core(s)\n",
              c.max_iterations, left, total, total / throughput / 60, total / throughput / 60 / jobs, jobs);
  const std::string from = recorded ? "recorded by the finished runs in the results folder"
                           : machine ? "recorded by " + std::to_string(machine->runs) + " finished runs of this engine in " +
                                           std::to_string(machine->studies) + " results folders under " + results_root
                           : scored ? "recorded by the runs of the ledger's scored sets, on the machine that ran them"
                                    : "the engine's make bench figure; no run of this engine has finished here yet";
  std::printf("(throughput %.3g particle-steps/s per core: %s)\n", throughput, from.c_str());
}

// The loop's state across iterations: the outcome so far, the draws, the ledger.
struct Loop {
  const Calibration& c;
  const RunOptions& o;
  pipeline::Study study;
  const pipeline::Profile* profile = nullptr;
  Outcome out;
  Sampler sampler;
  std::vector<Proposal> proposals;
  std::vector<int> drawn;
  std::vector<Marginal> before;
  std::unique_ptr<dem::FileLock> lock;
  std::string ledger_file;
  Ledger ledger;
  std::map<std::string, ScoredSet> from_ledger;  // the sets scored from the ledger, by name
  Loop(const Calibration& calibration, const RunOptions& options)
      : c(calibration), o(options), sampler(static_cast<int>(calibration.parameters.size())) {}
  int dimensions() const { return static_cast<int>(c.parameters.size()); }
};

// One iteration's plan: the runs of every set still to run, with what is known of each.
struct IterationPlan {
  std::vector<ParameterSet> to_run;
  std::vector<pipeline::PlannedRun> runs;
  std::map<std::string, std::vector<std::string>> hashes;  // input hashes are of content: the same whichever sets a plan holds
  std::vector<bool> finished;        // per run: its finished result is here
  std::set<std::string> unfinished;  // the sets some run of which has none
  std::set<std::string> in_ledger;   // this iteration's sets the ledger has scored
};

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
  for (const CurveRow& row : refs.curves) {
    const bool density = std::any_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == row.density; });
    const bool test = std::any_of(study.tests.begin(), study.tests.end(), [&](const auto& t) { return t.name == row.test; });
    if (!density || !test)
      throw dem::ConfigError(refs.file + ": curve '" + row.name + "' reads " + row.density + " " + row.test +
                             ", which the study " + c.study + " does not run");
  }
}

void start(Loop& l) {
  const Calibration& c = l.c;
  l.out.calibration = c;
  l.study = pipeline::load_study(c.study);
  if (!l.study.variants.empty())
    throw dem::ConfigError(c.file + ": study: " + c.study + " has variants; a calibration's sets are its variants, so its study has none");
  l.profile = l.o.profile.empty() ? &l.study.default_profile() : &l.study.profile(l.o.profile);
  l.out.profile = l.profile->name;
  l.out.seeds = l.profile->seeds;
  l.out.references = read_references(c.references, l.profile->name);
  l.out.engine = pipeline::engine_version(l.o.dem);
  if (l.out.engine.empty()) throw dem::ConfigError("cannot run the engine '" + l.o.dem + " --source-hash'");
  l.out.results = (fs::path(l.study.output) / ("calibration_" + c.name) / l.profile->name).lexically_normal().string();
  check_inputs(c, l.study, l.out.references);
  l.ledger_file = (fs::path(c.report) / "scored_sets.json").string();
  l.ledger = read_ledger(l.ledger_file, l.out.references);
}

// The iteration's batch, from the prior (the first) or from a proposal fitted after the sets so
// far: to the posterior on the response surface when there is one, else to the sets' weights
// tempered to span at least the best 2d + 2 sets.
void draw_batch(Loop& l, int it) {
  std::vector<Eigen::VectorXd> all_u;
  std::vector<double> all_ll;
  for (const ParameterSet& s : l.out.sets) all_u.push_back(s.u), all_ll.push_back(s.log_likelihood);
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
    s.name = set_name(it, k + 1);
    s.iteration = it;
    s.u = batch[static_cast<std::size_t>(k)];
    l.out.sets.push_back(std::move(s));
  }
}

// This iteration's sets the ledger has scored (their runs planned with the same hashes) are not
// run again; a set whose every run has its finished result here is scored on its runs. (Planned
// with every set to run so far: a run several sets share is named after the first.)
IterationPlan plan_iteration(Loop& l, int it) {
  IterationPlan p;
  for (const ParameterSet& s : l.out.sets)
    if (!l.from_ledger.count(s.name)) p.to_run.push_back(s);
  p.runs = plan_sets(l.c, l.study, *l.profile, p.to_run, l.out.results, l.out.engine);
  p.hashes = run_hashes_by_set(p.runs);
  p.finished.resize(p.runs.size());
  for (std::size_t i = 0; i < p.runs.size(); ++i) {
    p.finished[i] = pipeline::up_to_date(p.runs[i].result, p.runs[i].hash);
    if (!p.finished[i]) p.unfinished.insert(p.runs[i].variants.begin(), p.runs[i].variants.end());
  }
  for (ParameterSet& s : l.out.sets) {
    if (s.iteration != it || !p.unfinished.count(s.name)) continue;
    const auto h = p.hashes.find(s.name);
    if (const ScoredSet* e = h == p.hashes.end() ? nullptr : l.ledger.find(s.name, s.u, h->second)) {
      s.u = e->u, s.misfit = e->misfit;
      l.from_ledger.emplace(s.name, *e);
      p.in_ledger.insert(s.name);
    }
  }
  return p;
}

// Runs what the iteration needs but the ledger's sets (the plan is made again without them).
void run_iteration(Loop& l, int it, IterationPlan& p) {
  if (!p.in_ledger.empty()) {
    p.to_run.erase(std::remove_if(p.to_run.begin(), p.to_run.end(), [&](const ParameterSet& s) { return l.from_ledger.count(s.name) > 0; }),
                   p.to_run.end());
    p.runs = p.to_run.empty() ? std::vector<pipeline::PlannedRun>{} : plan_sets(l.c, l.study, *l.profile, p.to_run, l.out.results, l.out.engine);
  }
  std::printf("[calibrate] iteration %d: %d sets (%zu scored in the ledger), %zu runs planned (finished ones are reused)\n", it,
              l.c.batch, p.in_ledger.size(), p.runs.size());
  std::fflush(stdout);
  if (p.runs.empty()) return;
  if (!l.lock) l.lock = pipeline::lock_results_folder(l.out.results);
  pipeline::write_scenes(p.runs);
  pipeline::write_manifest(p.runs, with_sets(l.c, l.study, p.to_run), l.out.results, l.out.engine);
  pipeline::Outcome ran;
  if (l.o.executor == "slurm")
    ran = pipeline::slurm::execute(p.runs, std::vector<pipeline::SlurmOptions>(p.runs.size(), l.study.slurm), l.o.dem);
  else
    ran = pipeline::execute(p.runs, l.o.dem, l.o.jobs, l.o.threads);
  if (ran.interrupted) throw dem::ConfigError("interrupted: start the calibration again to go on (finished runs are reused)");
}

// Scores the iteration's sets not in the ledger on their samples; every set of it gets its
// log-likelihood.
void score_iteration(Loop& l, int it, const IterationPlan& p) {
  Outcome& out = l.out;
  double ledger_runs = 0;
  for (const auto& [name, e] : l.from_ledger) ledger_runs += e.runs;
  out.runs = static_cast<int>(p.runs.size() + std::lround(ledger_runs));
  out.ledger_sets = static_cast<int>(l.from_ledger.size());
  out.samples = samples_of_sets(p.runs);
  std::map<std::string, std::string> stops;  // set -> the engine's message of a run of it that stopped
  for (const pipeline::PlannedRun& r : p.runs)
    if (const auto stop = pipeline::recorded_stop(r.result, r.hash))
      for (const std::string& v : r.variants) stops.emplace(v, stop->message);
  for (ParameterSet& s : out.sets) {
    if (s.iteration != it || l.from_ledger.count(s.name)) continue;
    if (const auto stop = stops.find(s.name); stop != stops.end()) s.stopped = stop->second;
    s.misfit = score_complete(out.references, out.samples[s.name]);
    for (const std::string& left : s.misfit.left_out)
      std::printf("[calibrate] set %s scored without %s\n", s.name.c_str(), left.c_str());
  }
  for (ParameterSet& s : out.sets)
    if (s.iteration == it) s.log_likelihood = s.misfit.valued && !std::isnan(s.misfit.chi2) ? -0.5 * s.misfit.chi2 : -INFINITY;
  // The stamp: of the runs here when some ran, their date the latest of theirs and the ledger's.
  out.stamp = l.ledger.stamp;
  if (!p.to_run.empty()) try {
      validation::Stamp here = validation::stamp_of_results(out.results, p.to_run.front().name);
      if (l.ledger.stamp.recorded()) here.date = std::max(here.date, l.ledger.stamp.date);
      out.stamp = here;
    } catch (const std::exception&) {
    }
}

// The ledger: every set scored so far (with its share of the runs and their cost), and the entries
// of sets not drawn yet (a later iteration may draw them again).
void keep_scores(Loop& l, const IterationPlan& p) {
  const std::map<std::string, RunShare> shares = run_shares(p.runs, l.o.threads);
  Ledger next;
  next.references_key = l.ledger.references_key;
  next.stamp = l.out.stamp;
  for (const ParameterSet& s : l.out.sets) {
    if (const auto e = l.from_ledger.find(s.name); e != l.from_ledger.end()) {
      next.sets.push_back(e->second);
      continue;
    }
    const auto found = shares.find(s.name);
    const RunShare share = found == shares.end() ? RunShare{} : found->second;
    const auto h = p.hashes.find(s.name);
    next.sets.push_back({s.name, s.u, h == p.hashes.end() ? std::vector<std::string>{} : h->second, s.misfit, share.runs,
                         share.cost.core_seconds, share.cost.particle_steps});
  }
  for (const ScoredSet& e : l.ledger.sets)
    if (std::none_of(l.out.sets.begin(), l.out.sets.end(), [&](const ParameterSet& s) { return s.name == e.name; })) next.sets.push_back(e);
  if (const std::string kept = write_ledger(l.ledger_file, next, l.out.references); !kept.empty())
    std::printf("[calibrate] the ledger %s held sets scored against other references or not among this calibration's: "
                "kept as %s, a new one written\n", l.ledger_file.c_str(), kept.c_str());
}

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
  for (const ParameterSet& s : out.sets)
    for (const RowMisfit& m : s.misfit.rows)
      if (example.empty() && m.valued && !std::isfinite(m.chi2))
        example = " (set " + s.name + ": '" + m.name + "' has chi^2 " + validation::format_number(m.chi2) + ")";
  throw dem::ConfigError("no parameter set has a finite weight: the chi^2 of every set scored is infinite or not a number" + example +
                         ", so there is no posterior; check the sd and tolerances of " + out.references.file +
                         " (a point or row whose sd and tolerance are 0 cannot be missed by any run); nothing was reported");
}

// Every set weighted again; the posterior: on a response surface fitted to the sets near it
// (surrogate.hpp), when enough sets are scored; else the sets' own weights. The surface's region:
// the Gaussian this iteration drew from (the first: one fitted to the best sets).
void weigh(Loop& l, int it) {
  Outcome& out = l.out;
  std::vector<Eigen::VectorXd> u;
  std::vector<double> log_likelihood;
  for (const ParameterSet& s : out.sets) u.push_back(s.u), log_likelihood.push_back(s.log_likelihood);
  out.weights = importance_weights(u, log_likelihood, l.proposals, l.drawn);
  const Proposal region = it > 1 ? l.proposals.back()
                                 : fit_proposal(u, proposal_weights(u, log_likelihood, l.proposals, l.drawn, 2.0 * quadratic_terms(l.dimensions())), 0);
  out.posterior_from.clear();
  out.posterior_u = u, out.posterior_w = out.weights;
  if (const std::optional<ResponseSurface> surface = fit_surface(out.references, out.sets, region)) {
    std::vector<Eigen::VectorXd> pu;
    std::vector<double> pw;
    sample_surface(*surface, out.references, 4000, pu, pw);
    if (!pu.empty()) {
      out.posterior_u = std::move(pu), out.posterior_w = std::move(pw);
      out.surface_sets = surface->sets;
      out.surface_noise = surface->noise_to_reference;
      out.posterior_from = "response surface";
      out.region_centre = surface->centre;
      out.region_sd = surface->scale * surface->radius;
    }
  }
  require_weight(out);
}

// The first row of the last set that has no value, and why ("no rows" when it has none).
std::string why_unscored(const ParameterSet& s) {
  if (!s.stopped.empty()) return "the engine stopped a run of it: " + s.stopped;
  if (s.misfit.rows.empty()) return "no rows";
  for (const RowMisfit& m : s.misfit.rows)
    if (!m.valued) return m.name + ": " + m.note;
  return "?";
}

// " (2 not scored: they weigh nothing; i1s002: ...)", or "" when every set is scored.
std::string unscored_text(const Outcome& out) {
  if (out.unscored.empty()) return "";
  return " (" + std::to_string(out.unscored.size()) + " not scored: they weigh nothing; " + out.unscored.front() +
         (out.unscored.size() > 1 ? "; ..." : "") + ")";
}

IterationSummary summarize(Loop& l, int it) {
  const Outcome& out = l.out;
  const Calibration& c = l.c;
  IterationSummary summary;
  summary.number = it;
  summary.sets = c.batch;
  summary.valued = static_cast<int>(std::count_if(out.sets.begin(), out.sets.end(), [](const auto& s) { return s.misfit.valued; }));
  if (summary.valued == 0)
    throw dem::ConfigError("no parameter set of iteration " + std::to_string(it) + " could be scored: " + why_unscored(out.sets.back()));
  l.out.unscored.clear();
  for (const ParameterSet& s : out.sets)
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
  summary.moved = l.before.empty() ? 1 : largest_move(l.before, summary.marginals);
  l.before = summary.marginals;
  std::printf("[calibrate] iteration %d: %d of %zu sets scored%s; posterior from %s (effective sample size %.1f), moved %.3f of "
              "the prior ranges;", it, summary.valued, out.sets.size(), unscored_text(out).c_str(),
              out.posterior_from.empty() ? "the sets' weights" : ("a response surface over " + std::to_string(out.surface_sets) + " sets").c_str(),
              summary.ess, summary.moved);
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    std::printf(" %s %.4g +- %.3g", c.parameters[j].name.c_str(), summary.marginals[j].mean, summary.marginals[j].sd);
  std::printf("\n");
  std::fflush(stdout);
  return summary;
}

// Whether the posterior has settled after iteration `it` (then out.stop_reason says why).
bool settled(Loop& l, int it, const IterationSummary& summary) {
  const Calibration& c = l.c;
  if (it < c.min_iterations || summary.moved > c.tolerance || summary.ess < c.min_effective_sets || !summary.contained) return false;
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

}  // namespace

std::optional<Outcome> run_calibration(const Calibration& c, const RunOptions& o) {
  Loop l(c, o);
  start(l);
  Outcome& out = l.out;
  for (int it = 1; it <= c.max_iterations; ++it) {
    draw_batch(l, it);
    IterationPlan p = plan_iteration(l, it);
    if (o.plan_only) {
      print_plan(c, p.runs, o.jobs, fs::path(l.study.output).parent_path().string(), out.engine, p.hashes, p.finished, p.unfinished,
                 p.in_ledger, l.ledger);
      return std::nullopt;
    }
    run_iteration(l, it, p);
    score_iteration(l, it, p);
    keep_scores(l, p);
    weigh(l, it);
    const IterationSummary summary = summarize(l, it);
    out.iterations.push_back(summary);
    double ledger_seconds = 0;
    for (const auto& [name, e] : l.from_ledger) ledger_seconds += e.core_seconds;
    out.core_seconds = recorded_core_seconds(p.runs, o.threads) + ledger_seconds;
    if (settled(l, it, summary)) break;
    if (it < c.max_iterations && o.after_iteration) {
      out.stop_reason = "still iterating: iteration " + std::to_string(it) + " of at most " + std::to_string(c.max_iterations) +
                        " done (it moved " + validation::significant(summary.moved, 2) + " of a prior range); start it again to go on";
      o.after_iteration(out);
    }
  }
  if (!out.converged) out.stop_reason = unsettled_reason(c, out);
  if (!out.unscored.empty())
    out.stop_reason += "; " + std::to_string(out.unscored.size()) + " of the " + std::to_string(out.sets.size()) +
                       " sets could not be scored and weigh nothing, so the posterior covers only the part of the prior the "
                       "others sample (" + out.unscored.front() + (out.unscored.size() > 1 ? "; ..." : "") + ")";
  return out;
}

}  // namespace calibration
