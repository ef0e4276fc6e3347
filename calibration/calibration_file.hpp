#pragma once
// A calibration file (YAML): the study whose runs are calibrated, the references they are fitted
// to, the parameters with their priors, and how the iterations go (calibration/README.md).
#include <string>
#include <vector>

#include "parameters.hpp"

namespace calibration {

// A size the sets run at: a profile of the study (its lattice and seeds). Every set runs at the
// first; a larger one runs `sets` of the sets the size before it scored, `per_iteration` at most
// each iteration, chosen where they inform the posterior most (discrepancy.hpp); then `confirm`
// more, one an iteration, each the set the posterior at that size expects most likely to agree
// with all of its rows (a check of its best prediction); then `probe` more, one an iteration, each
// a new set at the point of the surface's region where that probability is largest (the reach's
// maximum, discrepancy.hpp), run at the first size too for its discrepancy pair; then, once the
// iterations end, the sets of the first size `named` for it (a researcher's choice: e.g. one whose
// rows the surface smooths over), which enter its discrepancy and the posterior at the end.
struct Size {
  std::string profile;
  int sets = 0;           // a larger size's sets at most (0: the first size, every set)
  int per_iteration = 0;  // a larger size's sets chosen per iteration at most
  int confirm = 0;        // a larger size's sets run after those to confirm the posterior's best prediction
  int probe = 0;          // then new sets at the reach's maximum
  std::vector<std::string> named;  // then, once the iterations end, these sets of the first size
  // A part of the largest size: its sets run these densities' tests only, and its discrepancy from
  // the first size is fitted to these densities' rows and curves only (empty: every density). The
  // parts of a size share its profile and split its densities.
  std::vector<std::string> densities;
};

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
  // `sizes:`, smallest first; empty: one size, the profile calibrate is given (or the study's default).
  std::vector<Size> sizes;
};

// How a calibration names the first size's sets: i<iteration>s<number> for a drawn one (the number
// in three digits: i2s007), i<iteration>p<size> for a probe run for size k (i6p2).
std::string drawn_set_name(int iteration, int number);
std::string probe_set_name(int iteration, std::size_t size);
// Whether `name` is one of those that calibration `c` can give (iteration <= max_iterations, number
// <= batch, size < its sizes); whether that set was scored is known once the iterations end.
bool can_name_set(const Calibration& c, const std::string& name);

// Reads and checks the file; errors name the file, the key and the allowed values.
Calibration read_calibration(const std::string& file);

}  // namespace calibration
