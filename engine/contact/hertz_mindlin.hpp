#pragma once
// Hertz-Mindlin contact law for elastic spheres of one material (Young's modulus E, Poisson's
// ratio nu), as in most DEM studies of sand:
//   normal:     f_n = 4/3 E* sqrt(R* overlap) overlap, E* = E / (2 (1 - nu^2)), R* = r_i r_j / (r_i + r_j);
//   tangential: Mindlin's no-slip stiffness k_t = 8 G* sqrt(R* overlap), G* = G / (2 (2 - nu)),
//               G = E / (2 (1 + nu)), applied incrementally: the history is the tangential force
//               itself, turned into the current tangent plane and loaded by f_t -= k_t v_t dt,
//               then capped at |f_t| <= mu f_n.
// The critical time step is Rayleigh's: pi r_min sqrt(rho / G) / (0.1631 nu + 0.8766).
#include <cmath>
#include <numbers>

#include "contact/capped_spring.hpp"

namespace dem {

struct HertzNormal {
  double young_modulus_Pa = 0;
  double poisson_ratio = 0;

  // Scene keys (contact/parameter.hpp). Poisson's ratio open at 0.5: an isotropic elastic solid
  // has -1 < nu <= 0.5, and nu = 0.5 (incompressible) is refused.
  static constexpr const char* law_name = "hertz_mindlin";
  static constexpr Parameter young_modulus_key{"young_modulus", "Pa", 0, 1e13, true, false, no_default,
                                               "Young's modulus E of the grains"};
  static constexpr Parameter poisson_ratio_key{"poisson_ratio", "", -1, 0.5, true, true, no_default,
                                               "Poisson's ratio nu of the grains"};
  static constexpr std::array parameters{young_modulus_key, poisson_ratio_key};
  static HertzNormal from(const ParameterValues& v) { return {v.at(young_modulus_key.name), v.at(poisson_ratio_key.name)}; }
  void write(ParameterValues& v) const { v[young_modulus_key.name] = young_modulus_Pa, v[poisson_ratio_key.name] = poisson_ratio; }

  double effective_modulus() const { return young_modulus_Pa / (2 * (1 - poisson_ratio * poisson_ratio)); }  // E*
  double shear_modulus() const { return young_modulus_Pa / (2 * (1 + poisson_ratio)); }                     // G
  double coefficient() const { return 4.0 / 3.0 * effective_modulus(); }                                  // 4/3 E*

  static constexpr bool needs_reduced_radius = true;
  static constexpr bool needs_normal_velocity = false;
  template <class O>
  [[gnu::always_inline]] inline typename O::Real force(typename O::Real overlap, typename O::Real reduced_radius) const {
    return (O::splat(coefficient()) * O::sqrt(reduced_radius * overlap)) * overlap;
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real friction_normal_force(typename O::Real fn) const {
    return fn;
  }
  // d f_n / d overlap = 3/2 f_n / overlap = 2 E* sqrt(R* overlap) [N/m].
  template <class O>
  [[gnu::always_inline]] inline typename O::Real stiffness(typename O::Real overlap, typename O::Real reduced_radius) const {
    return O::splat(1.5 * coefficient()) * O::sqrt(reduced_radius * overlap);
  }
  // Stored energy: the integral of f_n, 2/5 f_n overlap [J].
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(typename O::Real fn, typename O::Real overlap) const {
    return (O::splat(0.4) * fn) * overlap;
  }
  double critical_time_step(double /*m_min_kg*/, double r_min_m, double density) const {
    return std::numbers::pi * r_min_m * std::sqrt(density / shear_modulus()) / (0.1631 * poisson_ratio + 0.8766);
  }
  const char* critical_time_step_formula() const { return "the Rayleigh time pi r_min sqrt(rho/G) / (0.1631 nu + 0.8766)"; }
  // No constant stiffness: viscous body damping cannot be scaled (the scene must use local damping).
  double damping_stiffness() const { return 0; }
};

// Mindlin's tangential law with a Coulomb cap; the history is the tangential force [N].
struct MindlinCoulomb {
  static constexpr bool has_tangential = true;
  static constexpr const char* history_name = "tangential_force";
  static constexpr const char* history_unit = "N";
  static constexpr bool needs_reduced_radius = true;
  double shear_coefficient = 0;  // 8 G* [Pa]
  double mu = 0;

  static MindlinCoulomb of(const HertzNormal& n, double mu) {
    return {8 * n.shear_modulus() / (2 * (2 - n.poisson_ratio)), mu};
  }
  // Scene keys: on when friction > 0; the stiffness comes from the normal part's E and nu.
  static constexpr const char* switched_by = friction_key.name;
  static constexpr std::array parameters{friction_key};
  static MindlinCoulomb from(const ParameterValues& v) { return of(HertzNormal::from(v), v.at(friction_key.name)); }
  void write(ParameterValues& v) const { v[friction_key.name] = mu; }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real stiffness(typename O::Real overlap, typename O::Real reduced_radius) const {
    return O::splat(shear_coefficient) * O::sqrt(reduced_radius * overlap);
  }

  // f_t = f_t,turned - k_t du, capped at mu f_n. `lost`: the work the particles did on the contact
  // over du (trapezoidal), -1/2 (f_old + f_new).du, minus the change of the stored energy
  // |f|^2 / (2 k_t) at this step's k_t: 0 while it sticks, mu f_n |du| when it slides steadily.
  template <class O>
  [[gnu::always_inline]] inline void update(HistoryStep<O>& s, typename O::Real fn, typename O::Real overlap, typename O::Real reduced_radius,
              typename O::Bool touch) const {
    using Real = typename O::Real;
    using Vec = typename O::Vec;
    const Real kt = stiffness<O>(overlap, reduced_radius);
    const Vec f_old = s.h;
    const Vec f = f_old - kt * s.du;
    const Real limit = O::splat(mu) * fn;
    s.sliding = O::both(O::greater_equal(O::dot(f, f), limit * limit), touch);
    s.lost = O::zero();
    Vec kept = O::keep(touch, f);
    if (O::any(s.sliding)) {
      const Real norm = O::sqrt(O::dot(f, f));
      const Vec capped = O::select(O::greater(norm, O::zero()), limit / norm, O::zero()) * f;
      s.lost = O::keep(s.sliding, O::splat(-0.5) * O::dot(f_old + capped, s.du) -
                                      (O::dot(capped, capped) - O::dot(f_old, f_old)) / (O::splat(2.0) * kt));
      kept = O::keep(touch, O::select(s.sliding, capped, f));
    }
    s.h = kept;
    s.force = kept;
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(const typename O::Vec& ft, typename O::Real overlap, typename O::Real reduced_radius) const {
    return (O::splat(0.5) * O::dot(ft, ft)) / stiffness<O>(overlap, reduced_radius);
  }
  // The stiffness of the last step is not kept: the energy left when a contact opens, below
  // (mu f_n)^2 / (2 k_t) with f_n -> 0 (f_n ~ overlap^3/2, k_t ~ overlap^1/2), is not booked.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real opening_loss(typename O::Real /*history2*/) const {
    return O::zero();
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Vec force_of(const typename O::Vec& history, typename O::Real, typename O::Real) const {
    return history;
  }
};

}  // namespace dem
