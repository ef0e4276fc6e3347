#pragma once
// Rolling resistance: an elastic-plastic rolling spring (the "SDS" model of Luding 2008, as in
// LAMMPS's pair granular). The rolling displacement u_r (the history) grows by
// v_r dt with v_r = R* (omega_i - omega_j) x n, turned into the tangent plane as the tangential
// spring; the rolling "force" f_r = -k_r u_r is capped at |f_r| <= mu_r f_n, and the contact
// exerts the moment M = R* n x f_r on particle i and -M on particle j, so |M| <= mu_r R* f_n.
// Its power is f_r . v_r: the spring stores 1/2 k_r |u_r|^2 and the cap dissipates as friction's does.
#include "contact/capped_spring.hpp"

namespace dem {

struct NoRolling {
  static constexpr bool has_rolling = false;
};

struct RollingSpring {
  static constexpr bool has_rolling = true;
  double kr = 0;  // rolling stiffness [N/m]
  double mu_r = 0;  // rolling friction coefficient [-]

  // Scene keys (contact/parameter.hpp): on when rolling_friction > 0.
  static constexpr Parameter rolling_friction_key{
      "rolling_friction", "", 0, 10, false, false, 0.0,
      "rolling friction coefficient mu_r: rolling moment capped at mu_r R* f_n; 0 = no rolling resistance"};
  static constexpr Parameter rolling_stiffness_key{"rolling_stiffness", "N/m", 0, 1e12, true, false, no_default,
                                                   "stiffness k_r of the rolling spring (moment R* k_r u_r); needed when rolling_friction > 0"};
  static constexpr const char* switched_by = rolling_friction_key.name;
  static constexpr std::array parameters{rolling_friction_key, rolling_stiffness_key};
  static RollingSpring from(const ParameterValues& v) { return {v.at(rolling_stiffness_key.name), v.at(rolling_friction_key.name)}; }
  void write(ParameterValues& v) const { v[rolling_friction_key.name] = mu_r, v[rolling_stiffness_key.name] = kr; }

  template <class O>
  [[gnu::always_inline]] inline void update(HistoryStep<O>& s, typename O::Real fn, typename O::Bool touch) const {
    capped_linear_spring<O>(kr, mu_r, s, fn, touch);
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(const typename O::Vec& fr) const {
    return (O::splat(0.5) * O::dot(fr, fr)) / O::splat(kr);
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real opening_loss(typename O::Real history2) const {
    return O::splat(0.5 * kr) * history2;
  }
};

}  // namespace dem
