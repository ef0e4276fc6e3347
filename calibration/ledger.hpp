#pragma once
// A calibration's scored sets, kept in its report folder (scored_sets.json) and committed with
// it: a calibration that takes several sessions, on machines that do not keep the runs' results,
// takes a set's score from here instead of running the set again. An entry counts only for the
// same set drawn again (its name and unit values), whose runs are planned with the same input
// hashes (scene and engine source), scored against references of the same content.
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
};

struct Ledger {
  std::string references_hash;
  validation::Stamp stamp;  // of the runs the entries were scored on
  std::vector<ScoredSet> sets;

  // The entry of the set, or null when there is none with these unit values and run hashes.
  const ScoredSet* find(const std::string& name, const Eigen::VectorXd& u, const std::vector<std::string>& run_hashes) const;
  // The particle-steps per core-second its entries' runs recorded, on the machine that ran them
  // (null when no entry recorded both).
  std::optional<double> throughput() const;
};

// A hash of the references' content: their file, the rows file it reads and every curve's CSV.
std::string references_hash(const References& refs);

// The ledger in `file`: empty when there is none or when it was scored against other references
// (`references_hash`); throws, naming the file and the key, when it cannot be read as one.
Ledger read_ledger(const std::string& file, const std::string& references_hash);
void write_ledger(const std::string& file, const Ledger& ledger);

}  // namespace calibration
