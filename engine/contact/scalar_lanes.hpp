#pragma once
// One lane: the contact laws' operations (contact/lane_ops.inc) on plain doubles, for the scalar
// pair loop, the pairs left over by the vectorised one, and the measurements. A condition is a
// bool, a vector three doubles; every operation is the one a vector lane does.
#include <cmath>
#include <cstdint>
#include <type_traits>  // std::conditional_t in lane_ops.inc (clang)

#include "core/types.hpp"

namespace dem::scalar_lanes {

using V = double;
using Mask = bool;
struct V3 {
  V x, y, z;
};
constexpr std::size_t lanes = 1;

inline V splat(double a) { return a; }
inline V zero() { return 0.0; }
inline Mask no_lanes() { return false; }
inline V select(Mask m, V if_true, V if_false) { return m ? if_true : if_false; }
inline V keep(Mask m, V a) { return m ? a : 0.0; }  // a where m, else +0.0
inline Mask both(Mask a, Mask b) { return a && b; }
inline Mask either(Mask a, Mask b) { return a || b; }
inline Mask nonzero(V a) { return a != 0.0; }  // true for NaN
inline unsigned bits(Mask m) { return m ? 1u : 0u; }
inline Mask not_ge(V a, V b) { return !(a >= b); }
inline Mask greater(V a, V b) { return a > b; }
inline Mask greater_equal(V a, V b) { return a >= b; }
inline V sqrt_of(V a) { return std::sqrt(a); }

inline V3 load(const Vec3* p) { return {(*p)[0], (*p)[1], (*p)[2]}; }
inline void store(Vec3* p, const V3& v) { *p = Vec3(v.x, v.y, v.z); }
inline V3 gather(const Vec3* base, const std::uint32_t* index) { return load(base + *index); }
inline V gather(const double* base, const std::uint32_t* index) { return base[*index]; }
inline void store_lanes(double* out, V a) { *out = a; }
inline V load_lanes(const double* in) { return *in; }
inline V3 lanes_of(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline Vec3 vec3_of(const V3& v) { return {v.x, v.y, v.z}; }

#include "contact/lane_ops.inc"

}  // namespace dem::scalar_lanes
