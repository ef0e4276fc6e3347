#pragma once
// The contact-force loop (`forces_and_motion`, dynamics/kernel.hpp) one pair, four (AVX2) or eight
// (AVX-512) pairs at a time, and the damped leapfrog update four particles at a time (AVX2), with
// the same result bit for bit as one pair and one particle at a time (ParticleLoop::move):
//  - every lane does the scalar code's operations in the scalar code's order (no fused
//    multiply-add, the same association in every sum, the same branches as masks);
//  - the chunk sums are added item by item in order, as the scalar loops add them;
//  - the pairs and particles left over after the last full block go through the scalar code.
// tests/engine/dynamics/kernel_simd_test.cpp compares both ways on compressing packings.
#include "dynamics/kernel.hpp"

namespace dem {

// The widest vector loops this CPU can run, in doubles per operation: 8 (AVX-512), 4 (AVX2) or
// 0 (none; checked once).
int simd_width_available();
// The width new Simulations use: the available one, capped by cap_simd_width() or by the
// environment variable DEM_SIMD (0: the scalar loops; 4: at most AVX2), to compare the loops or to
// rule one out. `lanes`: 0, 4 or 8.
int simd_width();
void cap_simd_width(int lanes);

}  // namespace dem
