#pragma once
// Candidate contact pairs: a Verlet list with a skin, built from bins in fractional coordinates.
//
// The list holds every pair (i < j) whose surfaces were closer than `skin` at build time, sorted by
// (i, j). Forces are summed in that order, in chunks by particle (dynamics/kernel.hpp), so results
// do not depend, to the last bit, on when the list was rebuilt or on the skin (tests/.../skin_test).
// Each pair owns its contact history (tangential spring, sliding flag); a rebuild carries the
// history of surviving pairs over.
//
// Rebuild criterion (`needs_rebuild`): a pair outside the list at build time had a surface gap
// > skin. Its gap can close only through the particles' own displacement (at most 2 d_max, d_max
// measured relative to the deforming cell) and through the cell's contraction (at most
// (2 r_max + skin)(1 - lambda_min), lambda_min the smallest L/L_build). We rebuild before the sum
// of the two can exceed the skin.
#include <cstdint>
#include <vector>

#include "cell/periodic_cell.hpp"
#include "core/particles.hpp"

namespace dem {

struct PairList {
  std::vector<std::uint32_t> first, second;  // particle indices, first < second, sorted
  std::vector<Vec3> spring;                  // elastic tangential displacement [m] (frictional scenes only)
  std::vector<std::uint8_t> sliding;         // 1 if the contact slid at the last force evaluation (frictional only)
  std::size_t size() const { return first.size(); }
};

// For each particle, the pairs it belongs to, so that pair forces can be gathered per particle in
// pair order (the same order as a serial scatter, whatever the number of threads): the pairs where
// it is `second` (listed in `second_pairs`, ascending), then those where it is `first` (a contiguous
// range of the sorted list).
struct PairIndex {
  std::vector<std::uint32_t> first_begin;   // pairs first_begin[i] .. first_begin[i+1]-1 have first == i
  std::vector<std::uint32_t> second_begin;  // second_pairs[second_begin[i] .. second_begin[i+1]-1]
  std::vector<std::uint32_t> second_pairs;  // pair indices with second == i, ascending
  void build(const PairList& pairs, std::size_t particles);
};

class VerletList {
 public:
  VerletList() = default;
  VerletList(double skin_m, bool keep_history) : skin_(skin_m), keep_history_(keep_history) {}

  double skin() const { return skin_; }
  const PairList& pairs() const { return pairs_; }
  PairList& pairs() { return pairs_; }
  const PairIndex& index() const { return index_; }
  std::size_t builds() const { return builds_; }

  bool needs_rebuild(const Particles& p, const PeriodicCell& cell) const;
  // Replaces the pairs, e.g. with contacts and springs loaded from a saved state; the next build()
  // keeps their history.
  void restore(PairList pairs) {
    pairs_ = std::move(pairs);
    if (keep_history_ && pairs_.spring.size() != pairs_.size()) {  // history-less pairs start unloaded
      pairs_.spring.assign(pairs_.size(), Vec3::Zero());
      pairs_.sliding.assign(pairs_.size(), 0);
    }
    built_ = false;
  }
  // Rebuilds the list; throws std::runtime_error if the cell is too small for the minimum image.
  void build(const Particles& p, const PeriodicCell& cell);

  // Everything a checkpoint needs to continue bit for bit: the whole list (pairs out of contact
  // too: the rebuild criterion relies on every pair within the skin at the last build being
  // listed) and what that criterion compares with, so that the list is rebuilt at the same steps
  // as in an uninterrupted run.
  // Checkpoints are taken after a step, so the saved list is always a built one.
  struct Saved {
    PairList pairs;
    std::vector<Vec3> s_at_build;
    Vec3 lengths_at_build = Vec3::Ones();
    std::size_t builds = 0;
  };
  Saved saved() const { return {pairs_, s_at_build_, lengths_at_build_, builds_}; }
  void restore_exact(Saved saved, const Particles& p);

 private:
  void collect_pairs(const Particles& p, const PeriodicCell& cell, PairList& out) const;

  double skin_ = 0;
  bool keep_history_ = false;
  PairList pairs_;
  PairIndex index_;
  std::vector<Vec3> s_at_build_;
  Vec3 lengths_at_build_ = Vec3::Ones();
  double max_radius_ = 0;
  std::size_t builds_ = 0;
  bool built_ = false;
};

}  // namespace dem
