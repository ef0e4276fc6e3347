#pragma once
// The calibration loop's state and steps, shared by its files (not an interface of the room):
// calibrate.cpp (the loop and its sizes' runs), calibrate_plan.cpp (what a plan costs),
// calibrate_weigh.cpp (the posterior; the larger sizes: which sets run there, their discrepancies),
// calibrate_summary.cpp (an iteration's account: what it scored, whether the posterior settled).
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "calibrate.hpp"
#include "config/study_config.hpp"
#include "io/file_lock.hpp"
#include "ledger.hpp"
#include "plan/run_plan.hpp"
#include "discrepancy.hpp"
#include "surrogate.hpp"

namespace calibration {

// What a size runs with: its profile, its ledger and the sets taken from it, the lock of its results.
struct SizeState {
  const pipeline::Profile* profile = nullptr;
  pipeline::Study study;  // the study, with a part's densities only
  References refs;        // the references, with a part's densities' curves and rows only
  std::string ledger_file;
  Ledger ledger;
  std::map<std::string, ScoredSet> from_ledger;  // the sets scored from the ledger, by name
  std::unique_ptr<dem::FileLock> lock;
};

// The loop's state across iterations: the outcome so far, the draws, each size's ledger.
struct Loop {
  const Calibration& c;
  const RunOptions& o;
  pipeline::Study study;
  Outcome out;
  Sampler sampler;
  std::vector<Proposal> proposals;
  std::vector<int> drawn;
  std::vector<Marginal> before;
  std::vector<SizeState> at;  // parallel to out.sizes
  std::optional<ResponseSurface> surface;  // the first size's, of the last weighing
  std::vector<Eigen::VectorXd> first_u;    // the posterior at the first size, of the last weighing (weigh_larger may replace out's)
  std::vector<double> first_w;
  std::vector<Eigen::VectorXd> larger_u;   // the posterior at the largest size, of the last weighing (empty: none yet)
  std::vector<double> larger_w;
  std::vector<std::optional<Discrepancy>> deltas;  // per size (none at the first), of the last weighing
  bool ran_new = false;     // some size's step since the last report so far ran sets neither in a ledger nor finished here
  bool named_step = false;  // the iterations have ended; the sets named for the sizes are planned
  Loop(const Calibration& calibration, const RunOptions& options)
      : c(calibration), o(options), sampler(static_cast<int>(calibration.parameters.size())) {}
  int dimensions() const { return static_cast<int>(c.parameters.size()); }
};

// One size's plan in an iteration: the runs of every set of it still to run, with what is known of each.
struct IterationPlan {
  std::vector<ParameterSet> to_run;
  std::vector<pipeline::PlannedRun> runs;
  std::map<std::string, std::vector<std::string>> hashes;  // input hashes are of content: the same whichever sets a plan holds
  std::vector<bool> finished;        // per run: its finished result is here
  std::set<std::string> unfinished;  // the sets some run of which has none
  std::set<std::string> in_ledger;   // this iteration's sets the ledger has scored
};

// Every set planned (copies joined) at a profile into a results folder, as variants of the study.
std::vector<pipeline::PlannedRun> plan_sets(const Calibration& c, const pipeline::Study& study, const pipeline::Profile& profile,
                                            const std::vector<ParameterSet>& sets, const std::string& out,
                                            const std::string& engine);
// The input hashes of the runs each set needs, sorted, by set name.
std::map<std::string, std::vector<std::string>> run_hashes_by_set(const std::vector<pipeline::PlannedRun>& runs);

// The size whose sets size k's are chosen from and whose discrepancy it measures: the one before
// it, or the first for a part of a size.
std::size_t base_of(const Outcome& out, std::size_t k);

// Runs `runs` (the plan of `sets` at size k) in its results folder, locked; throws when interrupted.
void execute_sets(Loop& l, std::size_t k, const std::vector<ParameterSet>& sets, const std::vector<pipeline::PlannedRun>& runs);

// With RunOptions::ledger_verify: size k's ledger entries whose runs hash otherwise here are taken
// (rehashed, their verified_by said) once the verification sets, run here first, score bit for bit
// as the ledger has them; throws, naming the set and the row, when one does not (ledger_verify.cpp).
void verify_ledger(Loop& l, std::size_t k);

// Prints what size k's plan `p` of iteration `it` costs (0: none left to run) and what its `left`
// sets still to score would cost, the throughput it assumes and where that comes from.
void print_plan(const Loop& l, std::size_t k, int it, IterationPlan& p, int left);

// Weighing (calibrate_weigh.cpp). Every set of the first size weighted again; the posterior: on a
// response surface fitted to the sets near it (surrogate.hpp), when enough sets are scored, else
// the sets' own weights.
void weigh(Loop& l, int it);
// Size k's sets for iteration `it`: chosen among the sets the size before scored, near the
// posterior so far (discrepancy.hpp), up to its per_iteration and its budget.
void choose_larger_sets(Loop& l, std::size_t k, int it);
// Once the iterations end (`it`: the last), size k's sets named in the calibration file
// (Size::named) that it has not run, added to its sets with what the posterior predicts of them;
// whether any was. Throws, naming the key, for a name the size it chooses from has not scored.
bool choose_named(Loop& l, std::size_t k, int it);
// The discrepancies from each size to the next and, once each has enough pairs, the posterior at
// the largest size on the first size's surface plus them (the first size's alone is kept in
// out.first_size_only).
void weigh_larger(Loop& l);

// An iteration's account (calibrate_summary.cpp): its summary, printed; whether the posterior has
// settled after it (then out.stop_reason says why; with larger sizes, only once each has spent its
// sets and has its discrepancy); why it has not, once max_iterations is reached.
// After the named sets (after_named): the last iteration's account again, its `moved` kept.
IterationSummary summarize(Loop& l, int it, bool after_named = false);
bool settled(Loop& l, int it, const IterationSummary& summary);
std::string unsettled_reason(const Calibration& c, const Outcome& out);

}  // namespace calibration
