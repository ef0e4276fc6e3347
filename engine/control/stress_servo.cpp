#include "control/stress_servo.hpp"

#include <algorithm>

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

}  // namespace dem
