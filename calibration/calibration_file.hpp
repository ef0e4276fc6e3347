#pragma once
// A calibration file (YAML): the study whose runs are calibrated, the references they are fitted
// to, the parameters with their priors, and how the iterations go (calibration/README.md).
#include <string>
#include <vector>

#include "parameters.hpp"

namespace calibration {

struct Calibration {
  std::string file;
  std::string name;
  std::string study;       // the study file (absolute): its densities, tests, profiles and seeds
  std::string references;  // the reference file (absolute): references.hpp
  std::string report;      // folder of posterior.json, the tables and figures (absolute)
  std::vector<Parameter> parameters;
  int batch = 16;           // parameter sets per iteration
  int max_iterations = 8;
  int min_iterations = 3;
  // Stop when, from one iteration to the next, no parameter's posterior mean or sd moves by more
  // than this fraction of its prior range (on the unit interval).
  double tolerance = 0.03;
  // ... and the posterior rests on at least this many effective sets (Kish): with fewer, its
  // quantiles are those of a handful of points. Default: one batch.
  double min_effective_sets = 16;
  double prior_share = 0.2;  // of each proposal after the first (posterior.hpp)
};

// Reads and checks the file; errors name the file, the key and the allowed values.
Calibration read_calibration(const std::string& file);

}  // namespace calibration
