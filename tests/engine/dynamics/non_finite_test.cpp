// A run that blows up stops at once with an error naming the step, and never leaves a result
// that looks complete.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "config/scene_config.hpp"
#include "io/hdf5.hpp"
#include "run/run_scene.hpp"

namespace {

// Two overlapping spheres on a stiff spring with a time step 3x the leapfrog limit 2 sqrt(m/kn):
// the oscillation amplification per step is about |1 - (w dt)^2/2| + ... > 1, so the energy grows
// geometrically and overflows to inf (then NaN) within a few hundred steps.
const char* unstable_scene = R"(
name: unstable
particles: {csv: unstable.csv, cell: [0.02, 0.02, 0.02]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.0}
damping: {translational: 0, rotational: 0}
numerics: {time_step: 2.0e-5, max_time_step_fraction: 10}
stages:
  - {name: blow_up, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0}
)";

}  // namespace

TEST_CASE("a run whose values become non-finite stops with an error naming the step", "[dynamics][stability]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "non_finite";
  fs::create_directories(dir);
  {
    std::ofstream csv(dir / "unstable.csv");
    csv << "x,y,z,radius\n0.008,0.01,0.01,0.0015\n0.0105,0.01,0.01,0.0015\n";  // 0.5 mm overlap
  }
  const dem::SceneConfig scene = dem::scene_from_text(unstable_scene, (dir / "unstable.yaml").string());
  // Critical step of these 3 mm spheres: 2 sqrt(m/kn) = 2 sqrt(3.75e-5 / 1e6) = 1.22e-5 s < 2e-5 s.
  const std::string out = (dir / "unstable.h5").string();
  fs::remove(out);
  fs::remove(out + ".partial");
  try {
    dem::run_scene(scene, out);
    FAIL("the unstable run finished");
  } catch (const dem::NonFiniteError& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::Matchers::Contains("non-finite") && Catch::Matchers::Contains("at step"));
  }
  // 1 s at 2e-5 s would be 50,000 steps: the run must stop long before, and leave no final file.
  CHECK_FALSE(fs::exists(out));
  REQUIRE(fs::exists(out + ".partial"));
  dem::h5::Handle f = dem::h5::open_file_read(out + ".partial");
  const std::string status = dem::h5::get_string_attribute(f, "status");
  CHECK_THAT(status, Catch::Matchers::StartsWith("failed: non-finite"));
  // No time-series value written before the stop is NaN or infinite.
  dem::h5::Handle g = dem::h5::open_group(f, "timeseries");
  std::size_t cols = 0;
  const auto ke = dem::h5::read<double>(g, "kinetic_energy_translational", cols);
  for (double x : ke) CHECK(std::isfinite(x));
}
