#pragma once
// Calibration across sizes. A set's response at the paper's size (8,000 spheres) costs about eight
// times its response at 1,000, and at the small size the samples scatter more than a row's
// tolerance, so the response at the large size is modelled as the small size's response surface plus a
// discrepancy fitted in the parameters, in the manner of Kennedy and O'Hagan's autoregressive
// multi-fidelity model (Biometrika 2000) with a unit scale:
//
//     y_large(u) = y_small(u) + delta(u),
//
// delta fitted by least squares to the sets run at both sizes, each giving the difference of its two
// sample means. delta is a constant, or a constant and a slope in each parameter once the pairs
// leave at least two degrees of freedom for the residuals. Its prediction variance enters the
// likelihood beside the small surface's, and the samples' own scatter is then the large size's:
// every set shares the small size's packings, whose common deviation the difference cancels.
//
// Which sets run at the large size: the posterior-weighted reduction of delta's prediction variance
// (a sequential I-optimal design), among the sets the smaller size scored near the posterior.
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "references.hpp"
#include "sets.hpp"
#include "surrogate.hpp"

namespace calibration {

struct Discrepancy {
  Eigen::VectorXd centre, scale;  // of the pairs' unit values: the linear term's standardisation
  bool linear = false;            // else a constant
  std::vector<std::vector<Quadratic>> curves;  // per curve, per point: the difference (large - small)
  std::vector<Quadratic> rows;                 // per scalar row
  int pairs = 0;

  Eigen::VectorXd features(const Eigen::VectorXd& u) const;
};

// The least number of pairs a discrepancy is fitted to (a constant with two degrees of freedom for
// its residuals), and the number from which it has a slope in each of d parameters.
inline constexpr int min_discrepancy_pairs = 3;
int linear_discrepancy_pairs(int d);

// delta fitted to the sets scored at both sizes (matched by name; unscored ones left out); none
// with fewer than min_discrepancy_pairs pairs. Each point's sample_variance and samples: the large
// size's (its samples' own variance with 3 or more, else the reference's sd, as for a surface).
std::optional<Discrepancy> fit_discrepancy(const References& refs, const std::vector<ParameterSet>& small,
                                           const std::vector<ParameterSet>& large);

// A discrepancy fitted on `part` (a part of a size: some densities' curves and rows) over every
// curve and row of `all`: those outside the part take none (a Quadratic of no samples, which the
// likelihood and the report skip).
Discrepancy extended(const Discrepancy& delta, const References& part, const References& all);
inline bool covers(const Quadratic& q) { return q.samples > 0; }

// The indices of `n` candidates (unit values) to run at the larger size, chosen one at a time: each
// the one that most reduces the posterior-weighted prediction variance of a linear discrepancy given
// the sets already there (`chosen`). Candidates are restricted to those within Mahalanobis distance 2
// of the posterior's weighted mean and covariance while at least `n` are; else the nearest `n`.
std::vector<std::size_t> choose_for_larger_size(const std::vector<Eigen::VectorXd>& candidates,
                                                const std::vector<Eigen::VectorXd>& chosen,
                                                const std::vector<Eigen::VectorXd>& posterior_u,
                                                const std::vector<double>& posterior_w, int n);

// A set to confirm at the larger size: the candidate the posterior there expects most likely to
// agree with every row of `rows` (the scalar rows a part of a size covers): the largest product of
// the rows' probabilities (ResponseSurface::row_probabilities), among the candidates inside the
// surface's region when any is, else among all (the surface then extrapolates). None without candidates.
struct Confirmation {
  std::size_t index = 0;           // into the candidates
  double probability = 0;          // that one sample agrees with every row (their product)
  std::vector<double> row_probability;  // per row of `rows`
};
// How far the posterior at the larger size lets each row be reached: over `n` points drawn
// uniformly in the unit cube and kept inside the surface's region (where it was fitted), the
// largest probability that one sample agrees with each of `rows`, and with all of them at once.
// A row whose largest is small is one no set of that region is expected to make consistent. A
// maximum over random points, not a bound: a point between them may do better.
struct Reach {
  int points = 0;                  // inside the region
  std::vector<double> row_most;    // per row of `rows`
  double all_most = 0;
  Eigen::VectorXd all_best;        // the point of all_most (empty: no point inside the region)
};
Reach reach(const ResponseSurface& surface, const std::vector<Discrepancy>& larger, const std::vector<std::size_t>& rows, int n);

std::optional<Confirmation> choose_to_confirm(const ResponseSurface& surface, const std::vector<Discrepancy>& larger,
                                              const std::vector<Eigen::VectorXd>& candidates, const std::vector<std::size_t>& rows);

}  // namespace calibration
