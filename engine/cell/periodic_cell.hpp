#pragma once
// The periodic orthorhombic cell: the one place that knows the lengths, wrapping and minimum image.
//
// Sign convention (used everywhere in the engine): strains and strain rates are positive in
// compression. A strain rate r on axis k shrinks L_k as dL_k/dt = -r L_k, so the true strain
// eps_k = -ln(L_k / L_k0) is positive in compression.
#include <cassert>
#include <cmath>

#include "core/types.hpp"

namespace dem {

class PeriodicCell {
 public:
  PeriodicCell() = default;
  explicit PeriodicCell(const Vec3& lengths_m) { set_lengths(lengths_m); reference_ = lengths_m; }

  const Vec3& lengths() const { return L_; }
  const Vec3& inverse_lengths() const { return invL_; }
  double volume() const { return L_.prod(); }

  // Lengths at which strain is zero (reset at the start of a stage that measures strain).
  const Vec3& reference_lengths() const { return reference_; }
  void set_reference_lengths(const Vec3& l) { reference_ = l; }
  Vec3 strain() const {  // true strain, compression positive
    return Vec3(-std::log(L_[0] / reference_[0]), -std::log(L_[1] / reference_[1]), -std::log(L_[2] / reference_[2]));
  }

  // Nearest image of a fractional difference of two wrapped positions (each component in (-1, 1)).
  // Subtracts the nearest integer, found by the round-to-nearest of adding and removing
  // 1.5 * 2^52 (exact for |x| < 2^51 in the default rounding mode): two vectorisable additions
  // instead of a floor() call, which the profile showed as a quarter of the force loop.
  static Vec3 min_image(const Vec3& ds) {
    constexpr double magic = 6755399441055744.0;  // 1.5 * 2^52
    const Vec3 nearest = (ds.array() + magic).matrix() - Vec3::Constant(magic);
    return ds - nearest;
  }

  // Real-space vector from particle i to the nearest periodic image of particle j (both wrapped).
  Vec3 branch(const Vec3& s_i, const Vec3& s_j) const { return min_image(s_j - s_i).cwiseProduct(L_); }

  // Brings any finite fractional position into [0, 1) (for input; `wrap` is the per-step version).
  static void wrap_any(Vec3& s) {
    for (int k = 0; k < 3; ++k) {
      s[k] -= std::floor(s[k]);
      if (s[k] >= 1.0) s[k] = 0.0;
    }
  }

  // Brings a fractional position back into [0, 1) after a step. Returns false if it cannot (a move
  // of more than a cell in one step, or NaN): the run has become unstable.
  static bool wrap(Vec3& s) {
    bool ok = true;
    for (int k = 0; k < 3; ++k) {  // selects, not branches: the compiler emits blends
      double x = s[k];
      x += x < 0.0 ? 1.0 : 0.0;
      x -= x >= 1.0 ? 1.0 : 0.0;  // also catches -1e-17 + 1 == 1.0
      s[k] = x;
      ok &= (x >= 0.0) & (x < 1.0);
    }
    return ok;
  }

  Vec3 to_real(const Vec3& s) const { return s.cwiseProduct(L_); }

  // Homogeneous deformation over one step: L_k <- L_k exp(-rate_k dt). Particles, stored in
  // fractional coordinates, follow it affinely without being touched.
  void deform(const Vec3& strain_rate_per_s, double dt_s) {
    Vec3 l;
    for (int k = 0; k < 3; ++k) l[k] = L_[k] * std::exp(-strain_rate_per_s[k] * dt_s);
    set_lengths(l);
  }

  void set_lengths(const Vec3& l) {
    L_ = l;
    invL_ = l.cwiseInverse();
  }

 private:
  Vec3 L_ = Vec3::Ones();
  Vec3 invL_ = Vec3::Ones();
  Vec3 reference_ = Vec3::Ones();
};

}  // namespace dem
