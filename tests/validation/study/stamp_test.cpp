// A study's stamp from its results: the engine and the baseline of its first preparation (seed1,
// its first density, the named variant's), the spheres of that preparation, the samples of the
// manifest; and the stamp's JSON read back, "not recorded" for what it lacks.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <hdf5.h>

#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "study/baseline.hpp"
#include "study/stamp.hpp"
#include "study/utc_day.hpp"

namespace fs = std::filesystem;

namespace {

std::string scene(double time_step, int seed) {
  return "name: x\nparticles:\n  lattice: {n: [2, 2, 2], spacing: 0.005, seed: " + std::to_string(seed) +
         "}\nmaterial: {density: 2650, law: linear, kn: 1000000, friction: 0}\nnumerics: {time_step: " + std::to_string(time_step) + "}\n";
}

// A complete result (mark_complete), software_version, scene_yaml and one frame of `spheres` positions.
void write_result(const fs::path& file, const std::string& engine, const std::string& scene_yaml, int spheres) {
  fs::create_directories(file.parent_path());
  dem::h5::Handle f = dem::h5::create_file(file.string());
  dem::test::mark_complete(f);
  dem::h5::set_attribute(f, "software_version", engine);
  dem::h5::write_text(f, "scene_yaml", scene_yaml);
  {
    dem::h5::Handle g = dem::h5::create_group(f, "timeseries");
    dem::h5::write<double>(g, "void_ratio", {0.9, 0.7}, 1, "1");
  }
  dem::h5::Handle p = dem::h5::create_group(f, "particles");
  dem::h5::Handle all = dem::h5::create_group(p, "all");
  dem::h5::Handle position = dem::h5::create_group(all, "position");
  const hsize_t dims[3] = {1, static_cast<hsize_t>(spheres), 3};
  const std::vector<double> zeros(3 * static_cast<std::size_t>(spheres), 0.0);
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t set = H5Dcreate2(position, "value", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  H5Dclose(set);
  H5Sclose(space);
}

}  // namespace

TEST_CASE("stamp: from a study's results, its first preparation of seed1 and the named variant", "[stamp]") {
  const fs::path dir = dem::test::scratch_dir("stamp_of_results");
  // Variants "other" (listed first, another time step, engine B) and "base"; densities dense then
  // loose; seeds 2 and 1 (seed2 listed first). The stamp of "base" must be base's seed1 dense
  // preparation: engine A, 27 spheres, its scene's baseline.
  std::ofstream runs(dir / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  for (const std::string variant : {"other", "base"})
    for (int seed : {2, 1})
      for (const std::string density : {"dense", "loose"}) {
        const std::string run = "seed" + std::to_string(seed) + "/" + variant + "_" + density + "_prepare";
        runs << variant << "\t" << density << "\t-\t" << run << "\t/elsewhere/" << run << ".h5\t-\t0\tx\t" << seed << "\n";
        const bool is_it = variant == "base" && seed == 1 && density == "dense";
        write_result(dir / ("seed" + std::to_string(seed)) / (variant + "_" + density + "_prepare.h5"), variant == "base" ? "A" : "B",
                     scene(variant == "base" ? 1e-6 : 2e-6, seed), is_it ? 27 : 8);
      }
  runs.close();
  const validation::Stamp s = validation::stamp_of_results(dir.string(), "base");
  REQUIRE(s.engine == "A");
  REQUIRE(s.baseline == validation::baseline_of(scene(1e-6, 1)));
  REQUIRE(s.spheres == 27);
  REQUIRE(s.samples == 2);
  REQUIRE(s.date.size() == 10);  // YYYY-MM-DD, the day the files were written
  // Without a variant (or one the study lacks): the manifest's first preparation of seed1, other's.
  const validation::Stamp first = validation::stamp_of_results(dir.string());
  REQUIRE(first.engine == "B");
  REQUIRE(first.baseline == validation::baseline_of(scene(2e-6, 1)));
  REQUIRE(first.baseline != s.baseline);
  REQUIRE(validation::stamp_of_results(dir.string(), "none").engine == "B");
  // A folder without a manifest is refused, naming it.
  REQUIRE_THROWS_WITH(validation::stamp_of_results((dir / "nothing").string()), Catch::Contains("nothing"));
}

TEST_CASE("stamp: the engine source is the manifest's only when every result records its line's input hash", "[stamp]") {
  const fs::path dir = dem::test::scratch_dir("stamp_engine_source");
  // Two samples' preparations and tests; the manifest planned for engine source S with each run's
  // input hash h-<run>. A result the pipeline made from those inputs records that hash.
  const auto manifest = [&](bool with_hashes) {
    std::ofstream runs(dir / "runs.tsv");
    if (with_hashes) runs << "# engine source S schema 4\n";
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed" << (with_hashes ? "\tinput_hash" : "") << "\n";
    for (int seed : {1, 2})
      for (const std::string test : {"-", "test1"}) {
        const std::string run = "seed" + std::to_string(seed) + "/dense_" + (test == "-" ? "prepare" : test);
        runs << "-\tdense\t" << test << "\t" << run << "\t/elsewhere/" << run << ".h5\t-\t0\tx\t" << seed;
        if (with_hashes) runs << "\th-" << run;
        runs << "\n";
      }
  };
  const auto result = [&](int seed, const std::string& what, const std::string& hash) {
    const fs::path file = dir / ("seed" + std::to_string(seed)) / ("dense_" + what + ".h5");
    write_result(file, "A", scene(1e-6, seed), 8);
    dem::h5::Handle f = dem::h5::open_file_write(file.string());
    dem::h5::set_attribute(f, "input_hash", hash);
  };
  for (int seed : {1, 2})
    for (const std::string what : {"prepare", "test1"}) result(seed, what, "h-seed" + std::to_string(seed) + "/dense_" + what);
  manifest(true);
  const validation::Stamp all = validation::stamp_of_results(dir.string());
  REQUIRE(all.engine_source == "S schema 4");
  REQUIRE(all.other_engine_results == 0);
  // One result made from other inputs or by another engine (its hash is not its line's): counted,
  // and the stamp says so in JSON.
  result(2, "test1", "h-older");
  const validation::Stamp stale = validation::stamp_of_results(dir.string());
  REQUIRE(stale.other_engine_results == 1);
  const validation::Stamp back = validation::stamp_from_json(nlohmann::json::parse(validation::stamp_json(stale).dump()));
  REQUIRE(back.engine_source == "S schema 4");
  REQUIRE(back.other_engine_results == 1);
  // A manifest from before it listed hashes: no engine source recorded, nothing counted.
  manifest(false);
  const validation::Stamp older = validation::stamp_of_results(dir.string());
  REQUIRE(older.engine_source.empty());
  REQUIRE(older.other_engine_results == 0);
  REQUIRE(older.engine == "A");
}

TEST_CASE("stamp: JSON written and read back; what is missing is not recorded", "[stamp]") {
  const validation::Stamp s{"0.1.0+abc", "0123456789abcdef", 8000, 5, "2026-11-27"};
  const validation::Stamp back = validation::stamp_from_json(nlohmann::json::parse(validation::stamp_json(s).dump()));
  REQUIRE(back.engine == s.engine);
  REQUIRE(back.baseline == s.baseline);
  REQUIRE(back.spheres == 8000);
  REQUIRE(back.samples == 5);
  REQUIRE(back.date == s.date);
  const nlohmann::ordered_json none = validation::stamp_json(validation::Stamp{});
  for (const char* key : {"engine", "engine_source", "baseline", "spheres", "samples", "date"}) REQUIRE(none.at(key) == "not recorded");
  REQUIRE_FALSE(none.contains("other_engine_results"));
  REQUIRE_FALSE(validation::stamp_from_json(none).recorded());
  REQUIRE_FALSE(validation::stamp_from_json(nlohmann::json()).recorded());  // no stamp at all
  // Only some fields (the convergence summary's engine, baseline and date).
  const validation::Stamp part = validation::stamp_from_json({{"engine", "E"}, {"baseline", "b"}, {"date", "2026-11-01"}, {"runs", 3}});
  REQUIRE(part.recorded());
  REQUIRE(part.spheres == 0);
  REQUIRE(part.samples == 0);
  // A record stamped after the fact that knows its engine's source alone is recorded (the earlier
  // baseline's, reports/baselines/): it is another engine's, not one made before stamps.
  const validation::Stamp source_only = validation::stamp_from_json(
      {{"engine", "not recorded"}, {"engine_source", "85398fbd83a3644f"}, {"baseline", "not recorded"}, {"spheres", 8000}});
  REQUIRE(source_only.engine.empty());
  REQUIRE(source_only.recorded());
}

TEST_CASE("stamp: several studies' stamps combined list the values on which they differ", "[stamp]") {
  const validation::Stamp a{"E", "b1", 8000, 3, "2026-11-20"}, b{"E", "b2", 8000, 3, "2026-11-25"};
  const validation::Stamp c = validation::combined({a, b, a});
  REQUIRE(c.engine == "E");
  REQUIRE(c.baseline == "b1, b2");
  REQUIRE(c.date == "2026-11-25");
  REQUIRE(validation::combined({a, a}).baseline == "b1");
  // A study not run yet (nothing recorded) adds nothing, also when it comes first.
  const validation::Stamp d = validation::combined({validation::Stamp{}, a, validation::Stamp{"", "", 0, 0, "2026-12-01"}});
  REQUIRE(d.engine == "E");
  REQUIRE(d.baseline == "b1");
  REQUIRE(d.date == "2026-11-20");
}

// Seconds since the epoch of two known days (1970-01-01 00:00 UTC and 2024-02-29 23:59:59 UTC,
// 19,782 days and 86,399 s later), and the days a stamp or a --date may say.
TEST_CASE("stamp: the day in UTC, written and checked", "[stamp]") {
  CHECK(validation::utc_day(0) == "1970-01-01");
  CHECK(validation::utc_day(19782L * 86400 + 86399) == "2024-02-29");
  CHECK(validation::is_utc_day(validation::utc_day()));
  CHECK(validation::is_utc_day("2024-02-29"));
  for (const char* bad : {"2026-02-30", "2026-13-01", "2026-12-4", "4/12/2026", "2026-12-04x", ""}) {
    INFO(bad);
    CHECK_FALSE(validation::is_utc_day(bad));
  }
}
