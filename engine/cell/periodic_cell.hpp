#pragma once
// The periodic cell: the one place that knows its shape, wrapping and minimum image.
//
// The cell matrix H has the cell vectors as columns and is upper triangular, as in LAMMPS:
//   a = (Lx, 0, 0),  b = (xy, Ly, 0),  c = (xz, yz, Lz);
// a particle's real position is x = H s with s its fractional position in [0, 1)^3. With zero
// tilts (xy = xz = yz = 0) the cell is orthorhombic, and every formula below reduces, to the last
// bit, to the orthorhombic one: a tilt enters only as `+ tilt * component`, and adding +-0 leaves
// a double unchanged.
//
// Sign convention (used everywhere in the engine): strains and strain rates are positive in
// compression. The cell deforms with the compression-positive velocity gradient G, upper
// triangular like H (the cell does not rotate): dH/dt = -G H. Its diagonal is the axial strain
// rates (dL_k/dt = -G_kk L_k, so eps_k = -ln(L_k / L_k0)); its upper entries G_xy, G_xz, G_yz are
// the engineering shear strain rates, compression positive in the same sense: a positive G_xy is
// one that a positive (compression-positive) sigma_xy resists, so V sigma : G is the work done on
// the packing. The relative affine velocity of two points a branch vector l apart is -G l.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/types.hpp"

namespace dem {

// The cell's rate of deformation over a step: the compression-positive velocity gradient G.
struct CellRates {
  Vec3 axial = Vec3::Zero();  // G_xx, G_yy, G_zz [1/s]
  Vec3 shear = Vec3::Zero();  // G_xy, G_xz, G_yz, engineering shear strain rates [1/s]
  bool shears() const { return shear[0] != 0 || shear[1] != 0 || shear[2] != 0; }
};

class PeriodicCell {
 public:
  PeriodicCell() = default;
  explicit PeriodicCell(const Vec3& lengths_m) { set_lengths(lengths_m); reference_ = lengths_m; }

  const Vec3& lengths() const { return L_; }  // Lx, Ly, Lz: the diagonal of H
  const Vec3& inverse_lengths() const { return invL_; }
  const Vec3& tilts() const { return tilt_; }  // xy, xz, yz: the upper entries of H [m]
  bool sheared() const { return tilt_[0] != 0 || tilt_[1] != 0 || tilt_[2] != 0; }
  double volume() const { return L_.prod(); }
  Mat3 matrix() const {
    Mat3 H;
    H << L_[0], tilt_[0], tilt_[1], 0, L_[1], tilt_[2], 0, 0, L_[2];
    return H;
  }
  // The distance between opposite faces, per axis: V / |b x c|, V / |c x a|, V / |a x b| (the
  // lengths themselves, exactly, for an orthorhombic cell).
  Vec3 widths() const {
    if (!sheared()) return L_;
    const double xy = tilt_[0], xz = tilt_[1], yz = tilt_[2];
    const Vec3 bc(L_[1] * L_[2], -xy * L_[2], xy * yz - L_[1] * xz);
    return Vec3(volume() / bc.norm(), L_[1] * L_[2] / std::hypot(L_[2], yz), L_[2]);
  }

  // Lengths at which the axial strains are zero, and the shear strains accumulated since (reset
  // together at the start of a stage that measures strain).
  const Vec3& reference_lengths() const { return reference_; }
  void set_reference_lengths(const Vec3& l) { reference_ = l, shear_strain_.setZero(); }
  Vec3 strain() const {  // true axial strains, compression positive
    return Vec3(-std::log(L_[0] / reference_[0]), -std::log(L_[1] / reference_[1]), -std::log(L_[2] / reference_[2]));
  }
  // Engineering shear strains xy, xz, yz: the integral of G's upper entries since the reference
  // (unchanged by a re-mapping of the cell).
  const Vec3& shear_strain() const { return shear_strain_; }
  void set_shear_strain(const Vec3& g) { shear_strain_ = g; }

  // Nearest image of a fractional difference of two wrapped positions (each component in (-1, 1)).
  // Subtracts the nearest integer, found by the round-to-nearest of adding and removing
  // 1.5 * 2^52 (exact for |x| < 2^51 in the default rounding mode): two vectorisable additions
  // instead of a floor() call, which the profile showed as a quarter of the force loop.
  // In a tilted cell this is the nearest image of every pair closer than half the smallest width
  // (its fractional components are then within +-1/2); the Verlet list checks that contact range.
  static Vec3 min_image(const Vec3& ds) {
    constexpr double magic = 6755399441055744.0;  // 1.5 * 2^52
    const Vec3 nearest = (ds.array() + magic).matrix() - Vec3::Constant(magic);
    return ds - nearest;
  }

  // Real-space vector from particle i to the nearest periodic image of particle j (both wrapped).
  Vec3 branch(const Vec3& s_i, const Vec3& s_j) const { return to_real(min_image(s_j - s_i)); }

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

  // H s, and its inverse by back substitution.
  Vec3 to_real(const Vec3& s) const {
    return Vec3(s[0] * L_[0] + (s[1] * tilt_[0] + s[2] * tilt_[1]), s[1] * L_[1] + s[2] * tilt_[2], s[2] * L_[2]);
  }
  Vec3 to_fractional(const Vec3& x) const {
    const double sz = x[2] * invL_[2];
    const double sy = (x[1] - tilt_[2] * sz) * invL_[1];
    return Vec3((x[0] - (tilt_[0] * sy + tilt_[1] * sz)) * invL_[0], sy, sz);
  }

  // Homogeneous deformation over one step with the velocity gradient G: L_k <- L_k exp(-G_kk dt),
  // the tilts by dH/dt = -G H over the step (first order, from the start-of-step cell). Particles,
  // stored in fractional coordinates, follow it affinely without being touched.
  void deform(const Vec3& strain_rate_per_s, double dt_s) { deform(CellRates{strain_rate_per_s, Vec3::Zero()}, dt_s); }
  void deform(const CellRates& G, double dt_s) {
    Vec3 l;
    for (int k = 0; k < 3; ++k) l[k] = L_[k] * std::exp(-G.axial[k] * dt_s);
    if (sheared() || G.shears()) {
      const double xy = tilt_[0], xz = tilt_[1], yz = tilt_[2];
      tilt_[0] = xy * std::exp(-G.axial[0] * dt_s) - G.shear[0] * L_[1] * dt_s;
      tilt_[1] = xz * std::exp(-G.axial[0] * dt_s) - (G.shear[0] * yz + G.shear[1] * L_[2]) * dt_s;
      tilt_[2] = yz * std::exp(-G.axial[1] * dt_s) - G.shear[2] * L_[2] * dt_s;
      shear_strain_ += G.shear * dt_s;
    }
    set_lengths(l);
  }

  void set_lengths(const Vec3& l) {
    L_ = l;
    invL_ = l.cwiseInverse();
  }
  void set_tilts(const Vec3& t) { tilt_ = t; }

  // The re-mapping of a tilted cell (LAMMPS's box flip): a tilt past half of the length it tilts
  // along is brought back by a whole length, c -> c - n b, c -> c - n a, b -> b - n a. The lattice
  // of images is the same, so are the real positions; fractional positions must be recomputed
  // (`remapped`). Returns false, and changes nothing, when no tilt is past half a length.
  bool remap() {
    const double n_yz = std::round(tilt_[2] / L_[1]);
    double xz = tilt_[1] - n_yz * tilt_[0];
    const double n_xz = std::round(xz / L_[0]), n_xy = std::round(tilt_[0] / L_[0]);
    if (n_yz == 0 && n_xz == 0 && n_xy == 0) return false;
    tilt_ = Vec3(tilt_[0] - n_xy * L_[0], xz - n_xz * L_[0], tilt_[2] - n_yz * L_[1]);
    return true;
  }
  // A fractional position of the cell `before` as a wrapped fractional position of this cell.
  Vec3 remapped(const PeriodicCell& before, const Vec3& s) const {
    Vec3 out = to_fractional(before.to_real(s));
    wrap_any(out);
    return out;
  }

 private:
  Vec3 L_ = Vec3::Ones();
  Vec3 invL_ = Vec3::Ones();
  Vec3 tilt_ = Vec3::Zero();
  Vec3 reference_ = Vec3::Ones();
  Vec3 shear_strain_ = Vec3::Zero();
};

}  // namespace dem
