#include "control/stress_servo.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dem {

namespace {
// The rate of one strain-rate or stress-controlled component (see the header).
double component_rate(const AxisTarget& t, double stress_Pa, double stiffness_Pa, const ServoSettings& settings,
                      double dt_s) {
  if (t.mode == AxisTarget::Mode::StrainRate) return t.strain_rate_per_s;
  const double cap = settings.max_strain_rate_per_s;
  const double error = t.stress_Pa - stress_Pa;
  const double K = stiffness_Pa;
  const double r = K > 0 ? (settings.gain * error / dt_s + t.stress_rate_Pa_per_s) / K : (error > 0 ? cap : error < 0 ? -cap : 0.0);
  return std::clamp(r, -cap, cap);
}

// The affine shear stiffness of shear component k (3..5) from the axes' (see the header).
double shear_stiffness(std::size_t k, const Vec3& axes_Pa) {
  return std::sqrt(axes_Pa[component_row[k]] * axes_Pa[component_column[k]]) / 3;
}

// The stiffness the servo uses: the affine one of the axes times their ratios, of the shears
// times theirs.
struct ServoStiffness {
  Vec3 axes_Pa;
  Vec3 kappa = Vec3::Ones();
  double kappa_shear = 1;
  double of(std::size_t k) const {
    return k < 3 ? axes_Pa[static_cast<int>(k)] * kappa[static_cast<int>(k)] : kappa_shear * shear_stiffness(k, axes_Pa);
  }
};

// The control with a constant mean stress resolved: its followers become stress targets, which
// move with the leader's measured stress, without a feed-forward term (an affine estimate of the
// leader's stress rate overshot: p 4.5 % low on the 216-sphere test packing; one measured over
// the servo's window was too noisy: b 0.15 for 0.5). They lag the leader by the servo's lag.
std::array<AxisTarget, 6> resolved(const CellControl& c, const Mat3& stress_Pa) {
  std::array<AxisTarget, 6> t = c.component;
  if (c.constraint.kind != CellConstraint::Kind::ConstantMeanStress) return t;
  int leader = 0, followers[2], n = 0;
  for (int k = 0; k < 3; ++k) (t[static_cast<std::size_t>(k)].mode == AxisTarget::Mode::Follow ? followers[n++] : leader) = k;
  const double p = c.constraint.mean_stress_Pa, b = c.constraint.b, s_l = stress_Pa(leader, leader);
  const double s_first = (3 * p - s_l * (1 + b)) / (2 - b);
  const double targets[2] = {s_first, s_first + b * (s_l - s_first)};
  for (int f = 0; f < 2; ++f) t[static_cast<std::size_t>(followers[f])] = {AxisTarget::Mode::Stress, 0, targets[f], 0};
  return t;
}

CellRates rates_of(const CellControl& control, const std::array<AxisTarget, 6>& t, const Mat3& stress_Pa,
                   const ServoStiffness& stiffness, const ServoSettings& settings, double dt_s) {
  double g[6] = {0, 0, 0, 0, 0, 0};
  for (std::size_t k = 0; k < 6; ++k)
    if (t[k].mode != AxisTarget::Mode::Follow)
      g[k] = component_rate(t[k], stress_Pa(component_row[k], component_column[k]), stiffness.of(k), settings, dt_s);
  if (control.constraint.kind == CellConstraint::Kind::ConstantVolume) {
    double others = 0;
    int followers = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (t[k].mode == AxisTarget::Mode::Follow)
        ++followers;
      else
        others += g[k];
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (t[k].mode == AxisTarget::Mode::Follow) g[k] = -others / followers;
  }
  return {Vec3(g[0], g[1], g[2]), Vec3(g[3], g[4], g[5])};
}
}  // namespace

Vec3 servo_strain_rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                        const ServoSettings& settings, double dt_s) {
  Vec3 rate;
  for (int k = 0; k < 3; ++k)
    rate[k] = component_rate(targets[static_cast<std::size_t>(k)], stress_Pa(k, k), stiffness_Pa[k], settings, dt_s);
  return rate;
}

std::string control_error(const CellControl& c) {
  std::ostringstream msg;
  int axis_followers = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    if (c.component[k].mode != AxisTarget::Mode::Follow) continue;
    if (k >= 3) return std::string(component_names[k]) + " cannot follow a constraint: only the axes xx, yy, zz can";
    ++axis_followers;
  }
  switch (c.constraint.kind) {
    case CellConstraint::Kind::None:
      if (axis_followers > 0) return "a component is set to follow, but no constraint (constant_volume or constant_mean_stress) is given";
      return "";
    case CellConstraint::Kind::ConstantVolume:
      if (axis_followers == 0) return "constant_volume needs at least one axis that follows it; none does, so the volume is not held";
      if (axis_followers == 3) return "constant_volume with all three axes following leaves the split between them free: control one axis";
      return "";
    case CellConstraint::Kind::ConstantMeanStress:
      if (axis_followers != 2) {
        msg << "constant_mean_stress needs exactly two axes that follow it (one axis leads at a strain rate); " << axis_followers
            << " follow";
        return msg.str();
      }
      for (std::size_t k = 0; k < 3; ++k)
        if (c.component[k].mode == AxisTarget::Mode::Stress)
          return std::string("constant_mean_stress: the leading axis ") + component_names[k] +
                 " must be strain-rate controlled (with its stress set too, every axis stress would be fixed)";
      if (!(c.constraint.b >= 0 && c.constraint.b <= 1)) return "constant_mean_stress: b must be in [0, 1]";
      if (!(c.constraint.mean_stress_Pa > 0)) return "constant_mean_stress: the mean stress must be positive";
      return "";
  }
  return "";
}

CellRates servo_rates(const CellControl& control, const Mat3& stress_Pa, const Vec3& stiffness_Pa,
                      const ServoSettings& settings, double dt_s) {
  return rates_of(control, resolved(control, stress_Pa), stress_Pa, {stiffness_Pa}, settings, dt_s);
}

Vec3 AdaptiveServo::rates(const CellTargets& targets, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s) {
  return rates(CellControl::of_axes(targets), stress_Pa, stiffness_Pa, dt_s).axial;
}

CellRates AdaptiveServo::rates(const CellControl& control, const Mat3& stress_Pa, const Vec3& stiffness_Pa, double dt_s) {
  const Vec3 sigma = stress_Pa.diagonal();
  const Vec3 tau(stress_Pa(0, 1), stress_Pa(0, 2), stress_Pa(1, 2));
  const std::array<AxisTarget, 6> targets = resolved(control, stress_Pa);
  if (steps_ < 0 || (settings_.adapt_window_steps > 0 && steps_ >= settings_.adapt_window_steps)) {
    // One ratio for the packing, by least squares over the stress-controlled axes: per-axis
    // ratios are confounded by the coupling between axes (compressing one axis loads the others).
    double num = 0, den = 0, scale = 0, num_shear = 0, den_shear = 0;
    for (int k = 0; k < 3 && steps_ >= 0; ++k) {
      if (targets[static_cast<std::size_t>(k)].mode == AxisTarget::Mode::Stress) {
        num += (sigma[k] - window_start_[k]) * predicted_[k];
        den += predicted_[k] * predicted_[k];
        scale = std::max(scale, std::abs(targets[static_cast<std::size_t>(k)].stress_Pa));
      }
      if (targets[static_cast<std::size_t>(k) + 3].mode == AxisTarget::Mode::Stress) {
        num_shear += (tau[k] - window_start_shear_[k]) * predicted_shear_[k];
        den_shear += predicted_shear_[k] * predicted_shear_[k];
      }
    }
    // Learn only from windows that moved the stress noticeably (0.5 % of the target): in small,
    // noisy packings a smaller change is mostly fluctuation.
    const auto learn = [&](double ratio, double n, double d) {
      const double smoothed = 0.5 * ratio + 0.5 * n / d;
      return std::clamp(smoothed, std::max(settings_.min_stiffness_ratio, 0.5 * ratio), std::min(1.0, 2 * ratio));
    };
    if (den > 0 && std::sqrt(den) > 5e-3 * scale) kappa_.setConstant(learn(kappa_[0], num, den));
    if (den_shear > 0 && std::sqrt(den_shear) > 5e-3 * std::abs(sigma.sum() / 3))
      kappa_shear_ = learn(shear_ratio(), num_shear, den_shear);
    window_start_ = sigma;
    window_start_shear_ = tau;
    predicted_.setZero();
    predicted_shear_.setZero();
    steps_ = 0;
  }
  const CellRates rate = rates_of(control, targets, stress_Pa, {stiffness_Pa, kappa_, shear_ratio()}, settings_, dt_s);
  predicted_ += stiffness_Pa.cwiseProduct(rate.axial) * dt_s;
  for (std::size_t k = 3; k < 6; ++k)  // only the shears it learns from (a scene without them pays nothing)
    if (targets[k].mode == AxisTarget::Mode::Stress)
      predicted_shear_[static_cast<int>(k) - 3] += shear_stiffness(k, stiffness_Pa) * rate.shear[static_cast<int>(k) - 3] * dt_s;
  ++steps_;
  return rate;
}

}  // namespace dem
