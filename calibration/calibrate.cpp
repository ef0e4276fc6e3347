#include "calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>

#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "exec/slurm.hpp"
#include "plan/plan_cost.hpp"
#include "study/format.hpp"
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

// What the runs cost, from their results (wall time x threads; a copy costs nothing).
double recorded_core_seconds(const std::vector<pipeline::PlannedRun>& runs, int threads) {
  double seconds = 0;
  for (const pipeline::PlannedRun& r : runs)
    if (r.copy_of < 0)
      if (const auto cost = pipeline::result_cost(r.result); cost && cost->wall_s) seconds += *cost->wall_s * threads;
  return seconds;
}

double largest_move(const std::vector<Marginal>& a, const std::vector<Marginal>& b) {
  double moved = 0;
  for (std::size_t j = 0; j < a.size(); ++j)
    moved = std::max({moved, std::abs(a[j].unit_mean - b[j].unit_mean), std::abs(a[j].unit_sd - b[j].unit_sd)});
  return moved;
}

// `results_root`: the folder the study's results folders are in, where this engine's finished runs
// of other studies give a throughput when none of the calibration's own has finished.
void print_plan(const Calibration& c, std::vector<pipeline::PlannedRun>& runs, int jobs, const std::string& results_root,
                const std::string& engine) {
  const std::optional<double> recorded = pipeline::use_recorded_costs(runs);
  const std::optional<pipeline::MachineThroughput> machine =
      recorded ? std::nullopt : pipeline::recorded_throughput_under(results_root, engine);
  const double throughput = recorded ? *recorded : machine ? machine->particle_steps_per_s : pipeline::default_throughput;
  std::vector<bool> todo(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) todo[i] = runs[i].copy_of < 0 && !pipeline::up_to_date(runs[i].result, runs[i].hash);
  const std::vector<double> cost = pipeline::run_costs(runs, todo);
  double shared = 0, per_iteration = 0;
  int shared_runs = 0, set_runs = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bool is_shared = runs[i].variants.size() > 1;
    (is_shared ? shared : per_iteration) += cost[i];
    (is_shared ? shared_runs : set_runs) += todo[i];
  }
  const double first = pipeline::estimated_wall_time_s(runs, cost, jobs, throughput);
  const double total = shared + per_iteration * c.max_iterations;
  std::printf("calibration %s: %zu parameter(s), %d sets per iteration, at most %d iterations\n", c.name.c_str(),
              c.parameters.size(), c.batch, c.max_iterations);
  std::printf("first iteration: %zu runs (%d shared by every set, %d for its sets still to run), %.3g particle-steps, "
              "about %.1f min on %d core(s)\n", runs.size(), shared_runs, set_runs, shared + per_iteration, first / 60, jobs);
  std::printf("all %d iterations at most: %.3g particle-steps, %.1f core-min, about %.1f min on %d core(s)\n",
              c.max_iterations, total, total / throughput / 60, total / throughput / 60 / jobs, jobs);
  const std::string from = recorded ? "recorded by the finished runs in the results folder"
                           : machine ? "recorded by " + std::to_string(machine->runs) + " finished runs of this engine in " +
                                           std::to_string(machine->studies) + " results folders under " + results_root
                                     : "the engine's make bench figure; no run of this engine has finished here yet";
  std::printf("(throughput %.3g particle-steps/s per core: %s)\n", throughput, from.c_str());
}

}  // namespace

std::optional<Outcome> run_calibration(const Calibration& c, const RunOptions& o) {
  Outcome out;
  out.calibration = c;
  const pipeline::Study study = pipeline::load_study(c.study);
  if (!study.variants.empty())
    throw dem::ConfigError(c.file + ": study: " + c.study + " has variants; a calibration's sets are its variants, so its study has none");
  const pipeline::Profile& profile = o.profile.empty() ? study.default_profile() : study.profile(o.profile);
  out.profile = profile.name;
  out.seeds = profile.seeds;
  out.references = read_references(c.references, profile.name);
  out.engine = pipeline::engine_version(o.dem);
  if (out.engine.empty()) throw dem::ConfigError("cannot run the engine '" + o.dem + " --source-hash'");
  out.results = (fs::path(study.output) / ("calibration_" + c.name) / profile.name).lexically_normal().string();
  // Check every parameter's densities and every curve row's density and test are the study's
  // before anything runs.
  for (const Parameter& p : c.parameters)
    for (const std::string& density : p.densities)
      if (std::none_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == density; }))
        throw dem::ConfigError(c.file + ": parameters: " + p.name + ": densities: '" + density + "' is not a density of the study " +
                               c.study);
  for (const CurveRow& row : out.references.curves) {
    const bool density = std::any_of(study.densities.begin(), study.densities.end(), [&](const auto& d) { return d.name == row.density; });
    const bool test = std::any_of(study.tests.begin(), study.tests.end(), [&](const auto& t) { return t.name == row.test; });
    if (!density || !test)
      throw dem::ConfigError(out.references.file + ": curve '" + row.name + "' reads " + row.density + " " + row.test +
                             ", which the study " + c.study + " does not run");
  }

  const int d = static_cast<int>(c.parameters.size());
  Sampler sampler(d);
  std::vector<Proposal> proposals;
  std::vector<int> drawn;
  std::vector<Marginal> before;
  std::unique_ptr<dem::FileLock> lock;
  for (int it = 1; it <= c.max_iterations; ++it) {
    std::vector<Eigen::VectorXd> all_u;
    std::vector<double> all_ll;
    for (const ParameterSet& s : out.sets) all_u.push_back(s.u), all_ll.push_back(s.log_likelihood);
    // After the first iteration: fitted to the posterior on the response surface when there is
    // one, else to the sets' weights tempered to span at least the best 2d + 2 sets.
    const Proposal q = it == 1                       ? Proposal{}
                       : !out.posterior_from.empty() ? fit_proposal(out.posterior_u, out.posterior_w, c.prior_share)
                                                     : fit_proposal(all_u, proposal_weights(all_u, all_ll, proposals, drawn, 2.0 * d + 2),
                                                                    c.prior_share);
    const std::vector<Eigen::VectorXd> batch = sampler.draw(q, c.batch);
    proposals.push_back(q);
    drawn.push_back(c.batch);
    for (int k = 0; k < c.batch; ++k) {
      ParameterSet s;
      s.name = set_name(it, k + 1);
      s.iteration = it;
      s.u = batch[static_cast<std::size_t>(k)];
      out.sets.push_back(std::move(s));
    }
    std::vector<pipeline::PlannedRun> runs = plan_sets(c, study, profile, out.sets, out.results, out.engine);
    if (o.plan_only) {
      print_plan(c, runs, o.jobs, fs::path(study.output).parent_path().string(), out.engine);
      return std::nullopt;
    }
    if (!lock) lock = pipeline::lock_results_folder(out.results);
    pipeline::write_scenes(runs);
    pipeline::write_manifest(runs, with_sets(c, study, out.sets), out.results, out.engine);
    std::printf("[calibrate] iteration %d: %d sets, %zu runs planned (finished ones are reused)\n", it, c.batch, runs.size());
    std::fflush(stdout);
    pipeline::Outcome ran;
    if (o.executor == "slurm")
      ran = pipeline::slurm::execute(runs, std::vector<pipeline::SlurmOptions>(runs.size(), study.slurm), o.dem);
    else
      ran = pipeline::execute(runs, o.dem, o.jobs, o.threads);
    if (ran.interrupted) throw dem::ConfigError("interrupted: start the calibration again to go on (finished runs are reused)");
    out.runs = static_cast<int>(runs.size());
    out.samples = samples_of_sets(runs);
    for (ParameterSet& s : out.sets) {
      if (s.iteration != it) continue;
      s.misfit = score_complete(out.references, out.samples[s.name]);
      for (const std::string& left : s.misfit.left_out)
        std::printf("[calibrate] set %s scored without %s\n", s.name.c_str(), left.c_str());
      s.log_likelihood = s.misfit.valued ? -0.5 * s.misfit.chi2 : -INFINITY;
    }
    std::vector<Eigen::VectorXd> u;
    std::vector<double> log_likelihood;
    for (const ParameterSet& s : out.sets) u.push_back(s.u), log_likelihood.push_back(s.log_likelihood);
    out.weights = importance_weights(u, log_likelihood, proposals, drawn);
    // The posterior: on a response surface fitted to the sets near it (surrogate.hpp), when enough
    // sets are scored; else the sets' own weights. The surface's region: the Gaussian this
    // iteration drew from (the first: one fitted to the best sets).
    const Proposal region = it > 1 ? proposals.back()
                                   : fit_proposal(u, proposal_weights(u, log_likelihood, proposals, drawn, 2.0 * quadratic_terms(d)), 0);
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
    IterationSummary summary;
    summary.number = it;
    summary.sets = c.batch;
    summary.valued = static_cast<int>(std::count_if(out.sets.begin(), out.sets.end(), [](const auto& s) { return s.misfit.valued; }));
    if (summary.valued == 0)
      throw dem::ConfigError("no parameter set of iteration " + std::to_string(it) + " could be scored: " +
                             (out.sets.back().misfit.rows.empty() ? std::string("no rows") : [&] {
                               for (const RowMisfit& m : out.sets.back().misfit.rows)
                                 if (!m.valued) return m.name + ": " + m.note;
                               return std::string("?");
                             }()));
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
    summary.moved = before.empty() ? 1 : largest_move(before, summary.marginals);
    before = summary.marginals;
    std::printf("[calibrate] iteration %d: %d of %zu sets scored; posterior from %s (effective sample size %.1f), moved %.3f of "
                "the prior ranges;", it, summary.valued, out.sets.size(),
                out.posterior_from.empty() ? "the sets' weights" : ("a response surface over " + std::to_string(out.surface_sets) + " sets").c_str(),
                summary.ess, summary.moved);
    for (std::size_t j = 0; j < c.parameters.size(); ++j)
      std::printf(" %s %.4g +- %.3g", c.parameters[j].name.c_str(), summary.marginals[j].mean, summary.marginals[j].sd);
    std::printf("\n");
    std::fflush(stdout);
    out.iterations.push_back(summary);
    out.core_seconds = recorded_core_seconds(runs, o.threads);
    if (it >= c.min_iterations && summary.moved <= c.tolerance && summary.ess >= c.min_effective_sets && summary.contained) {
      out.converged = true;
      out.stop_reason = "no posterior mean or sd moved by more than " + validation::significant(c.tolerance, 3) +
                        " of its prior range (" + validation::significant(summary.moved, 2) + ") in iteration " + std::to_string(it) +
                        ", and the posterior rests on " + validation::significant(summary.ess, 3) + " effective points (at least " +
                        validation::significant(c.min_effective_sets, 3) + " asked)" +
                        (out.posterior_from.empty() ? "" : " inside the region of its response surface");
      break;
    }
    if (it < c.max_iterations && o.after_iteration) {
      out.stop_reason = "still iterating: iteration " + std::to_string(it) + " of at most " + std::to_string(c.max_iterations) +
                        " done (it moved " + validation::significant(summary.moved, 2) + " of a prior range); start it again to go on";
      o.after_iteration(out);
    }
  }
  if (!out.converged)
    out.stop_reason = "max_iterations (" + std::to_string(c.max_iterations) + ") reached before the posterior settled (it moved " +
                      validation::significant(out.iterations.back().moved, 2) + " of a prior range in the last iteration and rests on " +
                      validation::significant(out.iterations.back().ess, 2) + " effective points, " +
                      validation::significant(c.min_effective_sets, 3) + " asked" +
                      (out.iterations.back().contained ? "" : "; its mean +- 2 sd reaches out of its response surface's region") + ")";
  return out;
}

}  // namespace calibration
