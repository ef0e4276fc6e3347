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
// bench figure. Iteration `it` (the first the ledgers and the finished runs do not cover; 0: none,
// the calibration is complete) runs what has no result here and is needed by a set not in the
// ledger (a copy of another run costs no engine time); of the `left` sets still to score, each
// after this iteration's costs what this iteration's sets' own runs cost on average, whether they
// ran here or not; the runs every set shares are run once, in this iteration, if they are not here.
void print_plan(const Loop& l, std::size_t k, int it, IterationPlan& p, int left) {
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
    todo[i] = it > 0 && !done[i] && std::any_of(r.variants.begin(), r.variants.end(), [&](const std::string& v) { return !p.in_ledger.count(v); });
  }
  const std::vector<double> cost = pipeline::run_costs(runs, todo);
  // Each set of this iteration: its own runs' cost (a run of one set only, not a copy).
  std::map<std::string, double> own;
  for (const ParameterSet& s : l.out.sizes[k].sets)
    if (s.iteration == it) own[s.name] = 0;
  double shared = 0, first_own = 0;
  int shared_runs = 0, set_runs = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].variants.size() > 1) {
      shared += cost[i], shared_runs += todo[i];
    } else {
      first_own += cost[i], set_runs += todo[i];
      if (const auto o = own.find(runs[i].variants.front()); o != own.end() && runs[i].copy_of < 0) o->second += runs[i].cost;
    }
  }
  double own_per_set = 0;
  for (const auto& [name, c] : own) own_per_set += c / static_cast<double>(own.size());
  const int jobs = l.o.jobs;
  const double first = pipeline::estimated_wall_time_s(runs, cost, jobs, throughput);
  // This iteration's runs still to run, then each set after it at the average's cost.
  // This iteration's sets not scored yet; of those, the ones whose every run has finished here
  // (scored on them without running anything).
  int unscored_here = 0, ready = 0;
  for (const ParameterSet& s : l.out.sizes[k].sets)
    if (s.iteration == it && s.misfit.rows.empty()) ++unscored_here, ready += !p.unfinished.count(s.name);
  const double total = left > 0 ? shared + first_own + own_per_set * std::max(0, left - unscored_here) : 0;
  const SizeOutcome& so = l.out.sizes[k];
  const std::string what = l.out.sizes.size() > 1 ? "size " + so.label() + " (lattice " + std::to_string(size.profile->lattice) + ", " +
                                                        std::to_string(so.seeds.size()) + " sample(s) a set): "
                                                  : "";
  if (k == 0)
    std::printf("calibration %s: %zu parameter(s), %d sets per iteration, at most %d iterations%s\n", l.c.name.c_str(),
                l.c.parameters.size(), l.c.batch, l.c.max_iterations,
                it == 1   ? ""
                : l.named_step ? "; every iteration replays from the ledgers and the finished runs; then the sets named for a size run"
                : it == 0 ? "; every iteration replays from the ledgers and the finished runs: nothing to run"
                : it == 2 ? "; iteration 1 replays from the ledgers and the finished runs"
                          : ("; iterations 1 to " + std::to_string(it - 1) + " replay from the ledgers and the finished runs").c_str());
  if (it > 0)
    std::printf("%s%s: %zu runs (%d shared by every set, %d for its sets still to run), %.3g particle-steps, about %.1f min on %d core(s)\n",
                what.c_str(), l.named_step ? "the named sets" : it == 1 ? "first iteration" : ("iteration " + std::to_string(it)).c_str(), runs.size(), shared_runs,
                set_runs, shared + first_own, first / 60, jobs);
  if (ledger.other_sets > 0)
    std::printf("the ledger of scored sets (%s) holds %d set(s) scored against other references: none is "
                "taken, and a run keeps it aside (scored_sets.kept-N.json) before it writes its own\n", size.ledger_file.c_str(), ledger.other_sets);
  if (!ledger.sets.empty())
    std::printf("the ledger of scored sets (%s) holds %zu set(s); %zu taken so far (a set is taken when an iteration draws it "
                "again, at the unit values and on runs of the inputs it was scored with)\n",
                size.ledger_file.c_str(), ledger.sets.size(), size.from_ledger.size());
  std::printf("%sall %d iterations at most (%d sets still to score): %.3g particle-steps, %.1f core-min, about %.1f min on %d core(s)\n",
              what.c_str(), l.c.max_iterations, std::max(0, left - ready), total, total / throughput / 60, total / throughput / 60 / jobs, jobs);
  const std::string from = recorded ? "recorded by the finished runs in the results folder"
                           : machine ? "recorded by " + std::to_string(machine->runs) + " finished runs of this engine in " +
                                           std::to_string(machine->studies) + " results folders under " + results_root
                           : scored ? "recorded by the runs of the ledger's scored sets, on the machine that ran them"
                                    : "the engine's make bench figure; no run of this engine has finished here yet";
  std::printf("(throughput %.3g particle-steps/s per core: %s)\n", throughput, from.c_str());
}

}  // namespace calibration
