#pragma once
// The calibration loop: draw a batch of parameter sets, run them through the pipeline (reusing
// every finished run, and every set the report folder's ledger of scored sets holds: ledger.hpp),
// score them against the references, weight every set so far, and stop when the posterior no
// longer moves (posterior.hpp for the method).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "calibration_file.hpp"
#include "posterior.hpp"
#include "references.hpp"
#include "study/posterior_summary.hpp"
#include "study/stamp.hpp"
#include "sets.hpp"

namespace calibration {

struct Outcome;

struct RunOptions {
  std::string dem;          // the engine
  std::string profile;      // the study's profile ("": its default)
  int jobs = 1, threads = 1;
  std::string executor = "local";  // or slurm
  bool plan_only = false;
  // Take a ledger's scores of sets whose scenes are those this plan runs even when another engine
  // scored them (the runs' hashes match when planned with the engine the ledger's stamp names): the
  // size's stamp and the report then name that engine and how many sets it scored.
  bool ledger_engine = false;
  // Run nothing: every set must come from a ledger (a replay of a committed calibration).
  bool ledger_only = false;
  // Take a ledger's sets whose runs hash otherwise here (the scenes' text or the engine changed
  // since they were scored) by their names and unit values, once this many of them, spread over
  // the ledger, run again here give every row's mean and sd bit for bit as the ledger has them
  // (ledger_verify.cpp); else the calibration stops before it takes any. 0: never.
  int ledger_verify = 0;
  // Called after each iteration but the last with the outcome so far (stop_reason says it goes
  // on): the report is then written every iteration, and a calibration a session's end stops
  // leaves its posterior so far.
  std::function<void(const Outcome&)> after_iteration;
};

struct IterationSummary {
  int number = 0;
  int sets = 0;             // run this iteration
  int valued = 0;           // of all sets so far, those with a misfit
  double ess = 0;           // effective sample size of the posterior's points after it
  double sets_ess = 0;      // of the sets' own weights (exp(-chi2/2) over the proposals)
  bool contained = true;    // on a response surface: the posterior's mean +- 2 sd inside its region
  std::vector<Marginal> marginals;
  double moved = 0;         // the largest change of a unit mean or sd since the iteration before
};

// The sets' runs at one size (a profile of the study): at the first every set, at a larger one the
// sets chosen to run there (discrepancy.hpp; their `iteration` is the one that chose them).
struct SizeOutcome {
  std::string profile, results;  // results: the folder of the runs
  std::vector<std::string> densities;  // a part of the largest size: the densities it runs (else empty: all)
  // "check" or, for a part of a size, "check (dense)": how a size is named in messages and tables.
  std::string label() const {
    std::string names;
    for (const std::string& d : densities) names += (names.empty() ? "" : ", ") + d;
    return names.empty() ? profile : profile + " (" + names + ")";
  }
  std::vector<std::int64_t> seeds;
  int budget = 0;                // a larger size's sets at most, chosen where they inform the posterior most
  // Then the sets run to confirm the posterior's best prediction at this size (Size::confirm at
  // most): each set's name and the probability the posterior gave, when it chose it, that one
  // sample of it agrees with every scalar row of this size (and row by row, in `rows`' order).
  int confirm = 0;
  // Then the new sets run at the point of the surface's region where that probability is largest
  // (Size::probe at most; the reach's maximum), recorded as confirmed sets too.
  int probe = 0;
  // Then, once the iterations end, the sets of the first size the calibration file names for this
  // size (Size::named), recorded as confirmed sets too when the posterior here predicts them.
  std::vector<std::string> named;
  struct Confirmed {
    std::string set;
    double probability = 0;
    std::vector<std::string> rows;
    std::vector<double> row_probability;
    validation::Choice chosen = validation::Choice::best;
  };
  int confirmed_of_kind(validation::Choice kind) const {
    return static_cast<int>(std::count_if(confirmed.begin(), confirmed.end(), [&](const Confirmed& c) { return c.chosen == kind; }));
  }
  std::vector<Confirmed> confirmed;
  // A confirmed set's misfit of each of its rows, on its samples at this size (none: the set not
  // scored yet, or the row without a value), and its verdict on each (none: not judged either).
  std::vector<const RowMisfit*> measured(const Confirmed& c) const {
    std::vector<const RowMisfit*> out(c.rows.size(), nullptr);
    const auto set = std::find_if(sets.begin(), sets.end(), [&](const ParameterSet& p) { return p.name == c.set; });
    if (set == sets.end() || !set->misfit.valued) return out;
    for (std::size_t i = 0; i < c.rows.size(); ++i)
      for (const RowMisfit& m : set->misfit.rows)
        if (m.name == c.rows[i] && m.valued) out[i] = &m;
    return out;
  }
  std::vector<std::optional<bool>> verdicts(const Confirmed& c) const {
    std::vector<std::optional<bool>> out;
    for (const RowMisfit* m : measured(c)) out.push_back(m ? m->consistent : std::nullopt);
    return out;
  }
  int sets_in_iterations() const { return budget + confirm + probe; }
  int sets_at_most() const { return sets_in_iterations() + static_cast<int>(named.size()); }
  // Once every size has its discrepancy: how far the posterior at this size lets its scalar rows
  // be reached (discrepancy.hpp, reach): the points of the surface's region tried, and per row
  // (`reach_rows`) the largest probability that one sample agrees with it; with all of them at once.
  int reach_points = 0;
  std::vector<std::string> reach_rows;
  std::vector<double> reach_most;
  double reach_all = 0;
  std::vector<ParameterSet> sets;
  int runs = 0;                  // runs planned over all iterations (reused ones included)
  double core_seconds = 0;       // recorded by their results (wall time x threads)
  int ledger_sets = 0;           // sets whose score came from the ledger (ledger.hpp), not from runs here
  // Of those, the sets another engine scored (RunOptions::ledger_engine), and that engine.
  int other_engine_sets = 0;
  std::string other_engine;
  // Of those, the sets taken by their names and unit values after a verification (RunOptions::
  // ledger_verify), and what verified them (the sets run again, the engines).
  int verified_sets = 0;
  std::string verified_by;
  validation::Stamp stamp;       // of the runs (engine, baseline, spheres, samples, date)
  std::map<std::string, std::vector<validation::Sample>> samples;  // of each set (for the figures)
  // A larger size's discrepancy from the size before (discrepancy.hpp): the sets it was fitted to
  // (0 while there are too few), whether it has slopes, and per reference row its value and
  // prediction sd at the posterior's mean, point by point (a scalar row: one).
  int discrepancy_pairs = 0;
  bool discrepancy_linear = false;
  struct Change {
    std::string row;
    std::vector<double> shift, shift_sd;
  };
  std::vector<Change> changes;
};

struct Outcome {
  Calibration calibration;
  References references;
  std::string engine;
  std::vector<SizeOutcome> sizes;  // [0]: where every set runs; then each larger size
  std::vector<double> weights;  // of sizes[0]'s sets: likelihood exp(-chi2/2) over the proposals' mixture
  // The posterior's points: on the response surface (posterior_from "response surface"), else the
  // sets with their weights (posterior_from empty). With larger sizes, at the largest once each
  // has its discrepancy (SizeOutcome::discrepancy_pairs).
  std::vector<Eigen::VectorXd> posterior_u;
  std::vector<double> posterior_w;
  std::string posterior_from;
  // With larger sizes: the posterior of the first size's surface alone (what the larger sizes changed).
  std::vector<Marginal> first_size_only;
  int surface_sets = 0;
  double surface_noise = 0;  // the surface's residual sd over the reference mean's sd, on average
  Eigen::VectorXd region_centre, region_sd;
  std::vector<IterationSummary> iterations;
  bool converged = false;
  std::string stop_reason;
  // The sets that could not be scored (a run the engine refused or stopped, a point no run
  // reached), each "name: why": they weigh nothing, so the posterior covers only the rest of the prior.
  std::vector<std::string> unscored;

  const SizeOutcome& first() const { return sizes.front(); }
  SizeOutcome& first() { return sizes.front(); }
  const SizeOutcome& largest() const { return sizes.back(); }
  // Whether the sizes after the first are parts of one size, each running some densities.
  bool in_parts() const { return sizes.size() > 1 && !sizes.back().densities.empty(); }
  // The size whose sets size k's are chosen from and whose discrepancy it measures: the one before
  // it, or the first for a part of a size.
  std::size_t base_of(std::size_t k) const { return sizes[k].densities.empty() ? k - 1 : 0; }
  double core_seconds() const;
};

// Runs the calibration (or, with plan_only, prints what its first iteration would run and what
// max_iterations would cost, and returns none).
std::optional<Outcome> run_calibration(const Calibration& c, const RunOptions& o);

}  // namespace calibration
