// What a calibration's plan costs (calibrate --plan), per size.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "loop.hpp"
#include "plan/plan_cost.hpp"
#include "sets.hpp"

namespace calibration {
namespace fs = std::filesystem;

namespace {

// The study with the sets as its variants.
pipeline::Study with_sets(const Calibration& c, pipeline::Study study, const std::vector<ParameterSet>& sets) {
  study.variants.clear();
  for (const ParameterSet& s : sets) study.variants.push_back(variant_of(c, s));
  return study;
}

}  // namespace

std::vector<pipeline::PlannedRun> plan_sets(const Calibration& c, const pipeline::Study& study, const pipeline::Profile& profile,
                                            const std::vector<ParameterSet>& sets, const std::string& out,
                                            const std::string& engine) {
  const pipeline::Study s = with_sets(c, study, sets);
  return pipeline::join_studies({{s.name, pipeline::plan_study(s, profile, out, engine)}});
}

std::map<std::string, std::vector<std::string>> run_hashes_by_set(const std::vector<pipeline::PlannedRun>& runs) {
  std::map<std::string, std::vector<std::string>> out;
  for (const pipeline::PlannedRun& r : runs)
    for (const std::string& v : r.variants) out[v].push_back(r.hash);
  for (auto& [set, hashes] : out) std::sort(hashes.begin(), hashes.end());
  return out;
}

// The throughput: of this plan's finished runs; else of this engine's other runs on this machine;
// else of the runs that scored the ledger's sets (on the machine that ran them); else the make
// bench figure. The first iteration runs what has no result here and is needed by a set not in the
// ledger (a copy of another run costs no engine time); a later iteration's set costs what a
// first-iteration set's own runs cost, whether they ran here or not; the runs every set shares are
// run once, if they are not here.
void print_plan(const Loop& l, std::size_t k, IterationPlan& p, int sets_at_most, int per_iteration) {
  const SizeState& size = l.at[k];
  const Ledger& ledger = size.ledger;
  std::vector<pipeline::PlannedRun>& runs = p.runs;
  const std::string results_root = fs::path(l.study.output).parent_path().string();
  const std::optional<double> recorded = pipeline::use_recorded_costs(runs);
  const std::optional<pipeline::MachineThroughput> machine =
      recorded ? std::nullopt : pipeline::recorded_throughput_under(results_root, l.out.engine);
  const std::optional<double> scored = ledger.throughput();
  const double throughput = recorded ? *recorded
                            : machine ? machine->particle_steps_per_s
                            : scored  ? *scored
                                      : pipeline::default_throughput;
  std::vector<bool> done(runs.size()), todo(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const pipeline::PlannedRun& r = runs[i];
    done[i] = r.copy_of >= 0 || p.finished[i];
    todo[i] = !done[i] && std::any_of(r.variants.begin(), r.variants.end(), [&](const std::string& v) { return !p.in_ledger.count(v); });
  }
  const std::vector<double> cost = pipeline::run_costs(runs, todo);
  double shared = 0, first_own = 0, own_per_set = 0, shared_needed = 0;
  int shared_runs = 0, set_runs = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].variants.size() > 1) {
      shared += cost[i], shared_runs += todo[i];
      if (!done[i]) shared_needed += runs[i].cost;
    } else {
      first_own += cost[i], set_runs += todo[i];
      if (runs[i].copy_of < 0) own_per_set += runs[i].cost / per_iteration;
    }
  }
  const int jobs = l.o.jobs;
  const double first = pipeline::estimated_wall_time_s(runs, cost, jobs, throughput);
  // Sets no iteration runs: the first iteration's finished here or in the ledger, and the ledger's
  // of later iterations (drawn again as they were, from the same scores) when its first-iteration
  // entries were scored on runs of this plan's inputs (an engine or a scene changed since: none).
  const bool current = std::all_of(ledger.sets.begin(), ledger.sets.end(), [&](const ScoredSet& e) {
    const auto h = p.hashes.find(e.name);
    return h == p.hashes.end() || h->second == e.run_hashes;
  });
  std::size_t scored_sets = 0;
  for (const auto& entry : p.hashes) scored_sets += !p.unfinished.count(entry.first) || p.in_ledger.count(entry.first);
  if (current)
    for (const ScoredSet& e : ledger.sets) scored_sets += !p.hashes.count(e.name);
  const double left = std::max(0.0, static_cast<double>(sets_at_most) - static_cast<double>(scored_sets));
  const double total = left > 0 ? shared_needed + own_per_set * left : 0;
  const SizeOutcome& so = l.out.sizes[k];
  const std::string what = l.out.sizes.size() > 1 ? "size " + so.label() + " (lattice " + std::to_string(size.profile->lattice) + ", " +
                                                        std::to_string(so.seeds.size()) + " sample(s) a set): "
                                                  : "";
  if (k == 0)
    std::printf("calibration %s: %zu parameter(s), %d sets per iteration, at most %d iterations\n", l.c.name.c_str(),
                l.c.parameters.size(), l.c.batch, l.c.max_iterations);
  std::printf("%sfirst iteration: %zu runs (%d shared by every set, %d for its sets still to run), %.3g particle-steps, "
              "about %.1f min on %d core(s)\n", what.c_str(), runs.size(), shared_runs, set_runs, shared + first_own, first / 60, jobs);
  if (ledger.other_sets > 0)
    std::printf("the ledger of scored sets (%s) holds %d set(s) scored against other references: none is "
                "taken, and a run keeps it aside (scored_sets.kept-N.json) before it writes its own\n", size.ledger_file.c_str(), ledger.other_sets);
  if (!ledger.sets.empty())
    std::printf("the ledger of scored sets (%s) holds %zu set(s), %zu of them of the first iteration: "
                "%s\n", size.ledger_file.c_str(), ledger.sets.size(), p.in_ledger.size(),
                current ? "they are not run again"
                        : "some were scored on runs of other inputs (an engine or a scene changed): those run again, "
                          "and the later iterations' are counted as still to score");
  std::printf("%sall %d iterations at most (%.0f sets still to score): %.3g particle-steps, %.1f core-min, about %.1f min on %d core(s)\n",
              what.c_str(), l.c.max_iterations, left, total, total / throughput / 60, total / throughput / 60 / jobs, jobs);
  const std::string from = recorded ? "recorded by the finished runs in the results folder"
                           : machine ? "recorded by " + std::to_string(machine->runs) + " finished runs of this engine in " +
                                           std::to_string(machine->studies) + " results folders under " + results_root
                           : scored ? "recorded by the runs of the ledger's scored sets, on the machine that ran them"
                                    : "the engine's make bench figure; no run of this engine has finished here yet";
  std::printf("(throughput %.3g particle-steps/s per core: %s)\n", throughput, from.c_str());
}

}  // namespace calibration
