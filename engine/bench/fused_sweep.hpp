#pragma once
// An experiment for `dem-bench fused`: does one sweep that computes a particle's pair forces and
// moves it at once beat the engine's two passes (all pair forces into per-pair arrays, then a
// gather per particle) on big packings, where the step streams from memory?
//
// Both ways use the engine's own scalar per-pair and per-particle code (dynamics/kernel.hpp:
// PairLoop::pair, ParticleLoop::update), one thread, at a fixed cell (no servo: the cell's rate
// is zero). The fused sweep visits particles in index order; for particle p it evaluates the
// pairs (p, j > p), adds each pair's force and torques to per-particle sums of p and j, and then
// moves p. That is the engine's result bit for bit: a particle's sum receives its pairs in pair
// order, the pairs where it is `second` (evaluated while visiting lower particles) before those
// where it is `first`, which is the order of the engine's gather; and no pair evaluated after p
// moves reads p (its partners are all above it). The pair forces never go to per-pair arrays:
// each particle's few pairs use a small scratch buffer.
//
// The engine's step (dynamics/simulation.cpp, kernel*.{hpp,cpp,inc}) is not changed by this; the
// measurement says what such a change there would be worth (docs/performance.md).
#include <memory>

#include "contact/linear_spring.hpp"
#include "dynamics/simulation.hpp"
#include "io/state_io.hpp"

namespace dem::bench {

class StepLoops {
 public:
  // The packing of `state` with the engine's material, damping, time step and skin; starts
  // without a list (the first step builds it, carrying the springs of `state`'s contacts).
  StepLoops(SavedState state, const Material& material, const Damping& damping, double time_step_s, double skin_m);
  ~StepLoops();
  StepLoops(StepLoops&&) noexcept;

  void step_two_passes();  // the engine's order: forces of every pair, then the update with gathers
  void step_fused();       // one sweep (see above)

  const Particles& particles() const;
  const std::vector<Vec3>& net_force() const;  // from the last step [N]

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace dem::bench
