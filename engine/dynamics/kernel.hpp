#pragma once
// The hot loops, as templates on the contact law and the damping form, so that each scene runs a
// monomorphic loop with only the code it needs (no tangential code for a frictionless scene).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <omp.h>

#include "cell/periodic_cell.hpp"
#include "contact/contact_history.hpp"
#include "contact/contact_law.hpp"
#include "contact/scalar_lanes.hpp"
#include "core/particles.hpp"
#include "dynamics/simulation.hpp"
#include "neighbour/verlet_list.hpp"

namespace dem {

// Work is split into chunks of a fixed size, independent of the number of threads; sums are
// formed per chunk in index order and the chunk sums are added in chunk order. Every result is
// therefore bit-for-bit the same on 1 or N threads.
//
// Pairs are chunked by particle: pair chunk c holds the pairs whose `first` particle is in
// particle chunk c. Which pairs out of contact the list holds (it depends on the Verlet skin and
// on when it was rebuilt) then changes no sum: they add exact zeros (+0.0 to a sum that is never
// -0.0), and the contacts of each chunk are the same whatever the skin. A run is bit for bit the
// same with any skin.
inline constexpr std::ptrdiff_t chunk_size = 512;
inline std::ptrdiff_t chunk_count(std::size_t n) { return (static_cast<std::ptrdiff_t>(n) + chunk_size - 1) / chunk_size; }
// The first particle of chunk c of n particles (n for c = chunk_count(n)).
inline std::size_t chunk_first_particle(std::size_t n, std::ptrdiff_t c) { return std::min(n, static_cast<std::size_t>(c * chunk_size)); }
// The pairs [begin, end) of pair chunk c: those whose first particle is in particle chunk c.
struct PairRange {
  std::size_t begin, end;
};
inline PairRange pair_chunk_range(const PairIndex& index, std::ptrdiff_t c) {
  const std::size_t n = index.first_begin.size() - 1;
  return {index.first_begin[chunk_first_particle(n, c)], index.first_begin[chunk_first_particle(n, c + 1)]};
}

// A step over the chunks: pairs(c, begin, end) computes the forces of pair chunk c (pairs
// [begin, end)), move(c, begin, end) moves the particles [begin, end) of chunk c and returns false
// if one could not be wrapped into the cell; returns whether every move returned true.
//
// On one thread, one sweep: each chunk moves right after its pairs, while their forces are still
// in the cache (docs/performance.md has what that gains). That is allowed because pairs are listed
// with first < second: every pair of a particle of chunk c lies in pair chunk c or an earlier one,
// and no later pair chunk reads a particle of chunk c. On more threads, the pairs of every chunk,
// then (after the barrier) the moves, each thread taking the same chunks both times: equal runs
// of chunks starting from chunk 1, the first chunk going last, with the partial last chunk (the
// lowest-numbered particles are `first` in the pairs across the wrap of a spatially sorted order,
// so chunk 0 has the most pairs: on the 8,000-sphere dense packing 2,390 against about 1,690, and
// 506 in the last chunk of 320 particles). Moving chunks during the sweep on two threads, those
// sharing pairs with another thread's chunks after the barrier, was 5 to 9 % slower on 8,000
// spheres. Each chunk's forces and motion are the same either way, so the result is the same bit
// for bit on any number of threads.
//
// The bodies are also told whether the sweep runs on one thread (`serial`): only then may the pairs
// of a chunk add their forces straight into the particles' sums (see PairForces).
template <class PairBody, class MoveBody>
bool sweep_chunks(const PairIndex& index, const PairBody& pairs, const MoveBody& move) {
  const std::size_t n = index.first_begin.size() - 1;
  const std::ptrdiff_t chunks = chunk_count(n);
  auto pairs_of = [&](std::ptrdiff_t c, bool serial) {  // the pairs of pair_chunk_range(index, c)
    pairs(static_cast<std::size_t>(c), std::size_t{index.first_begin[chunk_first_particle(n, c)]},
          std::size_t{index.first_begin[chunk_first_particle(n, c + 1)]}, serial);
  };
  auto move_of = [&](std::ptrdiff_t c, bool serial) {
    return move(static_cast<std::size_t>(c), chunk_first_particle(n, c), chunk_first_particle(n, c + 1), serial);
  };
  int every = 1;
  // One thread runs its sweep inside the parallel region too: outside it, the same loop ran 6 %
  // slower with mu = 0.5 (3.17-3.25e7 particle-steps/s against 3.32-3.44e7; code generation).
#pragma omp parallel reduction(&& : every)
  {
    if (omp_get_num_threads() == 1) {
      for (std::ptrdiff_t c = 0; c < chunks; ++c) pairs_of(c, true), every = move_of(c, true) && every;
    } else {
#pragma omp for schedule(static)
      for (std::ptrdiff_t rotated = 0; rotated < chunks; ++rotated) pairs_of((rotated + 1) % chunks, false);
#pragma omp for schedule(static)
      for (std::ptrdiff_t rotated = 0; rotated < chunks; ++rotated) every = move_of((rotated + 1) % chunks, false) && every;
    }
  }
  return every != 0;
}

// What the update (forces_and_motion) sums over the particles [J].
struct MotionSums {
  double kinetic_half_step = 0;  // translational, 1/2 m |v(n+1/2)|^2
  double kinetic_centred = 0;    // translational + rotational, 1/2 m v(n-1/2).v(n+1/2) (+ the same with I, w)
  double damping_loss = 0;       // sum of dt F.v_mid - (change of 1/2 m v^2), translational + rotational
  double max_speed2 = 0;         // largest |v(n+1/2)|^2 [m^2/s^2], for the Verlet list's displacement bound
};

// A particle's net force or torque while its pairs add to it: x, y, z and a zero, one 256-bit load.
struct alignas(32) Sum4 {
  double v[4];
};

// A vector per pair kept as its x, y and z in arrays of their own: the vectorised loops move
// `lanes` consecutive pairs' components with one load or store each, where an array of Vec3 needs
// six shuffles more per load or store of four pairs.
struct PairComponents {
  std::vector<double> x, y, z;
  void resize(std::size_t n) { x.resize(n), y.resize(n), z.resize(n); }
};
// Where the loops find PairComponents (D: double, or const double to read only).
template <class D>
struct ComponentsAt {
  D* __restrict x;
  D* __restrict y;
  D* __restrict z;
};
inline ComponentsAt<double> components_at(PairComponents& c) { return {c.x.data(), c.y.data(), c.z.data()}; }
inline ComponentsAt<const double> components_at(const PairComponents& c) { return {c.x.data(), c.y.data(), c.z.data()}; }

// Forces of one evaluation, and the per-chunk partial sums of both loops. Kept between steps so
// that a step allocates nothing.
//
// Forces are stored per pair and gathered per particle by the update (no scattered writes, so
// pairs can be processed in parallel). Except on one thread with a law without torques: there
// each pair adds its force straight into the sums of its two particles (`scattered`), in pair
// order, and nothing is stored per pair. Each particle's sum then sees the same additions in the
// same order as the gather (the pairs where it is `second`, then those where it is `first`,
// ascending), so both give the same bits. A pair out of contact adds nothing, where the gather adds
// +0.0: the same, as the sums start at +0.0 and so are never -0.0. The update reads each sum and
// sets it back to zero, so the sums are zero between steps. Up to scatter_max_particles (below).
struct PairForces {
  std::vector<Vec3> force;              // force on `second` [N]; -force acts on `first`
  std::vector<Vec3> torque_i, torque_j;  // minus the torques on `first` and `second` [N m] (laws that rotate only)
  std::vector<StepSums> chunk_sums;       // per pair chunk; every chunk writes its own entry
  std::vector<MotionSums> motion_sums;    // per chunk of particles
  std::vector<Sum4> net_force;            // per particle: the scattered sums, zero between steps
  // Laws with contact dashpots: per pair, the dashpots' force on `second` [N] of this evaluation
  // (0 out of contact), for the second half of their dissipation (dashpot_second_half, below).
  PairComponents dashpot_force;
  // Laws with contact dashpots that rotate: per pair, the centre distance |l| of this evaluation
  // [m], from which the second half takes that evaluation's lever arms over |l| with one division
  // (no square root, one division where three were).
  std::vector<double> dashpot_distance;
  // Per pair chunk, when the pair loop booked the evaluation before's second half
  // (PairLoop::DashpotOut::previous): -sum F_d . u(n-1/2) of its pairs [W].
  std::vector<double> previous_dashpot_sums;
  // Laws whose dashpot coefficients depend on the masses only (Law::dashpot_per_pair): per pair,
  // c_n = 2 zeta sqrt(m* k_n) [kg/s] and c_t / dt [kg/s^2] (frictional laws), and the pair list
  // they were computed for (VerletList::changes; dashpot_coefficients below).
  std::vector<double> dashpot_c_n, dashpot_c_t_over_dt;
  std::uint64_t dashpot_list = ~std::uint64_t{0};
  Sum4* scattered_sums(std::size_t particles) {
    net_force.resize(particles, Sum4{});
    return net_force.data();
  }
};
// The scatter pays while the sample is small: on the benchmark machine (AMD EPYC, 1 MB L2 per
// core, 32 MB L3), one thread, mu = 0, +13 % at 8,000 spheres, ahead in 4 rounds of 5 at 64,000,
// even at 216,000 and 3 to 9 % slower at 512,000. With torques too (mu = 0.5) it was 8 % slower
// at 8,000 spheres and no faster at 64,000 (docs/performance.md).
inline constexpr std::size_t scatter_max_particles = 150'000;

// The second half of the evaluation before's dashpot work, booked by the next pair loop
// (dashpot_second_half): whether to book it, and the map from a branch vector of the cell now to
// the cell of that evaluation, back = H(n) H(n+1)^-1 (upper triangular; Simulation keeps it). The
// update moved each particle's fractional position by H(n)^-1 v dt, so the branch vector of that
// evaluation is l(n) = back l(n+1) - (v_j - v_i) dt: its normal and lever arms come back without
// being stored.
struct PreviousHalf {
  bool book = false;
  Mat3 back = Mat3::Identity();
};

// The inputs and outputs of the pair loop, as raw pointers (the arrays do not alias, and the
// compiler keeps them in registers). The pair loop itself (dynamics/kernel_simd_pairs.inc) is
// written once for any lanes and compiled for one lane, AVX2 and AVX-512; the contact law
// (contact/contact_law.hpp) supplies every force, energy and history update. `Sheared`: the
// cell may be tilted or shearing (the branch vectors and the affine velocity take the tilts and
// shear rates in); an orthorhombic cell runs the loop without them (the same result bit for bit).
template <class Law, bool Sheared>
struct PairLoop {
  Law law;
  PeriodicCell cell;
  CellRates rates;
  double dt;
  const std::uint32_t* __restrict first;
  const std::uint32_t* __restrict second;
  const Vec3* __restrict s;
  const Vec3* __restrict v;
  const Vec3* __restrict omega;
  const double* __restrict radius;
  Vec3* __restrict tangential;  // the tangential law's history (frictional laws)
  std::uint8_t* __restrict sliding_flag;
  Vec3* __restrict rolling;     // rolling springs (laws with rolling resistance)
  Vec3* __restrict pair_force;
  Vec3* __restrict torque_i;
  Vec3* __restrict torque_j;
  Sum4* __restrict scattered = nullptr;  // set: add the forces into these particle sums instead (see PairForces)
  const double* __restrict mass;  // laws with contact dashpots (m*); last, so the other laws' loop reads the fields it did
  // Laws with contact dashpots: where the pair loop leaves each pair's dashpot force
  // (PairForces); no member at all for the other laws.
  struct DashpotOut {
    ComponentsAt<double> force;
    double* __restrict distance;           // PairForces::dashpot_distance (laws that rotate)
    const double* __restrict c_n;          // the per-pair coefficients (Law::dashpot_per_pair), else null
    const double* __restrict c_t_over_dt;
    // Book the second half of the evaluation before's dashpot work (dashpot_second_half) while
    // this loop has the velocities of the half step after it: from the force still stored for
    // each pair, before this evaluation's replaces it, and that evaluation's geometry rebuilt
    // from this one's (PreviousHalf), into DashpotSums::previous (then
    // PairForces::previous_dashpot_sums). Only while the pair list is the one it was stored for.
    PreviousHalf previous;
  };
  struct NoDashpot {};
  [[no_unique_address]] std::conditional_t<Law::damped, DashpotOut, NoDashpot> dashpot_out;

  // Sizes the outputs and points at them.
  PairLoop(const Law& law_, const Particles& p, const PeriodicCell& cell_, const PairList& pairs, ContactHistory& history,
           const CellRates& rates_, double dt_, PairForces& out, const PreviousHalf& previous = {})
      : law(law_), cell(cell_), rates(rates_), dt(dt_) {
    // One spare entry, zero: the vectorised update reads each entry as four doubles (the fourth
    // is the next entry's first, and is dropped), so the last pair's read stays inside the array.
    out.force.resize(pairs.size() + 1);
    out.force.back().setZero();
    if constexpr (Law::rotates) {
      out.torque_i.resize(pairs.size() + 1);
      out.torque_j.resize(pairs.size() + 1);
      out.torque_i.back().setZero();
      out.torque_j.back().setZero();
    }
    out.chunk_sums.resize(static_cast<std::size_t>(chunk_count(p.size())));
    first = pairs.first.data();
    second = pairs.second.data();
    s = p.s.data();
    v = p.v.data();
    omega = p.omega.data();
    radius = p.radius.data();
    mass = p.mass.data();
    tangential = history.tangential.data();
    sliding_flag = history.sliding.data();
    rolling = history.rolling.data();
    pair_force = out.force.data();
    torque_i = out.torque_i.data();
    torque_j = out.torque_j.data();
    if constexpr (Law::damped) {
      out.dashpot_force.resize(pairs.size());
      if constexpr (Law::rotates) out.dashpot_distance.resize(pairs.size());
      dashpot_out = {components_at(out.dashpot_force), out.dashpot_distance.data(), out.dashpot_c_n.data(),
                     out.dashpot_c_t_over_dt.data(), previous};
    }
  }
};

// A pair chunk's sums for a law with contact dashpots: also the second half of the evaluation
// before's dashpot work, when the loop books it (in its own struct, so that the other laws' sums
// and their loops' code stay as they were).
struct DashpotSums : StepSums {
  double previous = 0;  // -sum F_d . u(n-1/2) of the chunk's pairs [W]
};

// Laws with Law::dashpot_per_pair: each pair's dashpot coefficients c_n = 2 zeta sqrt(m* k_n)
// and c_t / dt = 2 zeta sqrt(m* k_t) / dt, computed with the pair loop's operations (so the same
// bits as computing them there every step), into `out` for the pair list numbered `list`. Two mass
// lookups, two square roots and two divisions per pair that the pair loop no longer does.
template <class Law>
void dashpot_coefficients(const Law& law, const Particles& p, const PairList& pairs, double dt, std::uint64_t list,
                          PairForces& out) {
  using Ops = scalar_lanes::Ops;
  const std::size_t n = pairs.size();
  out.dashpot_c_n.resize(n);
  if constexpr (Law::has_tangential) out.dashpot_c_t_over_dt.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double mi = p.mass[pairs.first[k]], mj = p.mass[pairs.second[k]];
    const double reduced_mass = (mi * mj) / (mi + mj);
    out.dashpot_c_n[k] = law.normal.template normal_coefficient<Ops>(0.0, 0.0, reduced_mass);
    if constexpr (Law::has_tangential) {
      const double kt = law.tangential.template stiffness<Ops>(0.0, 0.0);
      out.dashpot_c_t_over_dt[k] = law.normal.template tangential_coefficient<Ops>(kt, reduced_mass) / dt;
    }
  }
  out.dashpot_list = list;
}

// Adds the chunk sums in chunk order, divides the stress and stiffness by the volume and
// symmetrises the stress.
StepSums total_of_chunks(const std::vector<StepSums>& chunk_sums, const PeriodicCell& cell);

// Viscous body damping, integrated semi-implicitly (exact for the damping term alone):
// v <- ((1 - h) v + dt F / m) / (1 + h), h = c dt / (2 m).
struct ViscousDamping {
  std::vector<double> a, b, a_rot, b_rot;  // per-particle update coefficients
  ViscousDamping(const Particles& p, const Damping& d, double kn, double dt) {  // kn: the law's damping stiffness
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

// The per-particle work of the update, on raw pointers: `gather` sums a particle's pair forces
// and torques, `update` moves it. The vectorised version (dynamics/kernel_simd.cpp) updates four
// particles at a time and uses these for the gathers and the particles left over. `Sheared`: the
// fractional step is H^-1 v dt by back substitution (with zero tilts the same bits as v dt / L).
template <bool Rotate, class DampingPolicy, bool Sheared = false>
struct ParticleLoop {
  const DampingPolicy& damping;
  Vec3 dt_over_L;
  Vec3 inv_L, tilt;  // Sheared only
  double dt;
  std::size_t n;
  const std::uint32_t* __restrict first_begin;
  const std::uint32_t* __restrict second_begin;
  const std::uint32_t* __restrict second_pairs;
  const Vec3* __restrict pair_force;
  const Vec3* __restrict torque_i;
  const Vec3* __restrict torque_j;
  const double* __restrict mass;
  const double* __restrict inertia;
  Vec3* __restrict v;
  Vec3* __restrict s;
  Vec3* __restrict omega;
  Vec3* __restrict net;
  Sum4* __restrict scattered = nullptr;  // set: the pair loop summed the forces here, per particle (see PairForces)

  // Sizes the outputs and points at them.
  ParticleLoop(const DampingPolicy& damping_, Particles& p, const PeriodicCell& cell, const PairIndex& index,
               PairForces& pf, std::vector<Vec3>& force, double dt_)
      : damping(damping_), dt_over_L(dt_ * cell.inverse_lengths()), inv_L(cell.inverse_lengths()), tilt(cell.tilts()),
        dt(dt_), n(p.size()) {
    force.resize(n);
    pf.motion_sums.resize(static_cast<std::size_t>(chunk_count(n)));
    first_begin = index.first_begin.data();
    second_begin = index.second_begin.data();
    second_pairs = index.second_pairs.data();
    pair_force = pf.force.data();
    torque_i = pf.torque_i.data();
    torque_j = pf.torque_j.data();
    mass = p.mass.data();
    inertia = p.inertia.data();
    v = p.v.data();
    s = p.s.data();
    omega = p.omega.data();
    net = force.data();
  }

  // Net force and torque of particle i, gathered in pair order (or taken from its sums).
  void gather(std::size_t i, Vec3& f, Vec3& t) const {
    f.setZero(), t.setZero();
    if (!Rotate && scattered) {  // summed by the pair loop: take the sum, leave zeros
      Sum4& sum = scattered[i];
      f = Vec3(sum.v[0], sum.v[1], sum.v[2]), sum = Sum4{};
      return;
    }
    for (std::uint32_t m = second_begin[i]; m < second_begin[i + 1]; ++m) {
      const std::uint32_t k = second_pairs[m];
      f += pair_force[k];
      if constexpr (Rotate) t -= torque_j[k];
    }
    for (std::uint32_t k = first_begin[i]; k < first_begin[i + 1]; ++k) {
      f -= pair_force[k];
      if constexpr (Rotate) t -= torque_i[k];
    }
  }

  // H^-1 v dt: back substitution from z (v dt / L for an orthorhombic cell).
  Vec3 fractional_step(const Vec3& u) const {
    if constexpr (!Sheared) {
      return u.cwiseProduct(dt_over_L);
    } else {
      const double uz = u[2] * inv_L[2], vy = u[1] - tilt[2] * uz, uy = vy * inv_L[1];
      return Vec3((u[0] - (tilt[0] * uy + tilt[1] * uz)) * dt_over_L[0], vy * dt_over_L[1], u[2] * dt_over_L[2]);
    }
  }

  // Leapfrog update of particle i under net force f (stored in net[i]) and torque t; adds to `sums`
  // (twice the energies). Returns false if the particle cannot be wrapped back into the cell.
  bool update(std::size_t i, const Vec3& f, const Vec3& t, MotionSums& sums) const {
    net[i] = f;
    const Vec3 v_old = v[i];
    damping.velocity(i, v[i], f);
    s[i] += fractional_step(v[i]);
    const bool ok = PeriodicCell::wrap(s[i]);
    const double speed2 = v[i].squaredNorm(), m = mass[i], twice_ke_new = m * speed2;
    sums.max_speed2 = std::max(sums.max_speed2, speed2);
    sums.kinetic_half_step += twice_ke_new;
    sums.kinetic_centred += m * v_old.dot(v[i]);
    sums.damping_loss += dt * f.dot(v_old + v[i]) - (twice_ke_new - m * v_old.squaredNorm());
    if constexpr (Rotate) {
      const Vec3 w_old = omega[i];
      damping.spin(i, omega[i], t);
      const double I = inertia[i], twice_rot_new = I * omega[i].squaredNorm();
      sums.kinetic_centred += I * w_old.dot(omega[i]);
      sums.damping_loss += dt * t.dot(w_old + omega[i]) - (twice_rot_new - I * w_old.squaredNorm());
    }
    return ok;
  }

  // Gathers and moves the particles [begin, end) one by one; false if one could not be wrapped.
  bool move(std::size_t begin, std::size_t end, MotionSums& sums) const {
    bool ok = true;
    for (std::size_t i = begin; i < end; ++i) {
      Vec3 f, t;
      gather(i, f, t);
      ok &= update(i, f, t, sums);
    }
    return ok;
  }
};

// Adds the chunk sums in chunk order and halves them; kinetic_half_step is NaN if not `wrapped`.
MotionSums total_of_chunks(const std::vector<MotionSums>& chunk_sums, bool wrapped);

// One step's contact forces and leapfrog update, `simd_lanes` (0, 4 or 8; see
// dynamics/kernel_simd.hpp) pairs at a time, the same result bit for bit at any width, in one
// sweep over the chunks (sweep_chunks).
//
// Forces: at the current positions, with the velocities of the previous half step; the relative
// velocity at a contact includes the affine part -G l of the deforming cell. `sums` receives the
// contact stress and the servo stiffness; `history` is updated.
//
// Update: velocities and fractional positions, with the net force and torque of each particle
// gathered from the pair forces in pair order (the order a serial scatter would use). `force`
// receives the net forces. Returns the kinetic energies and the energy the damping took in this
// step (see MotionSums); kinetic_half_step is NaN if a particle moved by more than a cell in one
// step (the run is unstable; positions can no longer be trusted).
//
// The damping loss needs no knowledge of the damping form: over one step a particle's kinetic
// energy changes by exactly dt (F + F_damping).v_mid with v_mid = (v_old + v_new) / 2 (the
// leapfrog update is m (v_new - v_old) = dt (F + F_damping)), so the damping took
// dt F.v_mid - (1/2 m v_new^2 - 1/2 m v_old^2).
//
// Instantiated for every law of AnyContactLaw, both damping forms, orthorhombic and sheared
// (dynamics/kernel_simd.cpp).
//
// Laws with contact dashpots, `previous.book`: the loop also books the second half of the
// evaluation before's dashpot work (PairLoop::DashpotOut), into out.previous_dashpot_sums: added
// in chunk order, the same bits as dashpot_second_half would have given after that step.
template <class Law, class DampingPolicy, bool Sheared>
MotionSums forces_and_motion(int simd_lanes, const Law& law, const DampingPolicy& damping, Particles& p,
                             const PeriodicCell& cell, const PairList& pairs, ContactHistory& history,
                             const PairIndex& index, const CellRates& rates, double dt, PairForces& out,
                             StepSums& sums, std::vector<Vec3>& force, const PreviousHalf& previous = {});

// What the second half of the contact dashpots' work reads (dashpot_second_half), as raw pointers.
struct DashpotWork {
  ComponentsAt<const double> force;  // PairForces::dashpot_force
  const double* __restrict distance;  // PairForces::dashpot_distance
  const std::uint32_t* __restrict first;
  const std::uint32_t* __restrict second;
  const Vec3* __restrict s;
  const double* __restrict radius;
  const Vec3* __restrict v;
  const Vec3* __restrict omega;
  Vec3 lengths, tilts;  // the cell of the coming evaluation (PeriodicCell)
  Vec3 axial, shear;    // the cell's rates of the coming step (CellRates)
  Mat3 back;            // PreviousHalf::back
  double dt;
};

// Laws with contact dashpots: the second half of their work in the step just taken [J]. The
// dashpots take dt F_d . u_mid in a step: F_d their force at this evaluation (on `second`, normal
// and tangential), u_mid the relative velocity of the contact point at the mean of the half steps
// before and after it, u = v_j - v_i - G l - (a_i w_i + a_j w_j) x n (the affine part with the
// velocity gradient of the coming step, as the next evaluation's closing speed takes it). That is
// the work the time-centred kinetic energy sees: the leapfrog changes 1/2 m v(n-1/2).v(n+1/2) by
// dt v(n-1/2).(F_n + F_(n-1))/2, i.e. by dt F_n.(v(n-1/2) + v(n+1/2))/2 summed over the steps.
// The pair loop books the half with v(n-1/2); this is the half with v(n+1/2), from the forces it
// stored and this evaluation's branch vector l rebuilt from the positions now (PreviousHalf),
// its lever arms over |l| from the centre distance it stored, `simd_lanes` pairs at a time (the
// same bits at any width: each pair's term is subtracted from its chunk's sum in pair order, the
// chunks' sums added in chunk order, the pair chunks of the step's sweep: so the next step's pair loop can book it instead,
// with the same bits, while it has the velocities in hand; forces_and_motion). Booking
// dt F_d . u(n-1/2) alone leaves c dt/4 (u_end^2 - u_start^2) open per contact, an O(dt) closure
// error; with both halves what is left is the leapfrog's O(dt^2) (energy_balance_test.cpp), which
// the arms of the next evaluation instead of this one's would spoil with an O(|w| dt) error
// (docs/performance.md). Instantiated for the laws with dashpots (dynamics/kernel_simd_dashpot.cpp).
template <class Law>
double dashpot_second_half(int simd_lanes, const Particles& p, const PeriodicCell& cell, const PairList& pairs, const PairIndex& index,
                           const PairForces& out, const CellRates& rates, const Mat3& back, double dt);

}  // namespace dem
