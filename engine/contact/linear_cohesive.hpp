#pragma once
// The linear spring with a constant cohesive pull-off force (material.law: linear_cohesive): a
// contact that pulls its spheres together with a fixed force f_c while they overlap, the simplest
// adhesion model (a constant attraction, as the DMT limit of adhesive elastic spheres, Derjaguin,
// Muller & Toporov 1975, with the Hertzian spring replaced by a linear one; PFC's and LAMMPS's
// cohesive laws are refinements of it):
//   normal:     f_n = kn overlap - f_c while overlap > 0, and 0 once it is not: the contact breaks
//               at zero overlap as the linear law's does (no tension beyond contact). Its
//               potential U = 1/2 kn overlap^2 - f_c overlap is continuous at touch but its force
//               jumps by f_c there, so the energy balance closes at O(dt), not O(dt^2).
//               Two spheres held by nothing else rest at overlap f_c / kn; pulling them apart
//               takes a force f_c (reached as the overlap goes to 0).
//   tangential: the linear law's Coulomb spring (LinearCoulomb, keys ks and friction), its cap
//               taking the compressive elastic part, |f_t| <= mu (f_n + f_c) = mu kn overlap: a
//               contact pulled to the brink of opening carries no friction, and the cap grows from
//               0 at touch as the linear law's does. (LAMMPS's granular JKR/DMT laws add 2 F_pulloff
//               instead; with a constant force the choice here keeps the cap >= 0 without a clip.)
// The critical time step, the servo stiffness and the viscous damping are the linear spring's (kn).
#include "contact/linear_spring.hpp"

namespace dem {

struct LinearCohesiveNormal : LinearNormal {
  double cohesion_force_N = 0;  // f_c, the constant pull-off force [N]

  // Scene keys (contact/parameter.hpp): the linear spring's kn, and f_c.
  static constexpr const char* law_name = "linear_cohesive";
  static constexpr Parameter cohesion_force_key{
      "cohesion_force", "N", 0, 1e6, false, false, no_default,
      "constant pull-off force f_c: f_n = kn overlap - f_c while the spheres overlap, "
      "0 once they do not; friction capped at mu kn overlap",
      false, 0.05};
  static constexpr std::array parameters{kn_key, cohesion_force_key};
  static LinearCohesiveNormal from(const ParameterValues& v) { return {LinearNormal::from(v), v.at(cohesion_force_key.name)}; }
  void write(ParameterValues& v) const { LinearNormal::write(v), v[cohesion_force_key.name] = cohesion_force_N; }

  // Lanes out of contact are dropped by the pair loop, so -f_c never acts beyond touch.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real force(typename O::Real overlap, typename O::Real /*reduced_radius*/) const {
    return O::splat(kn) * overlap - O::splat(cohesion_force_N);
  }
  // The Coulomb (and rolling) cap takes the compressive elastic part f_n + f_c = kn overlap,
  // clipped at 0 against the rounding of (kn overlap - f_c) + f_c at a grazing contact.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real friction_normal_force(typename O::Real fn) const {
    const typename O::Real elastic = fn + O::splat(cohesion_force_N);
    return O::select(O::greater(elastic, O::zero()), elastic, O::zero());
  }
  // Stored energy U = 1/2 kn overlap^2 - f_c overlap = 1/2 (f_n - f_c) overlap [J] (< 0 below
  // overlap 2 f_c / kn: a cohesive contact holds energy that separating the spheres must supply).
  template <class O>
  [[gnu::always_inline]] inline typename O::Real energy(typename O::Real fn, typename O::Real overlap) const {
    return (O::splat(0.5) * (fn - O::splat(cohesion_force_N))) * overlap;
  }
};

}  // namespace dem
