#pragma once
// The error budget of the convergence study: how far the paper's settings (time step, stress rate,
// sample size) are from the converged answer, factor by factor, beside the scatter between
// samples. Pure numerics over per-sample values (the runs of one density and one quantity, keyed
// by seed); compare-runs convergence reads them from the study's results or its committed
// summary (convergence_summary.hpp) and prints what these return.
#include <limits>
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
  // How much the interval rests on: the samples it is made of, the standard deviation of one
  // sample's error (paired factors; for size, of one sample at the paper's size), and for a paired
  // factor the correlation over the samples of the two settings' values (near 1: the pairs cancel
  // the samples' scatter; near 0 or below: pairing did not help). NaN where it does not apply.
  int samples = 0;
  bool across_sizes = false;  // the size factor: every sample its own packing, nothing paired
  double sd = std::numeric_limits<double>::quiet_NaN();
  double correlation = std::numeric_limits<double>::quiet_NaN();
  // Size: chi^2/dof of the sizes' means about the line (three sizes or more; NaN: not tested).
  double lack_of_fit = std::numeric_limits<double>::quiet_NaN();
};

// Pearson's correlation of the values two settings gave on the same samples (seeds in both);
// NaN with fewer than 3 such samples or a setting whose values are all equal.
double paired_correlation(const PerSeed& a, const PerSeed& b);

// The mean of a - b over the samples in both (paired), its 95 % interval (t, n - 1 dof), the sd
// of the differences and the pairs' correlation.
FactorError paired_difference(const PerSeed& a, const PerSeed& b);

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

// Sample size, samples not paired (another size is another packing): the sizes' means on the
// line Q = Q* + b/N by weighted least squares, and the error at the paper's size N0 is b/N0.
// The scatter of one sample is taken to shrink as 1/sqrt(N) (an average over N spheres): the
// variance of one sample at size N is s^2 N0/N, s^2 pooled over every size's samples
// (sum over sizes of (N/N0) sum (x - mean)^2, over sum (n - 1) dof), so that the many cheap small
// samples carry the fit. The interval is t (the pooled dof) times the fit's standard error of
// b/N0, widened by sqrt(chi^2/dof) of the means about the line when that exceeds 1 (three sizes
// or more: the 1/N form tested; two: assumed, and `how` says which). Needs the paper's size and
// another, and at least one dof.
FactorError size_error(const std::map<long, PerSeed>& by_size, long n_paper);

// The samples each setting would need for the half-width of this factor's error to be at most
// `tolerance` (in the error's units), its scatter per sample as measured: the smallest n with
// t(0.975, n - 1) sd / sqrt(n) <= tolerance for a paired factor; for size, today's samples scaled
// by (half-width / tolerance)^2. 0 when today's are enough; -1 when it cannot be said.
long samples_needed(const FactorError& f, double tolerance);

// Mean, and the 95 % half-width of the mean (t with n - 1 dof), of values; NaN half-width for n < 2.
Estimate mean_of(const std::vector<double>& values);
// Sample standard deviation (n - 1); NaN for n < 2.
double sd_of(const std::vector<double>& values);

// The budget of one quantity at one density.
struct Budget {
  std::string quantity;
  Estimate paper;                // mean over the samples at the paper's settings
  // The time step of the test (on the same prepared samples) and of the preparation (for the
  // test's quantities: the same seeds prepared at the paper's step and at the finest, both
  // sheared at the finest), the stress rate and the size.
  FactorError time_step, preparation_step, rate, size;
  double sd_one = 0;             // scatter of one sample at the paper's settings
  double sd_mean = 0;            // of the mean of `ensemble` samples (the paper study's)
  Estimate converged;            // paper - (time step + rate + size errors), half-widths in quadrature
};

// The combination: the errors are taken as additive (each measured with the others at the paper's
// settings, first order), their intervals independent.
Estimate converged_value(const Estimate& paper, const std::vector<const FactorError*>& factors);

// |x - converged| / |converged|, and its half-width from both intervals in quadrature.
Estimate relative_error_to(const Estimate& x, const Estimate& converged);

}  // namespace validation
