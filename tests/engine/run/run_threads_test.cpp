// The threads a run uses (run/thread_choice.hpp, run_stages): at most one per chunk of 512
// particles, and the caller's count set again when the run ends. Which count steps faster is not
// checked here: on a loaded machine (ctest -j2) the 1,000-sphere run may last past its first trial
// of 1 thread, so whether it tries 1 depends on the load. thread_choice_test.cpp drives that with
// a made-up clock.
#include <catch2/catch.hpp>

#include <omp.h>

#include <string>

#include "config/scene_config.hpp"
#include "engine/io/io_test_support.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

// side^3 spheres of 3.0-4.5 mm on a lattice, a few hundred steps of compression.
SceneConfig small_run(int side, const std::string& dir) {
  const std::string n = std::to_string(side);
  return scene_from_text("name: threads\n"
                         "particles:\n"
                         "  lattice: {n: [" + n + ", " + n + ", " + n + "], spacing: 4.6e-3, seed: 5}\n"
                         "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                         "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                         "numerics: {time_step: 1.0e-6}\n"
                         "output: {interval: 100}\n"
                         "stages:\n"
                         "  - {name: squeeze, type: strain_rate, strain_rate: [5, 5, 5], duration: 3.0e-4}\n",
                         dir + "/threads.yaml");
}

}  // namespace

// One test case, so that ctest never runs two 2-thread cases at once on 2 cores.
TEST_CASE("a run uses at most one thread per chunk of 512 particles and gives the caller's count back", "[run][threads]") {
  const std::string dir = test::scratch_dir("run_threads");
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);
  // 216 spheres: one chunk, one thread. 1,000 spheres: two chunks (512 and 488), two threads.
  const RunSummary one = run_scene(small_run(6, dir), dir + "/216.h5");
  CHECK(omp_get_max_threads() == 2);
  const RunSummary two = run_scene(small_run(10, dir), dir + "/1000.h5");
  CHECK(omp_get_max_threads() == 2);
  omp_set_num_threads(saved);
  CHECK(one.steps == 300);
  CHECK(one.threads == 1);
  CHECK(one.thread_trials == 0);
  CHECK(two.steps == 300);
  CHECK(two.threads == 2);
  // It starts on 2: a trial of 1 begins only after a whole window of the count in use, so,
  // however loaded the machine, some of its steps ran on 2 threads.
  CHECK(two.steps_on_one_thread < two.steps);
}
