#pragma once
// Work on particles and pairs is split into chunks of a fixed number of particles, independent of
// the number of threads: sums are formed per chunk in index order and the chunk sums are added in
// chunk order, so every result is bit-for-bit the same on 1 or N threads (dynamics/kernel.hpp).
#include <cstddef>

namespace dem {

inline constexpr std::ptrdiff_t chunk_size = 512;
inline std::ptrdiff_t chunk_count(std::size_t n) { return (static_cast<std::ptrdiff_t>(n) + chunk_size - 1) / chunk_size; }

}  // namespace dem
