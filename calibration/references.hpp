#pragma once
// What a calibration fits: curves (a lab test's y against x, e.g. q/p and volumetric strain against
// axial strain, with the specimens' scatter) and, optionally, the scalar rows of a validate
// reference file (reference_data/paper.yaml or a user's own), each turned into a misfit chi^2.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "judge/rows.hpp"
#include "study/results.hpp"

namespace calibration {

struct CurvePoint {
  double x = 0, y = 0;
  double sd = 0;  // the specimens' standard deviation of y at x (0: one specimen, or not given)
  std::vector<double> specimens;  // each specimen's y at x, when the CSV gives them (specimen_1, ...)
};

// The points of curves read on the same runs (density and test) whose CSVs give each specimen's
// value: a specimen that is stiffer at one strain is stiffer at the next, and its volume follows,
// so the deviation of a mean of a few specimens (or samples) from the population's is shared by
// the points. Their correlation over the specimens, shrunk towards none by 1 / (specimens - 1) (an
// estimate from a few specimens is noisy, and the shrunk one is positive definite), is that
// deviation's correlation, for the lab's specimens and for the model's samples alike.
struct CorrelatedPoints {
  std::vector<std::pair<std::size_t, std::size_t>> points;  // (curve, point)
  Eigen::MatrixXd correlation;
};

struct CurveRow {
  std::string name;
  std::string file;           // the CSV: x, y and optionally sd columns, a header line naming them
  std::string x, y;           // the run's time-series columns (strain_3, q_over_p, volumetric_strain, ...)
  std::string density, test;  // the runs it reads: the study's density and test names
  int specimens = 1;          // how many specimens the curve averages (its sd is their scatter)
  double tolerance = 0;       // how well y is read off the source (digitising), in y's unit
  std::vector<CurvePoint> points;
};

struct References {
  std::string file;
  std::string source;              // where the reference values come from (shown in the report)
  std::vector<CurveRow> curves;
  std::string rows_file;           // a validate reference file, or ""
  std::vector<validation::Row> rows;
  std::vector<CorrelatedPoints> correlated;  // groups of curve points, each point in one at most
};

// The groups of points whose specimens are given (at least 3, as many in every point of a group).
std::vector<CorrelatedPoints> correlated_points(const std::vector<CurveRow>& curves);

// Reads a calibration's reference file (YAML; errors name the file and the key) and its curves.
References read_references(const std::string& file, const std::string& profile);
// The curves and rows of `refs` that read these densities' runs (a part of a size: calibration_file.hpp).
References only_densities(const References& refs, const std::vector<std::string>& densities);
std::vector<CurvePoint> read_curve_csv(const std::string& file);

// The misfit of one row on a parameter set's samples.
struct RowMisfit {
  std::string name;
  double chi2 = 0;  // sum over the row's points of ((model - reference) / sigma)^2
  int points = 0;
  std::string note;  // why the row has no value (a run that does not reach a point's x, ...)
  bool valued = true;
  std::vector<double> model;     // a curve's: the samples' mean y at each point (surrogate.hpp fits it)
  std::vector<double> model_sd;  // ... and their sd (0 for one sample)
  int samples = 0;               // the samples it was computed on
  // A scalar row judged by validate's rules on these samples (validation::evaluate): consistent or
  // not; empty for a curve and for a row validate does not judge.
  std::optional<bool> consistent;
};

struct SetMisfit {
  std::vector<RowMisfit> rows;
  double chi2 = 0;
  bool valued = true;  // false: some row could not be computed (the set's likelihood is 0)
  std::vector<std::string> left_out;  // samples not scored, each with the runs it lacks (score_complete)
};

// The set scored on its samples whose every run finished, when at least `min_samples` (or all,
// when there are fewer) did; the others are left out, named with the runs they lack. A run that
// stops on an engine guard is missing data about the set, not evidence against it: the decisions
// study's local-damping loose preparation of one sample stopped on the energy guard at its first
// contacts (docs/open-questions.md). With fewer complete samples, score() on all of them says
// which row cannot be computed.
// A misfit scored against `from` restricted to the curves and rows of `to` (by name; `to` holds
// a subset of `from`'s).
SetMisfit projected(const SetMisfit& m, const References& from, const References& to);

SetMisfit score_complete(const References& refs, const std::vector<validation::Sample>& samples, std::size_t min_samples = 2);

// The curve's y on one run: on the run's last stage, where x first reaches each point's x (linear
// between the two rows that bracket it); empty when the stage never reaches it.
std::vector<std::optional<double>> curve_on_run(const CurveRow& c, const validation::TestResult& t);

// chi^2 of each row on the samples (one DensityResults map per sample) of a parameter set:
// - a curve point: (mean of the samples' y - y_ref)^2 / sigma^2, sigma^2 = tolerance^2 + sd^2 /
//   specimens + s^2 / m, s the samples' sd of y at the point when m >= 3 samples, else the
//   reference's sd (one specimen's scatter stands for one sample's: 1 or 2 samples cannot measure it);
// - a scalar row of rule interval: the distance of the samples' mean to the reference's region,
//   over sigma^2 = sd^2 (1 + 1/m) (the reference is one sample), sd at least the row's resolution;
// - a row of rule majority or every (a trend, an ordering): -2 ln((k + 1/2) / (m + 1)), k of the m
//   samples in which the statement holds (0.0 when all hold in many samples).
SetMisfit score(const References& refs, const std::vector<validation::Sample>& samples);

// score()'s chi^2 of one curve point, from the samples' mean and sd of y at it, and of a scalar row
// of rule interval, from the samples' mean and sd of its value.
double point_chi2(const CurveRow& c, const CurvePoint& p, double mean, double sd, int samples);
double interval_chi2(const validation::Row& row, double mean, double sd, int samples);

// Why a misfit kept elsewhere (a ledger's) does not follow from what it keeps, "" if it does: each
// row's chi^2 computed again from its values (a curve's mean and sd per point, a scalar row's mean
// and sd) against `refs`, a trend's whether it is that of a whole count of samples, the total the
// sum of the rows. An edited chi^2 is caught; values edited to agree with it are not.
std::string recheck(const References& refs, const SetMisfit& s);

}  // namespace calibration
