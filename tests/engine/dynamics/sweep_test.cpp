// The step's order over the chunks (dynamics/kernel.hpp, sweep_chunks): a chunk of particles may
// move only once every pair chunk that holds one of its pairs is done, and a pair chunk must never
// read a particle that has already moved. Exact results alone would not show a violation reliably
// (a race can come out right), so this test records when each body ran and checks the order for
// every pair, on 1, 2 and 3 threads. Pair chunk 0 is made slow, so that moving a chunk that shares
// pairs with chunk 0 before it is done would be caught whatever the threads' timing.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include <omp.h>

#include "dynamics/kernel.hpp"

using namespace dem;

namespace {

std::size_t chunk_of(std::size_t particle) { return particle / static_cast<std::size_t>(chunk_size); }

// Pairs sorted by (first, second): each particle with its next two, a chunk-0 particle with one
// in the last chunk (as across the periodic wrap of a spatially sorted order), and one with the
// middle of the packing.
PairList pairs_of(std::size_t n) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> v;
  for (std::uint32_t i = 0; i + 2 < n; ++i) v.emplace_back(i, i + 1), v.emplace_back(i, i + 2);
  v.emplace_back(static_cast<std::uint32_t>(n - 2), static_cast<std::uint32_t>(n - 1));
  v.emplace_back(3, static_cast<std::uint32_t>(n - 5));
  v.emplace_back(7, static_cast<std::uint32_t>(n / 2));
  std::sort(v.begin(), v.end());
  PairList p;
  for (auto [a, b] : v) p.first.push_back(a), p.second.push_back(b);
  return p;
}

}  // namespace

TEST_CASE("one-sweep step: chunks move after all their pairs and before no pair that reads them", "[dynamics][threads]") {
  const std::size_t n = 7 * static_cast<std::size_t>(chunk_size) - 100;  // 7 chunks, the last one short
  const PairList pairs = pairs_of(n);
  PairIndex index;
  index.build(pairs, n);
  const std::size_t chunks = static_cast<std::size_t>(chunk_count(n));

  for (int threads : {1, 2, 3}) {
    INFO(threads << " threads");
    std::atomic<long> clock{0};
    std::vector<long> pairs_done(chunks, -1), move_start(chunks, -1);
    std::vector<int> pair_calls(chunks, 0), move_calls(chunks, 0);
    std::vector<std::size_t> pair_range_ok(chunks, 0);
    std::atomic<int> told_serial{0}, told_parallel{0};  // calls told the sweep runs on one thread, on more
    omp_set_num_threads(threads);
    const bool all = sweep_chunks(
        index,
        [&](std::size_t c, std::size_t begin, std::size_t end, bool serial) {
          ++(serial ? told_serial : told_parallel);
          if (c == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
          pair_range_ok[c] = begin == index.first_begin[c * chunk_size] &&
                             end == index.first_begin[std::min(n, (c + 1) * chunk_size)];
          ++pair_calls[c];
          pairs_done[c] = clock++;
        },
        [&](std::size_t c, std::size_t begin, std::size_t end, bool serial) {
          ++(serial ? told_serial : told_parallel);
          move_start[c] = clock++;
          ++move_calls[c];
          return begin == c * chunk_size && end == std::min(n, begin + chunk_size);
        });
    omp_set_num_threads(1);
    CHECK(all);
    // Only a sweep on one thread may let the pairs add into the particles' sums (PairForces).
    CHECK(told_serial == (threads == 1 ? 2 * static_cast<int>(chunks) : 0));
    CHECK(told_parallel == (threads == 1 ? 0 : 2 * static_cast<int>(chunks)));
    for (std::size_t c = 0; c < chunks; ++c) {
      CHECK(pair_calls[c] == 1);
      CHECK(move_calls[c] == 1);
      CHECK(pair_range_ok[c]);
    }
    std::size_t wrong = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::size_t c = chunk_of(pairs.first[k]);  // the pair chunk holding pair k
      wrong += move_start[chunk_of(pairs.first[k])] < pairs_done[c];
      wrong += move_start[chunk_of(pairs.second[k])] < pairs_done[c];
    }
    CHECK(wrong == 0);
  }
}
