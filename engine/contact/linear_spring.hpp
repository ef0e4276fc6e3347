#pragma once
// The linear spring contact law (Cundall & Strack 1979):
//   normal:     f_n = kn * overlap, along the unit normal n (from particle i to particle j);
//   tangential: an elastic tangential displacement u_s (the history) is accumulated incrementally,
//               u_s += v_t dt, after turning the previous u_s into the current tangent plane
//               (magnitude kept); f_t = -ks u_s, capped at |f_t| <= mu f_n (the contact slides).
// Each part is written once for any lanes `O` (contact/lane_ops.inc); contact/contact_law.hpp
// says what a law provides.
#include <cmath>
#include <string>
#include <utility>

#include "contact/capped_spring.hpp"

namespace dem {

struct LinearNormal {
  double kn = 0;  // normal stiffness [N/m]

  // Scene keys (contact/parameter.hpp).
  static constexpr const char* law_name = "linear";
  static constexpr Parameter kn_key{"kn", "N/m", 0, 1e12, true, false, no_default, "normal contact stiffness"};
  static constexpr std::array parameters{kn_key};
  static LinearNormal from(const ParameterValues& v) { return {v.at(kn_key.name)}; }
  void write(ParameterValues& v) const { v[kn_key.name] = kn; }

  static constexpr bool needs_reduced_radius = false;
  static constexpr bool needs_normal_velocity = false;  // no dashpot (contact/contact_dashpot.hpp adds one)
  template <class O>
  [[gnu::always_inline]] inline typename O::Real force(typename O::Real overlap, typename O::Real /*reduced_radius*/) const {
    return O::splat(kn) * overlap;
  }
  // The normal force the Coulomb cap takes (a cohesive or damped law changes it): f_n itself.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real friction_normal_force(typename O::Real fn) const {
    return fn;
  }
  // d f_n / d overlap, for the servo [N/m]; a constant (a dashpot's coefficient is then one per pair).
  static constexpr bool constant_stiffness = true;
  template <class O>
  [[gnu::always_inline]] inline typename O::Real stiffness(typename O::Real /*overlap*/, typename O::Real /*reduced_radius*/) const {
    return O::splat(kn);
  }
  // Stored energy [J]: 1/2 kn overlap^2 = 1/2 f_n overlap.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(typename O::Real fn, typename O::Real overlap) const {
    return (O::splat(0.5) * fn) * overlap;
  }
  // The leapfrog's stability limit on one spring for the lightest particle, 2 sqrt(m_min / kn).
  double critical_time_step(double m_min_kg, double /*r_min_m*/, double /*density*/) const { return 2.0 * std::sqrt(m_min_kg / kn); }
  const char* critical_time_step_formula() const { return "2 sqrt(m_min/kn)"; }
  // The stiffness viscous damping scales with, c = 2 C sqrt(k m) [N/m].
  double damping_stiffness() const { return kn; }
};

// Coulomb friction on a linear tangential spring. The history is the elastic displacement u_s [m].
struct LinearCoulomb {
  static constexpr bool has_tangential = true;
  static constexpr const char* history_name = "tangential_spring";
  static constexpr const char* history_unit = "m";
  static constexpr bool needs_reduced_radius = false;
  double ks = 0;  // tangential stiffness [N/m]
  double mu = 0;  // friction coefficient [-]

  // Scene keys: on when friction > 0. ks is accepted (and unused) with friction 0.
  static constexpr const char* switched_by = friction_key.name;
  static constexpr Parameter ks_key{"ks", "N/m", 0, 1e12, false, false, no_default, "tangential contact stiffness", true};
  static constexpr std::array parameters{friction_key, ks_key};
  static LinearCoulomb from(const ParameterValues& v) { return {v.at(ks_key.name), v.at(friction_key.name)}; }
  void write(ParameterValues& v) const { v[ks_key.name] = ks, v[friction_key.name] = mu; }
  // What the keys' ranges cannot say: "" or the key and the complaint.
  static std::pair<const char*, std::string> problem(const ParameterValues& v) {
    if (!(v.at(ks_key.name) > 0)) return {ks_key.name, "must be > 0 when friction > 0, got " + std::to_string(v.at(ks_key.name))};
    return {"", ""};
  }

  // d f_t / d u_s [N/m] (for a tangential dashpot); a constant.
  static constexpr bool constant_stiffness = true;
  template <class O>
  [[gnu::always_inline]] inline typename O::Real stiffness(typename O::Real /*overlap*/, typename O::Real /*reduced_radius*/) const {
    return O::splat(ks);
  }

  template <class O>
  [[gnu::always_inline]] inline void update(HistoryStep<O>& s, typename O::Real fn, typename O::Real /*overlap*/, typename O::Real /*reduced_radius*/,
              typename O::Bool touch) const {
    capped_linear_spring<O>(ks, mu, s, fn, touch);
  }
  // Stored energy 1/2 |f_t|^2 / ks [J].
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(const typename O::Vec& ft, typename O::Real /*overlap*/, typename O::Real /*reduced_radius*/) const {
    return (O::splat(0.5) * O::dot(ft, ft)) / O::splat(ks);
  }
  // A contact that opens loses what is left in its spring, 1/2 ks |u_s|^2 with |u_s|^2 = `history2`.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real opening_loss(typename O::Real history2) const {
    return O::splat(0.5 * ks) * history2;
  }
  // The tangential force a stored history stands for [N] (measurements between steps).
  template <class O>
  [[gnu::always_inline]] inline typename O::Vec force_of(const typename O::Vec& history, typename O::Real /*overlap*/, typename O::Real /*reduced_radius*/) const {
    return O::splat(-ks) * history;
  }
};

}  // namespace dem
