#pragma once
// Linear spring contact law with optional Coulomb friction (Cundall & Strack 1979).
//
//   normal:     f_n = kn * overlap, along the unit normal n (from particle i to particle j);
//   tangential: an elastic tangential displacement u_s is accumulated incrementally,
//               u_s += v_t dt, after rotating the previous u_s into the current tangent plane
//               (magnitude kept); f_t = -ks u_s, capped at |f_t| <= mu f_n (the contact slides).
//
// Friction is a compile-time policy. NoFriction is the exemplar: a frictionless scene runs a
// kernel that has no tangential spring, no history and no torque.
#include <cmath>

#include "core/types.hpp"

namespace dem {

struct NoFriction {
  static constexpr bool has_tangential = false;
};

struct Coulomb {
  static constexpr bool has_tangential = true;
  double ks = 0;  // tangential stiffness [N/m]
  double mu = 0;  // friction coefficient [-]

  // Advances the elastic tangential displacement `spring` [m] of one contact by the tangential
  // relative velocity v_t [m/s] over dt, and returns the tangential force on particle j [N].
  // `sliding` is set when the Coulomb cap is active.
  //
  // `dissipated_J` receives the energy the cap took in this step (0 when sticking): the work the
  // particles did on the spring over the increment du, with the force taken as the mean of its
  // values before and after (the trapezoidal rule the leapfrog energy balance uses), minus the
  // change of the stored energy 1/2 ks |u|^2:  1/2 ks [(u_old + u_new).du - (|u_new|^2 - |u_old|^2)].
  // When a contact slides steadily at the cap this is mu f_n |du|, Coulomb's work on the slip.
  Vec3 tangential(Vec3& spring, const Vec3& n, const Vec3& v_t, double dt_s, double fn_N, bool& sliding,
                  double& dissipated_J) const {
    // Rotate the old displacement into the current tangent plane, keeping its magnitude.
    const double old_norm2 = spring.squaredNorm();
    if (old_norm2 > 0) {
      spring -= n.dot(spring) * n;
      const double new_norm2 = spring.squaredNorm();
      if (new_norm2 > 0) spring *= std::sqrt(old_norm2 / new_norm2);
    }
    const Vec3 du = v_t * dt_s;
    const Vec3 u_old = spring;
    spring += du;
    const double limit = mu * fn_N;  // largest |f_t| [N]
    const double ft2 = ks * ks * spring.squaredNorm();
    sliding = ft2 >= limit * limit;
    dissipated_J = 0;
    if (sliding) {
      const double norm = std::sqrt(spring.squaredNorm());
      spring *= norm > 0 ? limit / (ks * norm) : 0.0;
      dissipated_J = 0.5 * ks * ((u_old + spring).dot(du) - (spring.squaredNorm() - u_old.squaredNorm()));
    }
    return -ks * spring;
  }
};

template <class Friction>
struct LinearSpring {
  double kn = 0;  // normal stiffness [N/m]
  Friction friction{};
};

}  // namespace dem
