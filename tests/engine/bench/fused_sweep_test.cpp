// The fused-sweep experiment of `dem-bench fused` (engine/bench/fused_sweep.hpp) must time the
// same step as the engine's two passes: the same state bit for bit.
#include <catch2/catch.hpp>

#include "bench/fused_sweep.hpp"
#include "bench/tiling.hpp"
#include "engine/dynamics/packing_support.hpp"

using namespace dem;
using namespace dem::test;

namespace {

SavedState state_of(const Simulation& sim) {
  SavedState st;
  st.particles = sim.particles();
  st.cell = sim.cell();
  for (const auto& [i, j, spring, sliding] : touching(sim)) {
    st.contacts.first.push_back(i);
    st.contacts.second.push_back(j);
    if (sim.material().friction > 0) {
      st.contacts.spring.push_back(spring);
      st.contacts.sliding.push_back(static_cast<std::uint8_t>(sliding));
    }
  }
  return st;
}

}  // namespace

TEST_CASE("fused sweep: one sweep per step gives the two passes' state bit for bit", "[bench][fused]") {
  for (double mu : {0.5, 0.0}) {
    const Simulation sim = compressed(mu, 1, 8000, 6);
    // Tiled 2 x 2 x 2: pairs across the copies' faces join particles far apart in index.
    const SavedState st = bench::tile(state_of(sim), 2);
    bench::StepLoops two(st, sim.material(), sim.damping(), sim.time_step(), sim.verlet_list().skin());
    bench::StepLoops one(st, sim.material(), sim.damping(), sim.time_step(), sim.verlet_list().skin());
    for (int i = 0; i < 300; ++i) {
      two.step_two_passes();
      one.step_fused();
    }
    REQUIRE(sim.sums().contacts > 300);
    REQUIRE(one.particles().s == two.particles().s);
    REQUIRE(one.particles().v == two.particles().v);
    REQUIRE(one.particles().omega == two.particles().omega);
    REQUIRE(one.net_force() == two.net_force());
    REQUIRE(one.particles().v != st.particles.v);  // the particles moved: the steps did something
  }
}
