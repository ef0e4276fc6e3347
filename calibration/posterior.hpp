#pragma once
// The posterior over the parameters' unit cube [0, 1]^d, by adaptive multiple importance sampling
// (Cornuet et al., Scand. J. Stat. 2012): each iteration draws a batch from a proposal fitted to the
// weighted sets so far, and every set ever run is weighted again against the mixture of all the
// proposals used, so no run is thrown away. The prior is uniform on the cube (parameters.hpp).
//
// A proposal is a defensive mixture (Hesterberg, Technometrics 1995): a share of the prior itself
// beside a Gaussian with twice the weighted covariance of the sets (as in ABC population Monte
// Carlo, Beaumont et al., Biometrika 2009), truncated to the cube. The prior's share bounds every
// weight by likelihood / share, so a mode the Gaussian misses is still found, and a discrete
// parameter (whose likelihood is flat within each value's bin) is sampled like a continuous one.
// Draws are quasi-random: a Sobol sequence (Boost.Random) continued across iterations, mapped
// through the Gaussian's quantiles (Boost.Math). Everything is deterministic: the same results give
// the same draws, so a calibration started again replays itself and the pipeline reuses its runs.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "parameters.hpp"

namespace calibration {

struct Proposal {
  double prior_share = 1;  // 1: the prior alone (the first iteration)
  Eigen::VectorXd mean;
  Eigen::MatrixXd covariance;
  double inside = 1;  // the Gaussian's probability inside the cube
  // The density on the cube (the prior's is 1).
  double density(const Eigen::VectorXd& u) const;
};

// The proposal after the weighted sets (u, w): prior_share of the prior, the rest a Gaussian at the
// weighted mean with inflation x the weighted covariance, each variance at least floor_sd^2.
Proposal fit_proposal(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w, double prior_share,
                      double inflation = 2, double floor_sd = 0.005);

// The weights a proposal is fitted to: the posterior's, tempered (likelihood^(1/T), T >= 1, the
// smallest T found by bisection) until their effective sample size is at least `at_least`. Early
// on the posterior rests on one or two sets, whose covariance says nothing of its shape; the best
// few sets together do. Only the proposal sees the tempering: every set is weighed with the true
// likelihood (importance_weights), so the posterior does not depend on it.
std::vector<double> proposal_weights(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& log_likelihood,
                                     const std::vector<Proposal>& proposals, const std::vector<int>& drawn, double at_least);

// Quasi-random draws on the cube from a proposal, continuing one Sobol sequence.
class Sampler {
 public:
  explicit Sampler(int dimensions);
  std::vector<Eigen::VectorXd> draw(const Proposal& q, int n);

 private:
  Eigen::VectorXd next();
  int d_;
  struct Engine;
  std::shared_ptr<Engine> engine_;
};

// Normalised importance weights of every set: likelihood x prior / (the mixture of the proposals,
// each weighted by the number of sets drawn from it); log_likelihood may be -inf (a set that failed).
std::vector<double> importance_weights(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& log_likelihood,
                                       const std::vector<Proposal>& proposals, const std::vector<int>& drawn);

// Kish's effective sample size of normalised weights, (sum w)^2 / sum w^2.
double effective_sample_size(const std::vector<double>& w);

struct Marginal {
  double mean = 0, sd = 0;              // of the parameter's value
  double median = 0, lower_95 = 0, upper_95 = 0;  // weighted quantiles of the value
  double unit_mean = 0, unit_sd = 0;    // on the unit interval
  double narrowing = 1;                 // the prior's sd over the posterior's, on the unit interval
  bool identified = false;              // narrowing >= identified_narrowing
};
// A posterior narrower than the prior by less than this factor is called "not identified by the
// references": a uniform prior's sd is 0.289 of its range, so the posterior still spans about
// two thirds of it.
inline constexpr double identified_narrowing = 1.5;

Marginal marginal(const Parameter& p, std::size_t j, const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w);

// Weighted correlation matrix of the unit coordinates (of log values for a log_uniform prior).
Eigen::MatrixXd correlations(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w);

// The weighted quantile q of values x.
double weighted_quantile(std::vector<double> x, std::vector<double> w, double q);

}  // namespace calibration
