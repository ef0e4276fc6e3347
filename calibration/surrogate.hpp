#pragma once
// A response surface: each curve point's model value as a quadratic function of the parameters,
// fitted to the sets run near the posterior. A DEM sample's response is chaotic: two sets a hair
// apart follow different trajectories, so each set's misfit carries the noise of its few samples,
// and weighing sets by exp(-chi2/2) lets the luckiest set carry the posterior (its effective sample
// size stays near 1 however many sets are run). Fitted over many sets, the surface averages that
// noise out; the residual scatter about it is the noise, and its prediction variance enters the
// likelihood beside the reference's own uncertainty. The posterior is then sampled on the surface
// (thousands of points, no runs) inside the region the fitted sets cover.
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "posterior.hpp"
#include "references.hpp"
#include "sets.hpp"

namespace calibration {

struct Discrepancy;  // discrepancy.hpp: from this surface's size to a larger one

// y ~ b . x(z), x = (1, z_i, z_i z_j for i <= j), z the unit coordinates standardised to the region.
struct Quadratic {
  // The variance of one sample's y about the population's mean (its packing's own deviation, which
  // every set on the same sample shares, so the surface cannot average it out): the samples' own
  // when a set has 3 or more, else the reference's sd (one specimen's scatter stands for one sample's).
  double sample_variance = 0;
  int samples = 1;
  Eigen::VectorXd coefficients;
  Eigen::MatrixXd covariance;  // of the coefficients
  double residual_variance = 0;
  double value(const Eigen::VectorXd& x) const { return coefficients.dot(x); }
  double variance(const Eigen::VectorXd& x) const { return x.dot(covariance * x); }
};

// Ordinary least squares of y on the features of each row of x (minimum norm where the features
// are of lower rank, as a two-valued parameter's square is); needs more rows than that rank.
Quadratic fit_quadratic(const std::vector<Eigen::VectorXd>& features, const std::vector<double>& y);

// A scalar row of a validate reference file on the surface: its samples' mean as a quadratic, and
// the values that agree with the paper's statement (validation::paper_region: the reading widened by
// its tolerance, or a half-line for a trend).
struct RowSurface {
  Quadratic q;
  double low = 0, high = 0;
};

struct ResponseSurface {
  Eigen::VectorXd centre, scale;  // the region: centre and sd of the proposal it was fitted in
  double radius = 3;              // in units of the proposal's Mahalanobis distance
  Eigen::MatrixXd region_inverse; // the proposal's inverse covariance
  std::vector<std::vector<Quadratic>> curves;  // per curve, per point
  std::vector<RowSurface> rows;                // per scalar row
  int sets = 0;                   // the sets it was fitted to
  double noise_to_reference = 0;  // mean over points of the residual sd over the reference's sd of its mean

  Eigen::VectorXd features(const Eigen::VectorXd& u) const;
  bool inside(const Eigen::VectorXd& u) const;
  // ln p(references | u) on the surface. A curve point: Gaussian, variance tolerance^2 + sd^2 /
  // specimens + sample_variance / samples (the model's mean is over a few samples, not the
  // population) + the surface's prediction variance at u. A scalar row: the paper's statement is
  // about its one specimen, so ln P(one sample's value lies in the row's region), that value normal
  // about the surface's mean with variance sample_variance + the prediction variance; an interval
  // row and a trend are then read alike.
  double log_likelihood(const References& refs, const Eigen::VectorXd& u) const;
  // ... at a larger size: each point's mean the surface's plus every discrepancy's (each from the
  // size before to the next), its variance the surface's and every discrepancy's prediction
  // variance, and the samples' own term the largest size's (the last discrepancy's).
  double log_likelihood(const References& refs, const Eigen::VectorXd& u, const std::vector<Discrepancy>& larger) const;
  // Per scalar row: the probability that one sample's value at u lies in the row's region (at the
  // larger size the discrepancies lead to), the rows' terms of log_likelihood.
  std::vector<double> row_probabilities(const Eigen::VectorXd& u, const std::vector<Discrepancy>& larger) const;
};

// The number of quadratic features in d dimensions: 1 + d + d (d + 1) / 2.
int quadratic_terms(int d);

// The surface of every curve point and scalar row over the sets inside `region` (Mahalanobis
// distance <= 3 of its Gaussian); when fewer than 2 x the features are inside, the region widens to
// take the nearest that many. A row's sample_variance: the mean over those sets of its samples'
// variance (2 or more samples a set), else its resolution^2, else its tolerance^2. None without
// references or with too few scored sets.
std::optional<ResponseSurface> fit_surface(const References& refs, const std::vector<ParameterSet>& sets,
                                           const Proposal& region);

// The posterior on the surface: `n` points from the region's Gaussian, then `n` from a Gaussian
// fitted to their weights, kept inside the cube and the region, weighed by likelihood over the
// Gaussian's density (the prior is uniform). A fixed pseudo-random seed: deterministic.
void sample_surface(const ResponseSurface& s, const References& refs, int n, std::vector<Eigen::VectorXd>& u,
                    std::vector<double>& w);
// ... at the larger size the discrepancies lead to.
void sample_surface(const ResponseSurface& s, const std::vector<Discrepancy>& larger, const References& refs, int n,
                    std::vector<Eigen::VectorXd>& u, std::vector<double>& w);

}  // namespace calibration
