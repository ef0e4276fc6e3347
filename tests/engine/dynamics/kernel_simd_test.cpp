// The vectorised force loops (eight pairs per AVX-512 operation, four per AVX2 operation) and
// leapfrog update (four particles) must give the scalar loops' result bit for bit, at every width
// this CPU has.
//
// Why exact equality is the right expectation: each lane performs the scalar code's operations in
// the same order, and IEEE 754 makes every one of them (+, -, *, /, sqrt) correctly rounded, so a
// lane's result is the scalar result; no multiply-add is fused (AVX2 without FMA); branches
// become masks that select the value the branch would have computed; the chunk sums are added
// pair by pair in pair order, the energy sums particle by particle. Any deviation (an Eigen
// reduction in another order, a fused operation, a wrong mask) shows within a few steps of a
// compressing packing, where contacts form, stick, slide and open.
#include <catch2/catch.hpp>

#include <vector>

#include "dynamics/kernel_simd.hpp"
#include "engine/dynamics/packing_support.hpp"

using namespace dem;
using namespace dem::test;

namespace {

Simulation compressed_with(int width, double friction, int steps = 12000, int side = 10) {
  const int saved = simd_width();
  cap_simd_width(width);
  REQUIRE(simd_width() == width);
  Simulation sim = compressed(friction, 1, steps, side);
  cap_simd_width(saved);
  return sim;
}

// The vector widths this CPU can run.
std::vector<int> widths() {
  std::vector<int> out;
  for (int w : {4, 8})
    if (w <= simd_width_available()) out.push_back(w);
  return out;
}

}  // namespace

TEST_CASE("the vectorised loops give the scalar loops' run bit for bit", "[simd]") {
  if (widths().empty()) {
    WARN("this CPU has no AVX2: only the scalar loop runs, nothing to compare");
    return;
  }
  if (simd_width_available() < 8) WARN("this CPU has no AVX-512: only the four-lane loops are compared");
  SECTION("frictional") {
    // 729 spheres: the last chunk of 217 particles ends with one moved by the scalar code.
    const Simulation scalar = compressed_with(0, 0.5, 12000, 9);
    std::size_t sliding = 0;
    for (auto f : scalar.history().sliding) sliding += f;
    REQUIRE(sliding > 0);  // the Coulomb cap ran
    // Pairs left after the last full block go through the scalar code: make sure both paths ran.
    REQUIRE(scalar.pairs().size() % 8 % 4 != 0);
    for (int w : widths()) {
      INFO("vector width " << w);
      const Simulation simd = compressed_with(w, 0.5, 12000, 9);
      require_identical(scalar, simd);
      REQUIRE(scalar.energy().dissipated_friction == simd.energy().dissipated_friction);
      REQUIRE(scalar.energy().dissipated_damping == simd.energy().dissipated_damping);
      REQUIRE(scalar.energy().kinetic == simd.energy().kinetic);
      REQUIRE(scalar.sums().elastic_tangential_J == simd.sums().elastic_tangential_J);
      REQUIRE(scalar.sums().stiffness_Pa == simd.sums().stiffness_Pa);
    }
  }
  SECTION("frictionless") {
    const Simulation scalar = compressed_with(0, 0.0);
    for (int w : widths()) {
      INFO("vector width " << w);
      const Simulation simd = compressed_with(w, 0.0);
      require_identical(scalar, simd);
      REQUIRE(scalar.sums().elastic_normal_J == simd.sums().elastic_normal_J);
      REQUIRE(scalar.sums().stiffness_Pa == simd.sums().stiffness_Pa);
    }
  }
}

// Every law a scene can choose (packing_support.hpp, every_law()) through every pair loop: the
// laws' parts are written once for any lanes (contact/lane_ops.inc), and this checks that each
// law's normal force, history update, caps, torques and energies come out the same, bit for bit,
// in one lane, four (AVX2) and eight (AVX-512). 4,000 steps of 1,000 spheres: contacts form by
// step ~500 and the packing is at ~100 kPa by step 4,000, with contacts sliding at the Coulomb cap
// and rolling springs at theirs (both required, so each law's cap branch ran).
TEST_CASE("the vectorised loops give the scalar loop's run bit for bit for every contact law", "[simd][law]") {
  if (widths().empty()) {
    WARN("this CPU has no AVX2: only the scalar loop runs, nothing to compare");
    return;
  }
  const int saved = simd_width();
  for (const LawScene& law : every_law()) {
    INFO("law " << law.name);
    cap_simd_width(0);
    const LawRun scalar = compressed_law(law, 1, 4000);
    const bool frictional = has_tangential(scalar.sim.material().law), rolls = has_rolling(scalar.sim.material().law);
    INFO("contacts " << scalar.sim.sums().contacts << ", sliding " << scalar.sliding << ", rolling springs at the cap "
                     << scalar.rolling_at_cap << ", pairs " << scalar.sim.pairs().size());
    if (frictional) REQUIRE(scalar.sliding > 0);
    if (rolls) REQUIRE(scalar.rolling_at_cap > 0);
    if (rolls) REQUIRE(scalar.sim.energy().dissipated_rolling > 0);
    for (int w : widths()) {
      INFO("vector width " << w);
      cap_simd_width(w);
      REQUIRE(simd_width() == w);
      const LawRun simd = compressed_law(law, 1, 4000);
      require_identical(scalar.sim, simd.sim);
      const EnergyBalance &a = scalar.sim.energy(), &b = simd.sim.energy();
      REQUIRE(a.dissipated_friction == b.dissipated_friction);
      REQUIRE(a.dissipated_rolling == b.dissipated_rolling);
      REQUIRE(a.dissipated_damping == b.dissipated_damping);
      REQUIRE(a.kinetic == b.kinetic);
      REQUIRE(a.elastic == b.elastic);
      REQUIRE(a.work_by_cell == b.work_by_cell);
      const StepSums &sa = scalar.sim.sums(), &sb = simd.sim.sums();
      REQUIRE(sa.elastic_normal_J == sb.elastic_normal_J);
      REQUIRE(sa.elastic_tangential_J == sb.elastic_tangential_J);
      REQUIRE(sa.elastic_rolling_J == sb.elastic_rolling_J);
      REQUIRE(sa.stiffness_Pa == sb.stiffness_Pa);
      REQUIRE(sa.sum_normal_force_N == sb.sum_normal_force_N);
    }
  }
  cap_simd_width(saved);
}
