#pragma once
// Control of the periodic cell, per component of its velocity gradient G (cell/periodic_cell.hpp):
// the three axes xx, yy, zz and the three shears xy, xz, yz. Each component is strain-rate
// controlled, stress controlled, or follows a constraint of the whole cell (constant volume, or
// constant mean stress). A stress-controlled component is driven by a servo
//
//   rate_k = gain * (target_k - sigma_kk) / (K_k dt)  +  dtarget_k/dt / K_k,   |rate_k| <= max_rate,
//
// with K_k = (1/V) sum_c kn (n_k l_k)^2 the affine stiffness of the normal springs on axis k
// (stress increment per unit compressive strain if all particles followed the cell). The first term
// removes a fraction `gain` of the stress error per step; the second (feed-forward) term follows a
// moving target without lag. Because K_k is the affine (upper-bound) stiffness, the servo
// under-corrects rather than overshoots. With no contacts (K = 0) the axis moves at the cap.
// A shear component ab uses K_ab = sqrt(K_aa K_bb) / 3, the affine shear stiffness of an isotropic
// fabric (sum kn (n_a l_b)^2 / V, with <n_a^2 n_b^2> = <n_a^4> / 3 over the sphere): only its
// order of magnitude matters, the servo removes a fraction `gain` of the error per step.
// Compression positive throughout.
#include <array>
#include <string>

#include "cell/periodic_cell.hpp"

#include "core/types.hpp"

namespace dem {

struct AxisTarget {
  enum class Mode { StrainRate, Stress, Follow };  // Follow: set by the cell's constraint
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

using CellTargets = std::array<AxisTarget, 3>;  // the axes only; the cell does not shear

Vec3 servo_strain_rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                        const ServoSettings& settings, double dt_s);

// The six components in the order of CellControl::component, and their row and column in sigma.
inline constexpr std::array<const char*, 6> component_names{"xx", "yy", "zz", "xy", "xz", "yz"};
inline constexpr int component_row[6] = {0, 1, 2, 0, 0, 1}, component_column[6] = {0, 1, 2, 1, 2, 2};

// A constraint on the whole cell, which sets the components marked Follow:
//  - ConstantVolume (undrained): tr G = 0; the following axes share the opposite of the other
//    axes' rates equally. Only axes can follow, at least one and not all three.
//  - ConstantMeanStress: exactly one axis is strain-rate controlled (the leader) and the two
//    others follow as stress targets computed each step from the leader's measured stress s_l:
//    the first follower (in xx, yy, zz order) s_f = (3 p - s_l (1 + b)) / (2 - b), the second
//    s_f + b (s_l - s_f). Their mean with s_l is p; with the leader as the major stress,
//    b = (s_2 - s_3) / (s_1 - s_3) is the intermediate principal stress ratio (b = 0 triaxial
//    compression, b = 1 triaxial extension at constant p).
struct CellConstraint {
  enum class Kind { None, ConstantVolume, ConstantMeanStress };
  Kind kind = Kind::None;
  double mean_stress_Pa = 0;  // ConstantMeanStress: p
  double b = 0;               // ConstantMeanStress, in [0, 1]
};

struct CellControl {
  std::array<AxisTarget, 6> component;  // xx yy zz xy xz yz; the shears default to zero strain rate
  CellConstraint constraint;
  static CellControl of_axes(const CellTargets& axes) {
    CellControl c;
    for (std::size_t k = 0; k < 3; ++k) c.component[k] = axes[k];
    return c;
  }
};

// What is wrong with a control, naming its components ("" if nothing): a component that follows
// without a constraint, a constraint that leaves a component free or over-determines one.
std::string control_error(const CellControl& control);

// The velocity gradient of the next step (control_error(control) must be "").
CellRates servo_rates(const CellControl& control, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                      const ServoSettings& settings, double dt_s);

// The servo above with a learnt stiffness. A packing is softer than affine (particles rearrange,
// contacts slide): with real stiffness kappa K the servo above settles, on a ramp at rate r, to a
// lag e = r dt (1 - kappa) / (gain kappa), 18 % of p for kappa = 0.1 at the paper's 2 MPa/s. So
// every `adapt_window_steps` steps each stress-controlled axis compares the stress change it
// measured with the change K dt sum(rate) the affine stiffness predicted, and uses
// kappa K (kappa = their ratio, smoothed, in [min_stiffness_ratio, 1], at most halved or doubled
// per window) in both terms. With kappa learnt the ramp lag vanishes.
// The shears learn a ratio of their own (kappa_shear, the same rule over the stress-controlled
// shear components): their stiffness sqrt(K_aa K_bb)/3 is an isotropic estimate that is off by a
// different factor than the axes' (cyclic simple shear of the loose sample with all axes at fixed
// strain, where the axes learn nothing, reached 1.8 kPa of a 10 kPa amplitude in a quarter cycle
// with kappa_shear = 1). Until a shear window has taught it something, the shears use the axes'
// kappa. A shear target is often 0, so a window counts as informative when its predicted shear
// stress change is 0.5 % of the mean stress.
class AdaptiveServo {
 public:
  explicit AdaptiveServo(const ServoSettings& settings) : settings_(settings) {}
  Vec3 rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s);
  // Every component; kappa is learnt from the stress-controlled axes (constraint followers included).
  CellRates rates(const CellControl& control, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s);
  const Vec3& stiffness_ratio() const { return kappa_; }
  double shear_ratio() const { return kappa_shear_ > 0 ? kappa_shear_ : kappa_[0]; }
  // What the servo has learnt so far (saved in checkpoints).
  struct State {
    Vec3 kappa = Vec3::Ones(), predicted = Vec3::Zero(), window_start = Vec3::Zero();
    int steps = -1;
    double kappa_shear = 0;  // 0: not learnt yet
    Vec3 predicted_shear = Vec3::Zero(), window_start_shear = Vec3::Zero();  // xy, xz, yz
  };
  State state() const { return {kappa_, predicted_, window_start_, steps_, kappa_shear_, predicted_shear_, window_start_shear_}; }
  void restore(const State& s) {
    kappa_ = s.kappa, predicted_ = s.predicted, window_start_ = s.window_start, steps_ = s.steps;
    kappa_shear_ = s.kappa_shear, predicted_shear_ = s.predicted_shear, window_start_shear_ = s.window_start_shear;
  }

 private:
  ServoSettings settings_;
  Vec3 kappa_ = Vec3::Ones();
  Vec3 predicted_ = Vec3::Zero();     // affine prediction of the stress change in this window [Pa]
  Vec3 window_start_ = Vec3::Zero();  // stress at the window start [Pa]
  int steps_ = -1;                    // steps in the window; -1 before the first call
  double kappa_shear_ = 0;  // 0 until a shear window was informative (shear_ratio() is then the axes')
  Vec3 predicted_shear_ = Vec3::Zero(), window_start_shear_ = Vec3::Zero();
};

}  // namespace dem
