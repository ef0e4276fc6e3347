#pragma once
// One contact's history step, as the pair loop does it (dynamics/kernel_simd_pairs.inc), for the
// contact-law tests (not a test file itself: no _test suffix).
#include "contact/capped_spring.hpp"
#include "contact/scalar_lanes.hpp"

namespace dem::test {

// The history turned into the plane normal to n, then loaded by du = v_t dt and capped by the
// law (`update(step, f_n, overlap, R*, touch)`); returns the force, sets `sliding` and `lost`.
template <class Law>
Vec3 tangential_step(const Law& law, Vec3& history, const Vec3& n, const Vec3& v_t, double dt, double fn, double overlap,
                     double reduced_radius, bool& sliding, double& lost) {
  using O = scalar_lanes::Ops;
  HistoryStep<O> s;
  const auto h = scalar_lanes::lanes_of(history);
  s.h = turned_into_plane<O>(h, O::dot(h, h), scalar_lanes::lanes_of(n));
  s.du = O::splat(dt) * scalar_lanes::lanes_of(v_t);
  law.template update<O>(s, fn, overlap, reduced_radius, true);
  history = scalar_lanes::vec3_of(s.h);
  sliding = s.sliding;
  lost = s.lost;
  return scalar_lanes::vec3_of(s.force);
}

}  // namespace dem::test
