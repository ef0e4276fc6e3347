#pragma once
// The contact-force loop four pairs at a time (x86-64 AVX2), with the same result bit for bit as
// `compute_forces` (dynamics/kernel.hpp):
//  - every lane does the scalar code's operations in the scalar code's order (no fused
//    multiply-add, the same association in every sum, the same branches as masks);
//  - the chunk sums are added pair by pair in pair order, as the scalar loop adds them;
//  - the pairs left over after the last block of four go through the scalar code.
// tests/engine/dynamics/kernel_simd_test.cpp compares the two on jammed packings.
#include "dynamics/kernel.hpp"

namespace dem {

// True if this CPU can run the vectorised loop (checked once).
bool simd_forces_available();
// Whether new Simulations use it: if available, unless switched off here or by the environment
// variable DEM_SIMD=0 (to compare the two loops, or to rule the vectorised one out).
bool simd_forces_enabled();
void enable_simd_forces(bool on);

// As `compute_forces`; call only if simd_forces_available().
template <class Friction>
void compute_forces_simd(const LinearSpring<Friction>& law, const Particles& p, const PeriodicCell& cell,
                         PairList& pairs, const Vec3& strain_rate, double dt, PairForces& out, StepSums& sums);

// As `integrate` with viscous damping (the vectorised leapfrog update, four particles at a time);
// call only if simd_forces_available().
template <bool Rotate>
MotionSums integrate_simd(const ViscousDamping& damping, Particles& p, const PeriodicCell& cell, const PairIndex& index,
                          PairForces& pf, std::vector<Vec3>& force, double dt);

}  // namespace dem
