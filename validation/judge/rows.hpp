#pragma once
// The rows of a reference file (reference_data/paper.yaml, or a user's own: validation/README.md)
// and their evaluation on an ensemble of samples: each row's value per sample, the spread, and the
// verdict against the reference's statement.
#include <set>
#include <string>
#include <vector>

#include "study/ensemble.hpp"
#include "judge/quantities.hpp"
#include "study/results.hpp"

namespace validation {

struct Row {
  std::string name, quantity, check, reason, source;
  // Which runs the row reads, by the names the study gives them (runs.tsv); "" leaves the choice to
  // the study when it has only one (row_runs.hpp). `test` is, for an ordering (ev_lead, ev_lag), the
  // test the ordering is about; for another quantity that reads tests, the one test it reads.
  std::string variant, density, test;
  double reference = 0, tolerance = 0;
  // The smallest difference of the quantity that means something (its measurement's resolution):
  // shifts are counted in units of max(sd, resolution), so a scatter below it cannot inflate them.
  double resolution = 0;
  int cycle = 0, from_cycle = 0, to_cycle = 0;
  bool must_pass = false;
  // The reference holds in the quasi-static limit (inertial number I -> 0), e.g. a published
  // critical-state friction of slowly sheared spheres: a run at a finite rate cannot judge it, so
  // the row is not judged here (its values are shown); the critical-state section sets it beside
  // the value its rate series extrapolates to I -> 0.
  bool quasi_static = false;
  std::string group;  // the report groups rows (and draws one tornado chart per group)
  // How the row is judged: "interval" (a value read from the paper: consistent when the paper's
  // region overlaps the 95 % prediction interval of one sample) or "majority" (a trend or an
  // ordering: consistent when the statement holds in more than half of the samples) or "every"
  // (no scatter, e.g. a perfect lattice: consistent when it holds in every sample, one or more).
  std::string rule = "interval";
  std::string origin;  // where the row is written, for messages: `FILE: rows[i] ("NAME")`
};

struct References {
  std::string source;  // where the values come from
  std::string label;   // what the tables call the reference: "paper" in paper.yaml, "reference" by default
  std::vector<Row> rows;
  std::set<std::string> profiles;  // the profiles some row names (`profiles:` entries)
};

// The rows of a reference file for a profile. A row may carry per-profile entries (`profiles:
// {NAME: {tolerance, must_pass, reason}}`). If any row has one for `profile`, only those rows are
// kept, with that entry's values (paper.yaml's `quick`: its samples are smaller and its tests
// shorter); otherwise every row, with its own values. Throws dem::ConfigError naming the file, the
// row and the key on bad input (an unknown key lists a row's keys, an unknown quantity the known ones).
References read_references(const std::string& file, const std::string& profile);
std::vector<Row> load_references(const std::string& file, const std::string& profile);  // read_references().rows

struct RowResult {
  struct PerSample {
    std::string sample;
    Measured measured;
  };
  std::vector<PerSample> samples;
  Spread spread;              // over the samples that have a value
  Region paper;               // the values that agree with the paper's statement
  Verdict verdict = Verdict::NotJudged;
  int holds = 0;              // samples whose own value lies in the paper's region
  int valued = 0;             // samples with a value
  // Why the verdict cannot mean much (judge_values): the quantity does not fit the runs it read,
  // or the samples are too few for the row's tolerance. The verdict stands; the tables say it.
  std::vector<std::string> warnings;
};

// A row of rule interval whose 95 % interval of one sample is wider than this many times its
// tolerance is judged, but warned about: the paper's value then lies in it almost whatever it is
// (2 samples: t(0.975, 1) = 12.7 makes it the mean ± 15.6 sd).
constexpr double too_few_width = 4;

// The quantities the critical-state section takes to the quasi-static limit I -> 0 (its rate
// series, compare-runs critical-state --rates: the friction angle at the critical state). A
// quasi-static row of one of them is set beside that limit there; the warning of a quasi-static
// row names the section only for these.
bool taken_to_quasi_static_limit(const std::string& quantity);

// Whether the row's bound is this project's reading of the reference's words (a trend or an
// ordering, rule majority: "grows", "independent of cycles", for which the reference gives no
// number), not a value the reference states (rule interval, or every: a lattice's formula value
// ± the row's tolerance). The verdict tables mark such a bound †.
bool bound_is_reading(const Row& row);

// The spread, the samples that hold and the verdict of a row's per-sample values.
RowResult judge_values(const Row& row, std::vector<RowResult::PerSample> samples);

// `r` with every sample's value moved by `by`, judged again: what an ensemble would show if a
// reading shifted each of its samples by the shift the reading caused in another ensemble.
RowResult shifted(const Row& row, const RowResult& r, double by);

// `densities` of each sample: the sample's name and its results for the row's density.
RowResult evaluate(const Row& row, const std::vector<std::pair<std::string, const DensityResults*>>& samples);

// evaluate() on every sample of an ensemble.
RowResult evaluate(const Row& row, const std::vector<Sample>& samples);

}  // namespace validation
