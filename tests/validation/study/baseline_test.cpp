// The baseline hash: what a study varies or only names (lattice size and seed, name, output, the
// preparation friction, file paths) leaves it alone; a setting every study shares changes it;
// how the YAML is written (key order, number spelling) does not.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "io/hdf5.hpp"
#include "study/baseline.hpp"

using validation::baseline_of;

namespace {

// A preparation scene as a result stores it (keys in the engine's order, flow maps).
const std::string scene =
    "name: prepare_dense\n"
    "particles:\n"
    "  lattice: {n: [20, 20, 20], spacing: 0.005, seed: 1}\n"
    "  grading: {diameters: [0.003, 0.0037, 0.0045], percent_finer: [0, 50, 100], basis: number}\n"
    "material: {density: 2650, law: linear, kn: 1000000, ks: 1000000, friction: 0}\n"
    "damping: {form: viscous, translational: 0.05, rotational: 0.05}\n"
    "numerics: {time_step: 1e-06, max_time_step_fraction: 0.1, max_energy_error: 0.01, verlet_skin: 0.0001}\n"
    "output: {interval: 2000, flush_rows: 64}\n"
    "stages:\n"
    "  - {name: compress, type: stress, target: [100000, 100000, 100000], rate: 1000000}\n";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("baseline: 16 hex digits of FNV-1a 64", "[baseline]") {
  const std::string b = baseline_of(scene);
  REQUIRE(b.size() == 16);
  REQUIRE(b.find_first_not_of("0123456789abcdef") == std::string::npos);
  // An empty map is written "{}"; FNV-1a 64 of those two bytes, worked out apart (Python:
  // h = 0xcbf29ce484222325; per byte h ^= c; h = h * 0x100000001b3 mod 2^64).
  REQUIRE(baseline_of("{}") == "08f44b07b5901a25");
}

TEST_CASE("baseline: what every study varies or only names leaves it alone", "[baseline]") {
  const std::string b = baseline_of(scene);
  std::string other = replaced(scene, "n: [20, 20, 20]", "n: [10, 10, 10]");      // 1,000 spheres
  other = replaced(other, "seed: 1", "seed: 3");                                 // another sample
  other = replaced(other, "name: prepare_dense", "name: prepare_loose");         // another name
  other = replaced(other, "friction: 0}", "friction: 0.5}");                     // another density
  other = replaced(other, "output: {interval: 2000, flush_rows: 64}", "output: {interval: 500}");
  REQUIRE(baseline_of(other) == b);
  // A preparation at friction 0 as a result stores it: the engine writes no ks without friction
  // (seed1/dense_prepare.h5 of the quick study), so the densities of one study hash alike.
  REQUIRE(baseline_of(replaced(scene, "ks: 1000000, friction: 0}", "friction: 0}")) == b);
  // A sample read from a file instead of the lattice: the path is a place, not a setting.
  const std::string from_state_a = "particles: {state: /a/dense.h5}\nnumerics: {time_step: 1e-06}\n";
  const std::string from_state_b = "particles: {state: results/x/dense.h5}\nnumerics: {time_step: 1e-06}\n";
  REQUIRE(baseline_of(from_state_a) == baseline_of(from_state_b));
}

TEST_CASE("baseline: a shared setting changes it", "[baseline]") {
  const std::string b = baseline_of(scene);
  REQUIRE(baseline_of(replaced(scene, "time_step: 1e-06", "time_step: 5e-07")) != b);
  REQUIRE(baseline_of(replaced(scene, "translational: 0.05", "translational: 0.1")) != b);
  REQUIRE(baseline_of(replaced(scene, "form: viscous", "form: local")) != b);
  REQUIRE(baseline_of(replaced(scene, "spacing: 0.005", "spacing: 0.006")) != b);
  REQUIRE(baseline_of(replaced(scene, "kn: 1000000", "kn: 2000000")) != b);
  REQUIRE(baseline_of(replaced(scene, "rate: 1000000}", "rate: 2000000}")) != b);
  // A list's order is a setting (the grading's diameters against their percentages).
  REQUIRE(baseline_of(replaced(scene, "percent_finer: [0, 50, 100]", "percent_finer: [0, 100, 50]")) != b);
}

TEST_CASE("baseline: key order and number spelling do not change it", "[baseline]") {
  const std::string b = baseline_of(scene);
  // The same numbers as a scene file writes them, and the damping's keys in another order.
  std::string written = replaced(scene, "time_step: 1e-06", "time_step: 1.0e-6");
  written = replaced(written, "kn: 1000000", "kn: 1.0e6");
  written = replaced(written, "spacing: 0.005", "spacing: 5.0e-3");
  written = replaced(written, "damping: {form: viscous, translational: 0.05, rotational: 0.05}",
                     "damping: {rotational: 0.05, form: viscous, translational: 5e-2}");
  REQUIRE(baseline_of(written) == b);
  // Block style rather than flow, material's keys reordered.
  written = replaced(written, "material: {density: 2650, law: linear, kn: 1.0e6, ks: 1000000, friction: 0}",
                     "material:\n  friction: 0.2\n  ks: 1000000.0\n  kn: 1000000\n  law: linear\n  density: 2650.0");
  REQUIRE(baseline_of(written) == b);
}

TEST_CASE("baseline: text that is not YAML is refused, naming it", "[baseline]") {
  REQUIRE_THROWS_WITH(baseline_of("a: [1, 2", "x.h5"), Catch::Contains("x.h5"));
}

TEST_CASE("baseline: a copied result has the baseline of the run it copies while that run is here", "[baseline]") {
  // The pipeline's copy of a run (the same scene but for its name) recorded, before, the scene as the
  // study wrote it: no defaults filled in (here: no law, no max_energy_error), so its own text has
  // another baseline than the resolved scene of the run it copies.
  const std::filesystem::path dir = std::filesystem::path(DEM_BINARY_DIR) / "test_tmp" / "baseline_copy";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string as_written = replaced(replaced(scene, "law: linear, ", ""), "max_energy_error: 0.01, ", "");
  REQUIRE(baseline_of(as_written) != baseline_of(scene));
  const auto write = [&](const std::string& name, const std::string& text, const std::string& copied_from) {
    dem::h5::Handle f = dem::h5::create_file((dir / name).string());
    dem::h5::write_text(f, "scene_yaml", text);
    if (!copied_from.empty()) dem::h5::set_attribute(f, "copied_from", copied_from);
    return (dir / name).string();
  };
  const std::string source = write("source.h5", scene, "");
  const std::string copy = write("copy.h5", as_written, source);
  CHECK(validation::baseline_of_result(copy) == baseline_of(scene));
  // The run it copies gone: the copy's own text is all there is.
  std::filesystem::remove(source);
  CHECK(validation::baseline_of_result(copy) == baseline_of(as_written));
}
