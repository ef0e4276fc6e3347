#pragma once
// What a contact's history does in one step, written once for any lanes (contact/lane_ops.inc):
// the step's state (`HistoryStep`) and the linear spring capped by a Coulomb limit that both the
// linear tangential law and the rolling spring use.
#include "contact/parameter.hpp"

namespace dem {

// The Coulomb friction coefficient, read by every tangential law with a cap (and the switch that
// puts one in the law).
inline constexpr Parameter friction_key{"friction", "", 0, 10, false, false, no_default,
                                        "Coulomb friction coefficient mu; 0 = frictionless kernel"};

// One step of a contact's tangential (or rolling) history, for a block of lanes.
template <class O>
struct HistoryStep {
  typename O::Vec h;      // in: the history turned into the current tangent plane; out: after this step
  typename O::Vec du;     // in: the relative tangential (or rolling) displacement of this step [m]
  typename O::Vec force;  // out: the force on particle j [N] (rolling: the rolling "force", see rolling.hpp)
  typename O::Real lost;  // out: energy the cap took in this step [J]
  typename O::Bool sliding;  // out: lanes at the cap
};

// A history vector h (|h|^2 = h2) turned into the plane normal to the unit normal n, its magnitude kept.
template <class O>
[[gnu::always_inline]] inline typename O::Vec turned_into_plane(const typename O::Vec& h, typename O::Real h2,
                                                                const typename O::Vec& n) {
  using Real = typename O::Real;
  using Vec = typename O::Vec;
  const typename O::Bool had = O::greater(h2, O::zero());
  const Vec turned = h - O::dot(n, h) * n;
  const Real new2 = O::dot(turned, turned);
  const typename O::Bool rescale = O::both(had, O::greater(new2, O::zero()));
  return O::select(had, O::select(rescale, O::sqrt(h2 / new2) * turned, turned), h);
}

// A linear spring of stiffness k on the elastic displacement u (the history), loaded by du and
// capped at |k u| <= limit (Cundall & Strack 1979): f = -k u. Lanes not `touch`ing end with u = 0.
//
// `lost` is the energy the cap took: the work the particles did on the spring over du, the force
// taken as the mean of its values before and after (the trapezoidal rule of the leapfrog energy
// balance), minus the change of the stored energy 1/2 k |u|^2:
//   1/2 k [(u_old + u_new).du - (|u_new|^2 - |u_old|^2)],
// which is limit |du| when the contact slides steadily at the cap, and 0 when it sticks.
template <class O>
[[gnu::always_inline]] inline void capped_linear_spring(double k, double friction, HistoryStep<O>& s, typename O::Real fn, typename O::Bool touch) {
  using Real = typename O::Real;
  using Vec = typename O::Vec;
  const Vec u_old = s.h;
  const Vec u = u_old + s.du;
  const Real limit = O::splat(friction) * fn;
  s.sliding = O::both(O::greater_equal(O::splat(k * k) * O::dot(u, u), limit * limit), touch);
  s.lost = O::zero();
  Vec kept = O::keep(touch, u);
  if (O::any(s.sliding)) {  // lanes where nothing slides skip the cap's square root and divide
    const Real norm = O::sqrt(O::dot(u, u));
    const Real cap = O::select(O::greater(norm, O::zero()), limit / (O::splat(k) * norm), O::zero());
    const Vec capped = cap * u;
    s.lost = O::keep(s.sliding, O::splat(0.5 * k) * (O::dot(u_old + capped, s.du) - (O::dot(capped, capped) - O::dot(u_old, u_old))));
    kept = O::keep(touch, O::select(s.sliding, capped, u));
  }
  s.h = kept;
  s.force = O::splat(-k) * kept;
}

}  // namespace dem
