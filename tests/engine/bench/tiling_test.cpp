// Tiled and reordered packings for `dem-bench size` (engine/bench/tiling.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "analysis/measurements.hpp"
#include "bench/tiling.hpp"
#include "engine/dynamics/packing_support.hpp"
#include "engine/test_support.hpp"

using namespace dem;
using namespace dem::test;

namespace {

// The saved state of a simulation as `write_state` keeps it: the pairs in contact with their springs.
SavedState state_of(const Simulation& sim) {
  SavedState st;
  st.particles = sim.particles();
  st.cell = sim.cell();
  st.rates = sim.rates();
  st.time_step_s = sim.time_step();
  st.history.tangential_name = sim.history().tangential_name;
  for (const auto& [i, j, spring, sliding, rolling] : touching(sim)) {
    st.contacts.first.push_back(i);
    st.contacts.second.push_back(j);
    if (st.history.has_tangential()) {
      st.history.tangential.push_back(spring);
      st.history.sliding.push_back(static_cast<std::uint8_t>(sliding));
      (void)rolling;  // the tiled packings have no rolling resistance
    }
  }
  return st;
}

// A simulation started from `st` with the material of `like`, as build_simulation starts one from
// a saved state.
Simulation from_state(SavedState st, const Simulation& like) {
  Simulation sim(std::move(st.particles), st.cell, like.material(), like.damping(), like.time_step(),
                 like.verlet_list().skin());
  sim.restore(0, st.rates, std::move(st.contacts), st.history);
  return sim;
}

// One step at a fixed cell: the forces of the first evaluation (the list is built from the
// restored contacts, carrying their springs) are then in net_force().
void one_step(Simulation& sim) { sim.step(fixed_cell(), ServoSettings{}); }

// 216 spheres compressed with friction to ~100 kPa: several hundred contacts, loaded springs.
const Simulation& packing() {
  static const Simulation sim = compressed(0.5, 1, 12000, 6);
  return sim;
}

}  // namespace

TEST_CASE("tiling: n x n x n copies have n^3 times the particles and contacts and the same stress and forces",
          "[bench][tiling]") {
  const Simulation& sim = packing();
  const SavedState base = state_of(sim);
  const ContactCounts c1 = count_contacts(from_state(base, sim));
  const double p = mean_stress(c1.stress_Pa);
  REQUIRE(base.contacts.size() > 300);
  REQUIRE(p > 5e4);
  std::size_t loaded = 0;
  for (const Vec3& u : base.history.tangential) loaded += u.squaredNorm() > 0;
  REQUIRE(loaded > 100);  // the springs carry force: their copies and signs are checked below

  // Tolerances. A copied contact gives the same force and branch vector as its original to the
  // last bit or to round-off of the positions ((s + a)/n rounds, then min_image and * L), i.e. a
  // relative 1e-15; the stress then sums n^3 times as many such terms (at most ~20,000 here), so
  // its round-off is below 20,000 * 2^-53 ~ 2e-12 of the sum of their magnitudes, itself a few p.
  // One contact's share of the stress is ~p / Nc ~ 1e-3 p, and a wrong copy (a spring with the
  // wrong sign, a partner in the wrong tile) moves the stress or a force by that order, so 1e-9
  // separates round-off from any such error by orders of magnitude on both sides.
  for (int n : {2, 3}) {
    const SavedState tiled = bench::tile(base, n);
    const std::size_t n3 = static_cast<std::size_t>(n * n * n);
    REQUIRE(tiled.particles.size() == n3 * base.particles.size());
    REQUIRE(tiled.contacts.size() == n3 * base.contacts.size());
    REQUIRE(tiled.cell.lengths() == base.cell.lengths() * n);
    for (std::size_t k = 1; k < tiled.contacts.size(); ++k)
      REQUIRE(std::make_pair(tiled.contacts.first[k - 1], tiled.contacts.second[k - 1]) <
              std::make_pair(tiled.contacts.first[k], tiled.contacts.second[k]));

    // count_contacts recounts overlaps from the positions: every listed copy touches.
    const ContactCounts cn = count_contacts(from_state(tiled, sim));
    REQUIRE(cn.contacts == n3 * c1.contacts);
    REQUIRE(cn.sliding == n3 * c1.sliding);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) REQUIRE(std::abs(cn.stress_Pa(a, b) - c1.stress_Pa(a, b)) <= 1e-9 * p);

    // One step on each: every copy of particle i feels the force particle i feels.
    Simulation one = from_state(base, sim), many = from_state(tiled, sim);
    one_step(one);
    one_step(many);
    const double fn_mean = one.sums().sum_normal_force_N / static_cast<double>(one.sums().contacts);
    double worst = 0;
    for (std::size_t t = 0; t < n3; ++t)
      for (std::size_t i = 0; i < base.particles.size(); ++i)
        worst = std::max(worst, (many.net_force()[t * base.particles.size() + i] - one.net_force()[i]).norm());
    REQUIRE(worst <= 1e-9 * fn_mean);
    REQUIRE(many.sums().contacts == n3 * one.sums().contacts);
  }
}

TEST_CASE("tiling: n = 1 is the packing itself, bit for bit", "[bench][tiling]") {
  const SavedState base = state_of(packing());
  const SavedState same = bench::tile(base, 1);
  REQUIRE(same.particles.s == base.particles.s);
  REQUIRE(same.cell.lengths() == base.cell.lengths());
  REQUIRE(same.contacts.first == base.contacts.first);
  REQUIRE(same.contacts.second == base.contacts.second);
  REQUIRE(same.history.tangential == base.history.tangential);
  REQUIRE_THROWS_AS(bench::tile(base, 0), std::invalid_argument);
}

TEST_CASE("tiling: a spatial reordering keeps the packing: the same contacts, forces and stress", "[bench][tiling]") {
  const Simulation& sim = packing();
  const SavedState tiled = bench::tile(state_of(sim), 3);
  const std::vector<std::uint32_t> order = bench::spatial_order(tiled.particles, tiled.cell);
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint32_t> all(order.size());
  std::iota(all.begin(), all.end(), 0U);
  REQUIRE(sorted == all);  // a permutation

  const SavedState moved = bench::reordered(tiled, order);
  REQUIRE(moved.contacts.size() == tiled.contacts.size());
  for (std::size_t k = 0; k < order.size(); ++k) REQUIRE(moved.particles.s[k] == tiled.particles.s[order[k]]);
  // The same contacts, forces and stress (to round-off: the sums run in another order; see above).
  Simulation a = from_state(tiled, sim), b = from_state(moved, sim);
  one_step(a);
  one_step(b);
  REQUIRE(b.sums().contacts == a.sums().contacts);
  const double fn_mean = a.sums().sum_normal_force_N / static_cast<double>(a.sums().contacts);
  for (std::size_t k = 0; k < order.size(); ++k) REQUIRE((b.net_force()[k] - a.net_force()[order[k]]).norm() <= 1e-9 * fn_mean);
  const double p = mean_stress(a.sums().stress_Pa);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) REQUIRE(std::abs(b.sums().stress_Pa(r, c) - a.sums().stress_Pa(r, c)) <= 1e-9 * p);

  std::vector<std::uint32_t> twice(order.size(), 0);
  REQUIRE_THROWS_AS(bench::reordered(tiled, twice), std::invalid_argument);
}
