#pragma once
// The contact-force loop four pairs at a time and the viscous-damping update four particles at a
// time (x86-64 AVX2), with the same result bit for bit as `compute_forces` and `integrate`
// (dynamics/kernel.hpp):
//  - every lane does the scalar code's operations in the scalar code's order (no fused
//    multiply-add, the same association in every sum, the same branches as masks);
//  - the chunk sums are added item by item in order, as the scalar loops add them;
//  - the pairs and particles left over after the last block of four go through the scalar code.
// tests/engine/dynamics/kernel_simd_test.cpp compares both ways on compressing packings.
#include "dynamics/kernel.hpp"

namespace dem {

// True if this CPU can run the vectorised loops (checked once).
bool simd_available();
// Whether new Simulations use them: if available, unless switched off here or by the environment
// variable DEM_SIMD=0 (to compare with the scalar loops, or to rule the vectorised ones out).
bool simd_enabled();
void enable_simd(bool on);

// As `compute_forces`; call only if simd_available().
template <class Friction>
void compute_forces_simd(const LinearSpring<Friction>& law, const Particles& p, const PeriodicCell& cell,
                         PairList& pairs, const Vec3& strain_rate, double dt, PairForces& out, StepSums& sums);

// As `integrate` with viscous damping (the vectorised leapfrog update, four particles at a time);
// call only if simd_available().
template <bool Rotate>
MotionSums integrate_simd(const ViscousDamping& damping, Particles& p, const PeriodicCell& cell, const PairIndex& index,
                          PairForces& pf, std::vector<Vec3>& force, double dt);

}  // namespace dem
