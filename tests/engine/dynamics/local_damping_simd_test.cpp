// Local (Cundall) damping in the vectorised leapfrog update (dynamics/kernel_simd.cpp,
// damped_update) must give the scalar update's run bit for bit: each lane computes
// f - (alpha |f|) sign(v) and v + dt/m x that in the scalar order (see kernel_simd_test.cpp for
// why exact equality is the expectation).
#include <catch2/catch.hpp>

#include "dynamics/kernel_simd.hpp"
#include "engine/dynamics/packing_support.hpp"

using namespace dem;
using namespace dem::test;

namespace {

// 729 spheres compressed to 100 kPa for `steps` steps with local damping 0.2 (contacts form,
// slide and open; the last particle chunk ends with particles the scalar code moves).
Simulation compressed_locally(int width, int steps) {
  const int saved = simd_width();
  cap_simd_width(width);
  const SceneConfig scene = scene_from_text(
      "name: local\n"
      "particles:\n"
      "  lattice: {n: [9, 9, 9], spacing: 4.6e-3, seed: 5}\n"
      "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
      "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
      "damping: {form: local, translational: 0.2, rotational: 0.2}\n"
      "numerics: {time_step: 1.0e-6}\n"
      "stages: [{name: s, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0e-6}]\n",
      "local.yaml");
  Simulation sim = build_simulation(scene);
  Squeeze squeeze(scene);
  for (int i = 0; i < steps; ++i) squeeze.step(sim);
  cap_simd_width(saved);
  return sim;
}

}  // namespace

TEST_CASE("local damping: the vectorised update gives the scalar update's run bit for bit", "[simd][damping]") {
  if (simd_width_available() < 4) {
    WARN("this CPU has no AVX2: only the scalar update runs, nothing to compare");
    return;
  }
  const Simulation scalar = compressed_locally(0, 8000);
  const Simulation simd = compressed_locally(4, 8000);
  REQUIRE(scalar.energy().dissipated_damping > 0);  // the damping acted
  require_identical(scalar, simd);
  REQUIRE(scalar.energy().dissipated_damping == simd.energy().dissipated_damping);
  REQUIRE(scalar.energy().kinetic == simd.energy().kinetic);
}
