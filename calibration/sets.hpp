#pragma once
// Parameter sets as the pipeline runs them: each set is a variant of the calibration's study (its
// parameters' keys as overrides), planned, run and read back as an ensemble of samples.
#include <map>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration_file.hpp"
#include "config/study_config.hpp"
#include "plan/run_plan.hpp"
#include "references.hpp"
#include "study/results.hpp"

namespace calibration {

struct ParameterSet {
  std::string name;  // i<iteration>s<index> (a probe: i<iteration>p<size>), the variant's name
  int iteration = 0;
  Eigen::VectorXd u;  // on the unit cube
  double log_likelihood = 0;
  SetMisfit misfit;
  std::string stopped;  // the engine's message when it stopped (or refused) a run of the set, else ""
  // Drawn from the iteration's proposal; else chosen (a probe at the reach's maximum): such a set
  // takes part in the response surface but no importance weight (no proposal drew it).
  bool drawn = true;
  // Its log-likelihood among the draws' importance weights: -infinity (no weight) when not drawn.
  double drawn_log_likelihood() const { return drawn ? log_likelihood : -std::numeric_limits<double>::infinity(); }
};

// The variant that runs a set: each parameter's keys set to its value, in the runs it applies to;
// may_fail (a run the engine stops is recorded, not run again).
pipeline::Variant variant_of(const Calibration& c, const ParameterSet& s);

// The samples of each variant (by name) from a plan's runs: per seed, the preparation's and the
// tests' complete results; a result that is missing or not complete is left out (the set's
// misfit then says which).
std::map<std::string, std::vector<validation::Sample>> samples_of_sets(const std::vector<pipeline::PlannedRun>& runs);

}  // namespace calibration
