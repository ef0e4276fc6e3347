#pragma once
// The error budget of the convergence study: how far the paper's settings (time step, stress rate,
// sample size) are from the converged answer, factor by factor, beside the scatter between
// samples. Pure numerics over per-sample values (the runs of one density and one quantity, keyed
// by seed); compare-runs convergence reads them from the study's results or its committed
// summary (convergence_summary.hpp) and prints what these return.
#include <map>
#include <string>
#include <vector>

namespace validation {

// One quantity of one setting on each sample: seed -> value.
using PerSeed = std::map<int, double>;

// An estimate and the half-width of its 95 % interval (NaN: no interval, too few samples).
struct Estimate {
  double value = 0, half_width = 0;
};

// The paper's setting's error in one factor: value at the paper's setting minus the converged
// value, how it was found (a phrase for the table) and whether the extrapolation's premise held.
struct FactorError {
  Estimate error;
  std::string how;
  bool extrapolated = false;  // false: the finest setting stands in for the converged value
};

// Time step, paired by sample. h0 the paper's step, h0/2 and h0/4 the finer ones, `order` the
// scheme's. Per sample s: d1 = Q(h0) - Q(h0/2), d2 = Q(h0/2) - Q(h0/4). When the mean
// differences shrink one way at least at first order (same sign, observed order log2(d1/d2) >= 1),
// Richardson's extrapolation Q* = Q(h0/4) - d2 / (2^order - 1) per sample, and the error
// Q(h0) - Q*; else the finest step stands in, error Q(h0) - Q(h0/4), and `how` says why.
// Samples missing from any of the three are left out; fewer than 2 left: NaN half-width.
FactorError time_step_error(const PerSeed& paper, const PerSeed& half, const PerSeed& quarter, int order = 2);

// Loading rate, paired by sample (every rate shares the sample's preparation): per sample, the
// least-squares line of Q against the rate over the rates up to the paper's (the quasi-static side)
// is taken to rate -> 0 (the inertial number I is proportional to the rate); the error is
// Q(paper) - Q(0). The interval is the samples' (t with n - 1 dof) widened to also cover the same
// extrapolation in sqrt(rate) (the form the critical-state section uses), so that it holds for
// either. Needs at least 2 rates up to the paper's.
FactorError rate_error(const std::map<double, PerSeed>& by_rate, double paper_rate);

// Sample size, samples not paired (another size is another sample): the means at N0 (the
// paper's) and N1 > N0 taken to 1/N -> 0 along a straight line in 1/N: error = (m0 - m1) /
// (1 - N0/N1). With two sizes the 1/N form is assumed, not tested. Interval: Welch's standard
// error of m0 - m1 scaled alike, t with min(n0, n1) - 1 dof.
FactorError size_error(const PerSeed& paper, long n_paper, const PerSeed& larger, long n_larger);

// Mean, and the 95 % half-width of the mean (t with n - 1 dof), of values; NaN half-width for n < 2.
Estimate mean_of(const std::vector<double>& values);
// Sample standard deviation (n - 1); NaN for n < 2.
double sd_of(const std::vector<double>& values);

// The budget of one quantity at one density.
struct Budget {
  std::string quantity;
  Estimate paper;                // mean over the samples at the paper's settings
  FactorError time_step, rate, size;
  double sd_one = 0;             // scatter of one sample at the paper's settings
  double sd_mean = 0;            // of the mean of `ensemble` samples (the paper study's)
  Estimate converged;            // paper - (time step + rate + size errors), half-widths in quadrature
};

// The combination: the errors are taken as additive (each measured with the others at the paper's
// settings, first order), their intervals independent.
Estimate converged_value(const Estimate& paper, const FactorError& dt, const FactorError& rate, const FactorError& size);

// |x - converged| / |converged|, and its half-width from both intervals in quadrature.
Estimate relative_error_to(const Estimate& x, const Estimate& converged);

}  // namespace validation
