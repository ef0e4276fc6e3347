#pragma once
// A calibration's scored sets, kept in its report folder (scored_sets.json) and committed with
// it: a calibration that takes several sessions, on machines that do not keep the runs' results,
// takes a set's score from here instead of running the set again. An entry counts only for the
// same set drawn again (its name and unit values), whose runs are planned with the same input
// hashes (scene and engine source), scored against the same references (references_key).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "references.hpp"
#include "study/stamp.hpp"

namespace calibration {

struct ScoredSet {
  std::string name;
  Eigen::VectorXd u;
  std::vector<std::string> run_hashes;  // of every run the set needs, sorted
  SetMisfit misfit;
  double runs = 0;          // its share of the runs it needs (a run k sets need counts 1/k for each)
  double core_seconds = 0;  // its share of their recorded cost
  double particle_steps = 0;  // its share of their recorded particle-steps (0 in entries written without)
  // Empty for a set scored on runs of these hashes; else how its score came to stand for them:
  // scored on runs that hashed otherwise, taken after a verification (RunOptions::ledger_verify).
  std::string verified_by;
};

struct Ledger {
  std::string references_key;  // references_key() of the references its sets were scored against
  validation::Stamp stamp;  // of the runs the entries were scored on
  std::vector<ScoredSet> sets;
  int other_sets = 0;  // read_ledger: the file's sets scored against other references (not taken)

  // The entry of the set, or null when there is none with these unit values and run hashes.
  const ScoredSet* find(const std::string& name, const Eigen::VectorXd& u, const std::vector<std::string>& run_hashes) const;
  // The entry of the set whatever its runs' hashes (null when there is none with these unit values).
  ScoredSet* find_set(const std::string& name, const Eigen::VectorXd& u);
  // The particle-steps per core-second its entries' runs recorded, on the machine that ran them
  // (null when no entry recorded both).
  std::optional<double> throughput() const;
};

// The key of what the scores depend on: the references as parsed (each curve's name, columns,
// runs, specimens, tolerance and points; each row's name, quantity, selectors, reference,
// tolerance, resolution, cycles and rule), not their files' bytes: a comment, a reordered key or a
// number written another way changes no score, and so keeps the ledger.
std::string references_key(const References& refs);

// The ledger in `file`: its sets when they were scored against `refs` (its references_key; in a
// ledger written before there were keys, the hash of the reference files' bytes), else none;
// throws, naming the file and the key, when it cannot be read as one.
Ledger read_ledger(const std::string& file, const References& refs);

// Writes `ledger` (scored against `refs`) to `file`. A ledger there that `ledger` does not hold in
// full (scored against other references, or with a set `ledger` lacks) is never overwritten: it
// is first moved aside to scored_sets.kept-<N>.json beside it, whose path is returned ("" when
// nothing was moved).
std::string write_ledger(const std::string& file, const Ledger& ledger, const References& refs);

// Rekeys the ledger in `file`, of schema 1 (keyed on its reference files' bytes), to the references
// as parsed: `then` must be the references it was scored against (their files' bytes hash as the
// ledger says) and parse as `now` does (the same references_key). A comment or a reformatted number
// in a reference file then no longer discards its scores. Throws, naming what does not hold; the
// ledger before is kept aside (write_ledger). Returns the number of sets.
int rekey_ledger(const std::string& file, const References& then, const References& now);

}  // namespace calibration
