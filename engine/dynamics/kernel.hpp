#pragma once
// The hot loops, as templates on the contact law and the damping form, so that each scene runs a
// monomorphic loop with only the code it needs (no tangential code for a frictionless scene).
#include <cmath>
#include <vector>

#include "cell/periodic_cell.hpp"
#include "contact/linear_spring.hpp"
#include "core/particles.hpp"
#include "dynamics/simulation.hpp"
#include "neighbour/verlet_list.hpp"

namespace dem {

// Contact forces at the current positions. Velocities are those of the previous half step; the
// relative velocity at a contact includes the affine part -rate (.) l of the deforming cell.
// Force and torque arrays are overwritten; `sums` receives the stress and servo stiffness.
template <class Friction>
void compute_forces(const LinearSpring<Friction>& law, const Particles& p, const PeriodicCell& cell, PairList& pairs,
                    const Vec3& strain_rate, double dt, std::vector<Vec3>& force, std::vector<Vec3>& torque,
                    StepSums& sums) {
  const std::size_t n = p.size();
  force.assign(n, Vec3::Zero());
  if constexpr (Friction::has_tangential) torque.assign(n, Vec3::Zero());
  Mat3 stress = Mat3::Zero();
  Vec3 stiffness = Vec3::Zero();
  std::size_t contacts = 0;
  double sum_fn = 0;
  const double kn = law.kn;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::uint32_t i = pairs.first[k], j = pairs.second[k];
    const Vec3 l = cell.branch(p.s[i], p.s[j]);  // centre of i to centre of j
    const double dist2 = l.squaredNorm();
    const double rsum = p.radius[i] + p.radius[j];
    if (dist2 >= rsum * rsum) {
      if constexpr (Friction::has_tangential) {
        pairs.spring[k].setZero();
        pairs.sliding[k] = 0;
      }
      continue;
    }
    const double dist = std::sqrt(dist2);
    const Vec3 nrm = l / dist;
    const double overlap = rsum - dist;
    const double fn = kn * overlap;
    Vec3 f = fn * nrm;  // force on j; -f acts on i
    if constexpr (Friction::has_tangential) {
      const double arm_i = p.radius[i] - 0.5 * overlap, arm_j = p.radius[j] - 0.5 * overlap;
      const Vec3 v_rel = p.v[j] - p.v[i] - strain_rate.cwiseProduct(l) - (arm_i * p.omega[i] + arm_j * p.omega[j]).cross(nrm);
      const Vec3 v_t = v_rel - nrm.dot(v_rel) * nrm;
      bool sliding = false;
      const Vec3 ft = law.friction.tangential(pairs.spring[k], nrm, v_t, dt, fn, sliding);
      pairs.sliding[k] = sliding;
      f += ft;
      const Vec3 nxft = nrm.cross(ft);
      torque[i] -= arm_i * nxft;
      torque[j] -= arm_j * nxft;
    }
    force[j] += f;
    force[i] -= f;
    stress.noalias() += f * l.transpose();
    // Servo stiffness: d(sigma_kk)/d(eps_k) of the normal springs if the contact followed the
    // cell, kn (n_k l_k)^2. (Adding the sticking tangential springs, ks (l_k^2 - (n_k l_k)^2),
    // over-estimates the relaxed stiffness: on a 1,000-sphere packing ramped at 2 MPa/s the
    // stress then lagged its target by 0.7 % of p, against a 0.3 % lead with kn alone.)
    const Vec3 nl = nrm.cwiseProduct(l);
    stiffness += kn * nl.cwiseProduct(nl);
    ++contacts;
    sum_fn += fn;
  }
  const double inv_volume = 1.0 / cell.volume();
  sums.stress_Pa = 0.5 * (stress + stress.transpose()) * inv_volume;
  sums.stiffness_Pa = stiffness * inv_volume;
  sums.contacts = contacts;
  sums.sum_normal_force_N = sum_fn;
}

// Viscous body damping, integrated semi-implicitly (exact for the damping term alone):
// v <- ((1 - h) v + dt F / m) / (1 + h), h = c dt / (2 m).
struct ViscousDamping {
  std::vector<double> a, b, a_rot, b_rot;  // per-particle update coefficients
  ViscousDamping(const Particles& p, const Damping& d, double kn, double dt) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double h = d.translational * dt * std::sqrt(kn / p.mass[i]);
      const double h_rot = d.rotational * dt * p.radius[i] * std::sqrt(kn / p.inertia[i]);
      a.push_back((1 - h) / (1 + h));
      b.push_back(dt / (p.mass[i] * (1 + h)));
      a_rot.push_back((1 - h_rot) / (1 + h_rot));
      b_rot.push_back(dt / (p.inertia[i] * (1 + h_rot)));
    }
  }
  void velocity(std::size_t i, Vec3& v, const Vec3& f) const { v = a[i] * v + b[i] * f; }
  void spin(std::size_t i, Vec3& w, const Vec3& t) const { w = a_rot[i] * w + b_rot[i] * t; }
};

// Cundall's local non-viscous damping: F_k <- F_k - alpha |F_k| sign(v_k), v at the previous half step.
struct LocalDamping {
  double alpha, alpha_rot;
  std::vector<double> dt_over_m, dt_over_I;
  LocalDamping(const Particles& p, const Damping& d, double /*kn*/, double dt)
      : alpha(d.translational), alpha_rot(d.rotational) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      dt_over_m.push_back(dt / p.mass[i]);
      dt_over_I.push_back(dt / p.inertia[i]);
    }
  }
  static Vec3 damped(const Vec3& f, const Vec3& v, double a) {
    Vec3 out;
    for (int k = 0; k < 3; ++k) out[k] = f[k] - a * std::abs(f[k]) * (v[k] > 0 ? 1.0 : v[k] < 0 ? -1.0 : 0.0);
    return out;
  }
  void velocity(std::size_t i, Vec3& v, const Vec3& f) const { v += dt_over_m[i] * damped(f, v, alpha); }
  void spin(std::size_t i, Vec3& w, const Vec3& t) const { w += dt_over_I[i] * damped(t, w, alpha_rot); }
};

// Leapfrog update of velocities and fractional positions. Returns the translational kinetic
// energy of the fluctuating motion at the new half step [J], or NaN if a particle moved by more
// than a cell in one step (the run is unstable; positions can no longer be trusted).
template <bool Rotate, class DampingPolicy>
double integrate(const DampingPolicy& damping, Particles& p, const PeriodicCell& cell, const std::vector<Vec3>& force,
                 const std::vector<Vec3>& torque, double dt) {
  const Vec3 dt_over_L = dt * cell.inverse_lengths();
  double twice_ke = 0;
  bool wrapped = true;
  for (std::size_t i = 0; i < p.size(); ++i) {
    damping.velocity(i, p.v[i], force[i]);
    p.s[i] += p.v[i].cwiseProduct(dt_over_L);
    wrapped &= PeriodicCell::wrap(p.s[i]);
    twice_ke += p.mass[i] * p.v[i].squaredNorm();
    if constexpr (Rotate) damping.spin(i, p.omega[i], torque[i]);
  }
  return wrapped ? 0.5 * twice_ke : std::nan("");
}

}  // namespace dem
