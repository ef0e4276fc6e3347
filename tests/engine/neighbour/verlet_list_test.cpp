// Verlet list (neighbour/verlet_list.hpp): completeness under the rebuild criterion for a moving,
// compressing gas, exactness of a rebuild, and the carry-over of contact history.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "engine/test_support.hpp"
#include "generate/grading.hpp"
#include "neighbour/verlet_list.hpp"

using namespace dem;

namespace {

using PairVec = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// All pairs (i < j, sorted) whose surface gap is below `gap`, by brute force over all pairs.
PairVec brute_force_pairs(const Particles& p, const PeriodicCell& cell, double gap) {
  PairVec out;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      const double cut = p.radius[i] + p.radius[j] + gap;
      if (cell.branch(p.s[i], p.s[j]).squaredNorm() < cut * cut) out.emplace_back(i, j);
    }
  return out;
}

PairVec list_pairs(const PairList& l) {
  PairVec out;
  for (std::size_t k = 0; k < l.size(); ++k) out.emplace_back(l.first[k], l.second[k]);
  return out;
}

// `count` non-overlapping spheres (d = 1.6 to 2.4 mm) at random places in `cell`, each velocity
// component normal with standard deviation `speed` [m/s].
Particles random_gas(const PeriodicCell& cell, std::size_t count, double speed, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, speed);
  Particles p;
  while (p.size() < count) {
    const double r = 1e-3 * (0.8 + 0.4 * uniform01(rng));
    const Vec3 s(uniform01(rng), uniform01(rng), uniform01(rng));
    bool free = true;
    for (std::size_t j = 0; j < p.size() && free; ++j) free = cell.branch(s, p.s[j]).norm() > r + p.radius[j];
    if (free) {
      p.add(s, r, 2650);
      p.v.back() = Vec3(g(rng), g(rng), g(rng));
    }
  }
  return p;
}

}  // namespace

TEST_CASE("Verlet list: never misses a contact in a compressing random gas", "[neighbour][verlet]") {
  // 150 spheres (d = 1.6 to 2.4 mm) in a 15 mm cell with random velocities of ~5 m/s, compressed on
  // x and y and stretched on z. Before every step we check the invariant the force loop relies on:
  // if the rebuild criterion does not fire, every pair in contact is in the list (brute force). If
  // it fires, the rebuilt list must equal the brute-force set of pairs with gap < skin. The check is
  // exact (set comparison), no tolerance.
  const PeriodicCell cell(Vec3(0.015, 0.015, 0.015));
  const Particles p = random_gas(cell, 150, 5.0, 11);
  const double skin = 1e-4;
  Simulation sim(p, cell, test::material(1e5), test::no_damping(), 5e-7, skin);
  CellTargets targets;
  targets[0].strain_rate_per_s = 150;
  targets[1].strain_rate_per_s = 100;
  targets[2].strain_rate_per_s = -30;
  std::size_t contacts_seen = 0, checks_without_rebuild = 0;
  for (int n = 0; n < 3000; ++n) {
    const Particles before = sim.particles();
    const PeriodicCell cell_before = sim.cell();
    const bool due = sim.verlet_list().needs_rebuild(before, cell_before);
    const std::size_t builds = sim.verlet_list().builds();
    const PairVec touching = brute_force_pairs(before, cell_before, 0.0);
    contacts_seen += touching.size();
    if (!due) {
      const PairVec listed = list_pairs(sim.pairs());
      for (const auto& pr : touching) {
        INFO("step " << n << ": pair (" << pr.first << ", " << pr.second << ") in contact but not in the list");
        REQUIRE(std::binary_search(listed.begin(), listed.end(), pr));
      }
      ++checks_without_rebuild;
    }
    sim.step(targets, ServoSettings{});
    REQUIRE(sim.verlet_list().builds() == builds + (due ? 1 : 0));
    if (due) REQUIRE(list_pairs(sim.pairs()) == brute_force_pairs(before, cell_before, skin));
    // Every pair in contact at this force evaluation was counted: the force loop saw all of them.
    REQUIRE(sim.sums().contacts == touching.size());
  }
  // The run did exercise the list: many rebuilds, many steps on an old list, and real contacts.
  INFO("builds " << sim.verlet_list().builds() << ", contact-steps " << contacts_seen);
  REQUIRE(sim.verlet_list().builds() > 50);
  REQUIRE(checks_without_rebuild > 1000);
  REQUIRE(contacts_seen > 500);
  REQUIRE(sim.cell().lengths().x() == Approx(0.015 * std::exp(-150 * 3000 * 5e-7)).epsilon(1e-12));
}

TEST_CASE("Verlet list: the displacement bound rebuilds at the exact criterion's steps and skips its passes",
          "[neighbour][verlet]") {
  // The step decides with rebuild_due (a bound on the displacement first, the exact pass only when
  // the bound cannot rule a rebuild out). Slow spheres (~2 cm/s) in a cell strained at 40/s: over
  // 20,000 steps the exact criterion, evaluated before every step, must fire at exactly the steps
  // where the list is rebuilt, while the step itself ran the exact pass at a minority of steps.
  const PeriodicCell cell(Vec3(0.015, 0.015, 0.015));
  const Particles p = random_gas(cell, 120, 0.02, 5);
  Simulation sim(p, cell, test::material(1e5), test::no_damping(), 1e-6, 5e-5);
  CellTargets targets;
  targets[0].strain_rate_per_s = 40;
  targets[1].strain_rate_per_s = -20;
  const int steps = 20000;
  int exact_due = 0;
  for (int n = 0; n < steps; ++n) {
    const bool due = sim.verlet_list().needs_rebuild(sim.particles(), sim.cell());
    const std::size_t builds = sim.verlet_list().builds();
    sim.step(targets, ServoSettings{});
    INFO("step " << n);
    REQUIRE(sim.verlet_list().builds() == builds + (due ? 1 : 0));
    exact_due += due;
  }
  INFO("builds " << sim.verlet_list().builds() << ", exact passes " << sim.verlet_list().exact_checks());
  REQUIRE(exact_due >= 5);  // the list was rebuilt during the run, not only at the start
  REQUIRE(sim.verlet_list().exact_checks() < static_cast<std::size_t>(steps / 4));
}

TEST_CASE("Verlet list: the affine term of the criterion catches gaps closed by the cell alone", "[neighbour][verlet]") {
  // Two spheres at rest in fractional coordinates (no fluctuating motion, d_max = 0), initially 150 um
  // apart with a 100 um skin, so not in the list. Compressing x at 100/s closes the gap only through
  // the cell; the criterion must rebuild before they touch. Brute-force check before every step.
  const double r = 1e-3, skin = 1e-4;
  const PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(Vec3(0.3, 0.5, 0.5), r, 2650);
  p.add(Vec3(0.3 + (2 * r + 1.5 * skin) / 0.02, 0.5, 0.5), r, 2650);
  Simulation sim(p, cell, test::material(1e5), test::no_damping(), 1e-6, skin);
  CellTargets targets;
  targets[0].strain_rate_per_s = 100;  // the centre distance shrinks by 0.2 um per step
  int touching_steps = 0;
  for (int n = 0; n < 2000 && touching_steps < 5; ++n) {
    const PairVec touching = brute_force_pairs(sim.particles(), sim.cell(), 0.0);
    if (!sim.verlet_list().needs_rebuild(sim.particles(), sim.cell())) {
      const PairVec listed = list_pairs(sim.pairs());
      for (const auto& pr : touching) REQUIRE(std::binary_search(listed.begin(), listed.end(), pr));
    }
    sim.step(targets, ServoSettings{});
    REQUIRE(sim.sums().contacts == touching.size());
    touching_steps += static_cast<int>(touching.size());
  }
  REQUIRE(touching_steps == 5);
  REQUIRE(sim.verlet_list().builds() >= 2);
}

TEST_CASE("Verlet list: a rebuild keeps the history of surviving pairs and only theirs", "[neighbour][verlet]") {
  // Spheres 2-3 stay in contact; 0 moves next to 1 (a new pair that sorts before (2,3), shifting its
  // index); 1-4 separate. History is carried by (i, j), not by index.
  const double r = 1e-3;
  const PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  Particles p;
  p.add(Vec3(0.10, 0.5, 0.5), r, 2650);  // 0
  p.add(Vec3(0.50, 0.2, 0.5), r, 2650);  // 1
  p.add(Vec3(0.50, 0.8, 0.5), r, 2650);  // 2
  p.add(Vec3(0.59, 0.8, 0.5), r, 2650);  // 3: 1.8 mm from 2
  p.add(Vec3(0.59, 0.2, 0.5), r, 2650);  // 4: 1.8 mm from 1
  VerletList list(1e-4);
  list.build(p, cell);
  REQUIRE(list_pairs(list.pairs()) == PairVec{{1, 4}, {2, 3}});
  ContactHistory h{"tangential_spring", true, {}, {}, {}};
  h.reset(list.pairs().size());
  h.tangential[0] = Vec3(0, 0, 3e-6);
  h.tangential[1] = Vec3(0, 1e-6, 2e-6);
  h.sliding[1] = 1;
  h.rolling[1] = Vec3(4e-6, 0, 0);
  p.s[0] = Vec3(0.41, 0.2, 0.5);  // now 1.8 mm from 1
  p.s[4] = Vec3(0.70, 0.2, 0.5);  // now 4 mm from 1
  REQUIRE(list.needs_rebuild(p, cell));
  list.build(p, cell);
  h = h.carried(list.from_previous());
  REQUIRE(list_pairs(list.pairs()) == PairVec{{0, 1}, {2, 3}});
  REQUIRE(list.from_previous() == std::vector<std::uint32_t>{ContactHistory::none, 1});
  REQUIRE(h.tangential[0] == Vec3::Zero());  // new pair: no history
  REQUIRE(h.sliding[0] == 0);
  REQUIRE(h.rolling[0] == Vec3::Zero());
  REQUIRE(h.tangential[1] == Vec3(0, 1e-6, 2e-6));  // surviving pair: kept exactly
  REQUIRE(h.sliding[1] == 1);
  REQUIRE(h.rolling[1] == Vec3(4e-6, 0, 0));
  REQUIRE(list.builds() == 2);
  // Without friction or rolling (a frictionless law) the history keeps nothing at all.
  ContactHistory plain;
  plain.reset(list.pairs().size());
  plain = plain.carried(list.from_previous());
  REQUIRE(plain.tangential.empty());
  REQUIRE(plain.rolling.empty());
}

TEST_CASE("Verlet list: a contact's tangential spring survives rebuilds inside a simulation", "[neighbour][verlet][friction]") {
  // Spheres 0 and 1 overlap by 50 um along x, at rest, with a restored tangential spring u = 2 um
  // along y. At the first force evaluation v = omega = 0, so the tangential force on 1 is exactly
  // -ks u = -0.2 N (below mu f_n = 2.5 N). Afterwards the spring's torque spins both spheres and
  // relaxes u slowly (by ~arm^2 ks t^2 / I = 0.6 % over the run), so the later forces are not a
  // constant; instead we compare with a reference run in which the list is never rebuilt.
  // In the test run sphere 2, far away and never in contact, moves at 2000 m/s (20 um = twice the skin per step; the
  // criterion takes the two largest displacements, and the others' are tiny) so that the list is rebuilt at every step; if history survives rebuilds (and forces are summed in (i, j) order)
  // both runs are identical bit for bit. A lost spring would drop f_t to ~0 at the first rebuild.
  const double r = 1e-3, overlap = 5e-5, ks = 1e5, dt = 1e-8;
  const PeriodicCell cell(Vec3(0.02, 0.02, 0.02));
  const auto run = [&](double speed_of_2, double skin) {
    Particles p;
    p.add(test::fractional(cell, Vec3(0.01 - r + overlap / 2, 0.005, 0.01)), r, 2650);
    p.add(test::fractional(cell, Vec3(0.01 + r - overlap / 2, 0.005, 0.01)), r, 2650);
    p.add(Vec3(0.5, 0.75, 0.5), r, 2650);
    p.v[2] = Vec3(0, 0, speed_of_2);
    Simulation sim(p, cell, test::material(1e5, ks, 0.5), test::no_damping(), dt, skin);
    PairList saved;
    saved.first = {0};
    saved.second = {1};
    ContactHistory history{"tangential_spring", false, {Vec3(0, 2e-6, 0)}, {0}, {}};
    sim.restore(0, CellRates{}, saved, history);
    return sim;
  };
  Simulation moving = run(2000, 1e-5), reference = run(0, 1e-3);
  for (int n = 0; n < 50; ++n) {
    moving.step(test::fixed_cell(), ServoSettings{});
    reference.step(test::fixed_cell(), ServoSettings{});
    REQUIRE(moving.sums().contacts == 1);
    REQUIRE(moving.net_force()[1] == reference.net_force()[1]);
    // Round-off of the normal only (y, z components ~1e-17): 1e-12 relative at n = 0; then within the
    // rolling relaxation (< 1 %).
    if (n == 0) REQUIRE(moving.net_force()[1].y() == Approx(-ks * 2e-6).epsilon(1e-12));
    REQUIRE(moving.net_force()[1].y() == Approx(-ks * 2e-6).epsilon(1e-2));
  }
  REQUIRE(moving.verlet_list().builds() >= 40);
  REQUIRE(reference.verlet_list().builds() == 1);
}
