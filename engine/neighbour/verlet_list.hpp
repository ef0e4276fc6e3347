#pragma once
// Candidate contact pairs: a Verlet list with a skin, built from bins in fractional coordinates.
//
// The list holds every pair (i < j) whose surfaces were closer than `skin` at build time, sorted by
// (i, j). Forces are summed in that order, in chunks by particle (dynamics/kernel.hpp), so results
// do not depend, to the last bit, on when the list was rebuilt or on the skin (tests/.../skin_test).
// The contact history lives in its own store (contact/contact_history.hpp); a rebuild tells where
// each new pair was in the old list (`from_previous`) so that the history of surviving pairs is
// carried over.
//
// Rebuild criterion (`needs_rebuild`): a pair outside the list at build time had a surface gap
// > skin. Its gap can close only through its two particles' own displacements (at most d_1 + d_2,
// the two largest displacements of any particles, measured relative to the deforming cell: the
// two of a pair are two different particles) and through the cell's contraction (at most
// (2 r_max + skin)(1 - lambda_min), lambda_min the smallest L/L_build; for a tilted cell the
// smallest singular value of H H_build^-1). We rebuild before the sum of the two can exceed the
// skin. (2 d_1 instead of d_1 + d_2 rebuilt up to twice as often where a few rattlers move
// fastest: docs/performance.md.)
//
// That criterion costs a pass over every particle. The step calls `rebuild_due` instead, which
// first screens with a bound that costs nothing per particle: the fluctuating displacement of any
// particle since the last exact measurement is at most its displacement then plus the sum over
// steps of dt max_i |v_i| (told by `add_motion`), times the largest stretch L/L_min of a cell
// side since then (for a tilted cell: the largest singular value of H over the smallest one of
// any H since); so d_1 + d_2 is at most that stretch times (d_1 + d_2 then + twice the motion).
// Only when that bound cannot rule a rebuild out does it run the exact criterion, whose measured
// displacements restart the bound. The list is therefore rebuilt at exactly the steps where the
// exact criterion alone would rebuild it.
#include <cstdint>
#include <limits>
#include <vector>

#include "cell/periodic_cell.hpp"
#include "contact/contact_history.hpp"
#include "core/particles.hpp"

namespace dem {

struct PairList {
  std::vector<std::uint32_t> first, second;  // particle indices, first < second, sorted
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
  explicit VerletList(double skin_m) : skin_(skin_m) {}

  double skin() const { return skin_; }
  const PairList& pairs() const { return pairs_; }
  // How many times the pairs were replaced (build, restore, restore_exact): what a per-pair value
  // computed from the pair list alone is kept against (the contact dashpots' coefficients).
  std::uint64_t changes() const { return changes_; }
  const PairIndex& index() const { return index_; }
  std::size_t builds() const { return builds_; }

  // The exact rebuild criterion (a pass over every particle).
  bool needs_rebuild(const Particles& p, const PeriodicCell& cell) const;
  // The same decision, the exact criterion run only when the displacement bound does not rule a
  // rebuild out (see above); call once per step, before the forces.
  bool rebuild_due(const Particles& p, const PeriodicCell& cell);
  // After a position update: the largest distance any particle moved relative to the cell, dt max |v| [m].
  void add_motion(double max_step_m) { drift_m_ += 2 * max_step_m; }
  std::size_t exact_checks() const { return exact_checks_; }  // passes of the exact criterion so far
  // Replaces the pairs, e.g. with the contacts of a saved state; the next build() tells where they went.
  void restore(PairList pairs) {
    pairs_ = std::move(pairs);
    ++changes_;
    built_ = false;
  }
  // Asks for a rebuild at the next step (after the cell was re-mapped: the same pairs, but every
  // fractional position moved); the history is carried over by the build as usual.
  void invalidate() { built_ = false; }
  // Rebuilds the list, and carries `history` (one entry per pair) over to the new pairs; throws
  // std::runtime_error if the cell is too small for the minimum image. If it throws (that, or an
  // allocation), the list and the history are left as they were.
  void build(const Particles& p, const PeriodicCell& cell, ContactHistory* history = nullptr);
  // After build(): for each pair, its index in the list before the build, or ContactHistory::none
  // (empty if build() was given a history that keeps nothing).
  const std::vector<std::uint32_t>& from_previous() const { return from_previous_; }

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
    Vec3 tilts_at_build = Vec3::Zero();
  };
  Saved saved() const { return {pairs_, s_at_build_, cell_at_build_.lengths(), builds_, cell_at_build_.tilts()}; }
  void restore_exact(Saved saved, const Particles& p);

 private:
  void collect_pairs(const Particles& p, const PeriodicCell& cell, PairList& out) const;
  // d_1 + d_2, the sum of the two largest displacements since the build [m]: what the particles'
  // own motion can close of any pair's gap.
  double displacement_closing(const Particles& p, const PeriodicCell& cell) const;
  double affine_closing(const PeriodicCell& cell) const;  // [m]
  // The exact criterion, shared by needs_rebuild and rebuild_due so that both decide alike.
  bool beyond_skin(double closing, double affine) const { return closing + affine > skin_; }

  double skin_ = 0;
  PairList pairs_;
  std::vector<std::uint32_t> from_previous_;
  PairIndex index_;
  std::vector<Vec3> s_at_build_;
  PeriodicCell cell_at_build_;
  double max_radius_ = 0;
  std::size_t builds_ = 0;
  std::uint64_t changes_ = 0;
  bool built_ = false;
  // The displacement bound of `rebuild_due`: d_1 + d_2 at the last exact measurement plus twice
  // the motion since, and the shortest cell sides since then. Infinite until the first measurement.
  double drift_m_ = std::numeric_limits<double>::infinity();
  Vec3 lengths_min_ = Vec3::Ones();
  double smallest_singular_value_ = 0;  // of any H since the last measurement (tilted cells)
  std::size_t exact_checks_ = 0;
};

}  // namespace dem
