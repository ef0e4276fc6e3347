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
};

using CellTargets = std::array<AxisTarget, 3>;

Vec3 servo_strain_rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                        const ServoSettings& settings, double dt_s);

}  // namespace dem
