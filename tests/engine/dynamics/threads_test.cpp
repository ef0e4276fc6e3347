// Threads inside a run (OpenMP) must not change a single bit of the result.
//
// Why exact equality is the right expectation: pair forces are computed per pair (no shared
// writes) and gathered per particle in pair order (on one thread, a frictionless law adds them
// into the particles' sums in the same order instead); sums (stress, stiffness, kinetic energy) are
// formed over chunks of a fixed size, independent of the thread count, and the chunk sums are
// added in chunk order. So 1 and 2 threads perform the same floating-point operations in the same
// order. A 1,000-sphere packing has 2 particle chunks and about 7 pair chunks, so 2 threads do
// split the work.
#include <catch2/catch.hpp>

#include "engine/dynamics/packing_support.hpp"

using namespace dem;
using namespace dem::test;

// One test case (not two), so that ctest never runs two 2-thread cases at once on 2 cores.
TEST_CASE("1 and 2 threads give bit-for-bit the same run", "[threads]") {
  SECTION("frictional") {
    const Simulation one = compressed(0.5, 1, 12000);
    const Simulation two = compressed(0.5, 2, 12000);
    std::size_t sliding = 0;
    for (auto f : one.history().sliding) sliding += f;
    REQUIRE(sliding > 0);  // the Coulomb branch ran
    require_identical(one, two);
  }
  SECTION("frictionless") { require_identical(compressed(0.0, 1, 12000), compressed(0.0, 2, 12000)); }
  // A run on several threads changes its count between steps (run/thread_choice.hpp): spells of
  // 1 and 2 threads of 1 to 600 steps, frictional (the pairs store their forces on 2 threads) and
  // frictionless (on 1 thread a law without torques adds them straight into the particles' sums,
  // which the update leaves at zero for a step on 2 threads).
  SECTION("the count changed between steps") {
    const auto spells = [](int i) {
      const int period[] = {1, 2, 7, 600};
      return (i / period[(i / 1000) % 4]) % 2 == 0 ? 2 : 1;
    };
    for (const double friction : {0.5, 0.0}) {
      INFO("friction " << friction);
      require_identical(compressed(friction, 1, 8000), compressed(friction, 1, 8000, 10, "", spells));
    }
  }
  // Every law a scene can choose (packing_support.hpp, every_law()): 4,000 steps of 1,000 spheres,
  // contacts forming, sliding at the Coulomb cap and rolling springs at theirs (both required).
  SECTION("every contact law") {
    for (const LawScene& law : every_law()) {
      INFO("law " << law.name);
      const LawRun one = compressed_law(law, 1, 4000), two = compressed_law(law, 2, 4000);
      INFO("contacts " << one.sim.sums().contacts << ", sliding " << one.sliding << ", rolling springs at the cap "
                       << one.rolling_at_cap);
      if (has_tangential(one.sim.material().law)) REQUIRE(one.sliding > 0);
      if (has_rolling(one.sim.material().law)) REQUIRE(one.rolling_at_cap > 0);
      require_identical(one.sim, two.sim);
      REQUIRE(one.sim.energy().dissipated_friction == two.sim.energy().dissipated_friction);
      REQUIRE(one.sim.energy().dissipated_rolling == two.sim.energy().dissipated_rolling);
      REQUIRE(one.sim.energy().dissipated_damping == two.sim.energy().dissipated_damping);
      REQUIRE(one.sim.energy().elastic == two.sim.energy().elastic);
    }
  }
}
