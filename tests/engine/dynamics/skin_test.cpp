// The Verlet skin must not change a single bit of a run.
//
// Why exact equality is the right expectation: a wider skin only adds pairs out of contact to the
// list. Their forces, torques and sums are exact zeros (+0.0, which leaves any sum that started at
// +0.0 unchanged), and pair sums are chunked by particle (dynamics/kernel.hpp), so every contact
// lands in the same chunk, in the same order, whatever the skin and whenever the list was rebuilt.
#include <catch2/catch.hpp>

#include <algorithm>

#include "engine/dynamics/packing_support.hpp"

using namespace dem;
using namespace dem::test;

TEST_CASE("the Verlet skin changes no bit of a run", "[skin]") {
  for (const double friction : {0.5, 0.0}) {
    CAPTURE(friction);
    const Simulation wide = compressed(friction, 1, 12000, 10, "4.0e-4");
    const Simulation narrow = compressed(friction, 1, 12000, 10, "2.0e-5");
    // The two runs do hold different lists, rebuilt at different steps.
    REQUIRE(narrow.pairs().size() < wide.pairs().size());
    REQUIRE(narrow.verlet_list().builds() > wide.verlet_list().builds());
    require_identical_motion(wide, narrow);
    const std::vector<Contact> contacts = touching(wide);
    REQUIRE(contacts == touching(narrow));  // the same contacts with the same springs and flags
    const auto loaded = std::count_if(contacts.begin(), contacts.end(),
                                      [](const Contact& c) { return std::get<2>(c) != Vec3::Zero(); });
    if (friction > 0) REQUIRE(loaded > 500);
    REQUIRE(wide.energy().dissipated_friction == narrow.energy().dissipated_friction);
    REQUIRE(wide.energy().dissipated_damping == narrow.energy().dissipated_damping);
    REQUIRE(wide.energy().work_by_cell == narrow.energy().work_by_cell);
    REQUIRE(wide.sums().stiffness_Pa == narrow.sums().stiffness_Pa);
  }
}
