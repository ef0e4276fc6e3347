#include "control/stress_servo.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

Vec3 servo_strain_rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                        const ServoSettings& settings, double dt_s) {
  Vec3 rate;
  const double cap = settings.max_strain_rate_per_s;
  for (int k = 0; k < 3; ++k) {
    const AxisTarget& t = targets[static_cast<std::size_t>(k)];
    if (t.mode == AxisTarget::Mode::StrainRate) {
      rate[k] = t.strain_rate_per_s;
      continue;
    }
    const double error = t.stress_Pa - stress_Pa(k, k);
    const double K = stiffness_Pa[k];
    const double r = K > 0 ? (settings.gain * error / dt_s + t.stress_rate_Pa_per_s) / K : (error > 0 ? cap : error < 0 ? -cap : 0.0);
    rate[k] = std::clamp(r, -cap, cap);
  }
  return rate;
}

Vec3 AdaptiveServo::rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s) {
  const Vec3 sigma = stress_Pa.diagonal();
  if (steps_ < 0 || (settings_.adapt_window_steps > 0 && steps_ >= settings_.adapt_window_steps)) {
    // One ratio for the packing, by least squares over the stress-controlled axes: per-axis
    // ratios are confounded by the coupling between axes (compressing one axis loads the others).
    double num = 0, den = 0, scale = 0;
    for (int k = 0; k < 3 && steps_ >= 0; ++k) {
      if (targets[static_cast<std::size_t>(k)].mode != AxisTarget::Mode::Stress) continue;
      num += (sigma[k] - window_start_[k]) * predicted_[k];
      den += predicted_[k] * predicted_[k];
      scale = std::max(scale, std::abs(targets[static_cast<std::size_t>(k)].stress_Pa));
    }
    // Learn only from windows that moved the stress noticeably (0.5 % of the target): in small,
    // noisy packings a smaller change is mostly fluctuation.
    if (den > 0 && std::sqrt(den) > 5e-3 * scale) {
      const double k0 = kappa_[0];
      const double smoothed = 0.5 * k0 + 0.5 * num / den;
      kappa_.setConstant(std::clamp(smoothed, std::max(settings_.min_stiffness_ratio, 0.5 * k0), std::min(1.0, 2 * k0)));
    }
    window_start_ = sigma;
    predicted_.setZero();
    steps_ = 0;
  }
  const Vec3 rate = servo_strain_rates(targets, stress_Pa, stiffness_Pa.cwiseProduct(kappa_), settings_, dt_s);
  predicted_ += stiffness_Pa.cwiseProduct(rate) * dt_s;
  ++steps_;
  return rate;
}

}  // namespace dem
