#pragma once
// Per-axis control of the periodic cell: each axis is either strain-rate controlled or stress
// controlled. A stress-controlled axis is driven by a servo
//
//   rate_k = gain * (target_k - sigma_kk) / (K_k dt)  +  dtarget_k/dt / K_k,   |rate_k| <= max_rate,
//
// with K_k = (1/V) sum_c kn (n_k l_k)^2 the affine stiffness of the normal springs on axis k
// (stress increment per unit compressive strain if all particles followed the cell). The first term
// removes a fraction `gain` of the stress error per step; the second (feed-forward) term follows a
// moving target without lag. Because K_k is the affine (upper-bound) stiffness, the servo
// under-corrects rather than overshoots. With no contacts (K = 0) the axis moves at the cap.
// Compression positive throughout.
#include <array>

#include "core/types.hpp"

namespace dem {

struct AxisTarget {
  enum class Mode { StrainRate, Stress };
  Mode mode = Mode::StrainRate;
  double strain_rate_per_s = 0;     // used when mode == StrainRate
  double stress_Pa = 0;             // used when mode == Stress
  double stress_rate_Pa_per_s = 0;  // d(target)/dt, for the feed-forward term
};

struct ServoSettings {
  double gain = 1e-3;                // fraction of the stress error removed per step [-]
  double max_strain_rate_per_s = 1;  // cap on |strain rate| of a stress-controlled axis [1/s]
  int adapt_window_steps = 250;      // AdaptiveServo: steps between stiffness-ratio updates (0: off)
  double min_stiffness_ratio = 0.05; // AdaptiveServo: lower bound of the learnt ratio kappa
};

using CellTargets = std::array<AxisTarget, 3>;

Vec3 servo_strain_rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                        const ServoSettings& settings, double dt_s);

// The servo above with a learnt stiffness. A packing is softer than affine (particles rearrange,
// contacts slide): with real stiffness kappa K the servo above settles, on a ramp at rate r, to a
// lag e = r dt (1 - kappa) / (gain kappa), 18 % of p for kappa = 0.1 at the paper's 2 MPa/s. So
// every `adapt_window_steps` steps each stress-controlled axis compares the stress change it
// measured with the change K dt sum(rate) the affine stiffness predicted, and uses
// kappa K (kappa = their ratio, smoothed, in [min_stiffness_ratio, 1], at most halved or doubled
// per window) in both terms. With kappa learnt the ramp lag vanishes.
class AdaptiveServo {
 public:
  explicit AdaptiveServo(const ServoSettings& settings) : settings_(settings) {}
  Vec3 rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s);
  const Vec3& stiffness_ratio() const { return kappa_; }
  // What the servo has learnt so far (saved in checkpoints).
  struct State {
    Vec3 kappa = Vec3::Ones(), predicted = Vec3::Zero(), window_start = Vec3::Zero();
    int steps = -1;
  };
  State state() const { return {kappa_, predicted_, window_start_, steps_}; }
  void restore(const State& s) { kappa_ = s.kappa, predicted_ = s.predicted, window_start_ = s.window_start, steps_ = s.steps; }

 private:
  ServoSettings settings_;
  Vec3 kappa_ = Vec3::Ones();
  Vec3 predicted_ = Vec3::Zero();     // affine prediction of the stress change in this window [Pa]
  Vec3 window_start_ = Vec3::Zero();  // stress at the window start [Pa]
  int steps_ = -1;                    // steps in the window; -1 before the first call
};

}  // namespace dem
