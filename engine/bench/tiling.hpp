#pragma once
// Bigger packings for `dem-bench size` without a new compression: a periodic packing tiled
// n x n x n is again a periodic packing in equilibrium, with n^3 times the particles and the
// contacts (each with its tangential spring) and the same stress tensor (to round-off).
//
// Particle order matters for speed (cache misses), not for the physics: `tile` keeps the copies
// tile by tile (tile (a, b, c) holds particles (a n^2 + b n + c) N .. + N - 1, each tile in the
// original order), and `reordered` with `spatial_order` puts the whole packing in one Morton
// (Z-order) curve over bins of about one diameter.
#include <cstdint>
#include <vector>

#include "io/state_io.hpp"

namespace dem::bench {

// The packing tiled n x n x n (n >= 1): cell lengths (and reference lengths) times n, particle
// i of tile (a, b, c) at fractional position (s_i + (a, b, c)) / n with the same velocity, spin,
// radius, mass and inertia. Each contact (i, j) of `in` becomes one contact per tile, between the
// copy of i in that tile and the copy of j in the tile holding the periodic image of j nearest to
// i, with the same spring (negated when the copy of j gets the lower index, as the spring is j's
// displacement relative to i); contacts sorted by (first, second). n = 1 returns `in` unchanged.
// Throws std::invalid_argument for n < 1 or more than 2^32 - 1 particles.
SavedState tile(const SavedState& in, int n);

// The same packing with its particles renumbered: particle k of the result is particle
// order[k] of `in` (order a permutation of 0 .. N-1); contacts renumbered, oriented and sorted
// as in `tile`. Throws std::invalid_argument if `order` is not a permutation.
SavedState reordered(const SavedState& in, const std::vector<std::uint32_t>& order);

// The particles in the order of a Morton (Z-order) curve over bins of about one mean diameter
// (ties by index): neighbours in space are mostly close in index, at every size.
std::vector<std::uint32_t> spatial_order(const Particles& p, const PeriodicCell& cell);

}  // namespace dem::bench
