// validate records the stamp of the numbers it judged in validation.json: from the results, the
// engine and baseline of the first sample's preparation, its spheres and the samples; with
// --from-json, the record's stamp as it was (none: every field "not recorded").
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "study/baseline.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/validate";
const std::string source = DEM_SOURCE_DIR;

dem::test::CommandResult validate(const std::string& args) { return dem::test::run_command("'" + bin + "' " + args + " 2>&1"); }

nlohmann::json json_of(const fs::path& p) { return nlohmann::json::parse(dem::test::read_bytes(p.string())); }

}  // namespace

TEST_CASE("validate: the stamp from the results, kept by --from-json, not recorded in a record without one", "[validate][cli][stamp]") {
  const fs::path dir = dem::test::scratch_dir("validate_stamp");
  // Three samples: the shipped medium, dense and loose 1,000-sphere samples (10 x 10 x 10 lattice)
  // as the loose preparations of seed1..3; seed2 listed first in runs.tsv.
  const std::vector<std::string> packings = {"medium_1k.h5", "dense_1k.h5", "loose_1k.h5"};
  fs::create_directories(dir / "results");
  {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int seed : {2, 1, 3}) {
      const fs::path s = dir / "results" / ("seed" + std::to_string(seed));
      fs::create_directories(s);
      fs::copy_file(source + "/scenes/samples/" + packings[seed - 1], s / "loose_prepare.h5", fs::copy_options::overwrite_existing);
      runs << "-\tloose\t-\tseed" << seed << "/loose_prepare\t/x/loose_prepare.h5\t-\t0\tas written\t" << seed << "\n";
    }
  }
  std::ofstream(dir / "refs.yaml") << "source: lab\nlabel: lab\nrows:\n"
      "  - {name: e0, quantity: void_ratio_after_preparation, reference: 0.6, check: within, tolerance: 0.1, source: s, reason: r}\n";
  const std::string refs = (dir / "refs.yaml").string();
  const auto a = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / "a").string() + "'");
  INFO(a.out);
  const nlohmann::json stamp = json_of(dir / "a" / "validation.json").at("stamp");
  // seed1's preparation is the shipped medium sample: its engine and its scene's baseline.
  std::string engine, scene;
  {
    dem::h5::Handle f = dem::h5::open_file_read(source + "/scenes/samples/medium_1k.h5");
    engine = dem::h5::get_string_attribute(f, "software_version");
    scene = dem::h5::read_text(f, "scene_yaml");
  }
  CHECK(stamp.at("engine") == engine);
  CHECK(stamp.at("baseline") == validation::baseline_of(scene));
  CHECK(stamp.at("spheres") == 1000);
  CHECK(stamp.at("samples") == 3);
  CHECK(stamp.at("date").get<std::string>().size() == 10);
  // The three shipped samples are the three preparation scenes: one baseline (they differ only in
  // friction and name), so any seed would give the same.
  {
    dem::h5::Handle f = dem::h5::open_file_read(source + "/scenes/samples/dense_1k.h5");
    CHECK(validation::baseline_of(dem::h5::read_text(f, "scene_yaml")) == stamp.at("baseline").get<std::string>());
  }
  // Judged again from the record: the stamp as it was recorded, not today's.
  const auto b = validate("--from-json '" + (dir / "a" / "validation.json").string() + "' --references '" + refs + "' --out '" +
                          (dir / "b").string() + "'");
  INFO(b.out);
  CHECK(json_of(dir / "b" / "validation.json").at("stamp") == stamp);
  // A record made before stamps: every field not recorded.
  nlohmann::json old = json_of(dir / "a" / "validation.json");
  old.erase("stamp");
  fs::create_directories(dir / "c");
  std::ofstream(dir / "c" / "old.json") << old.dump(1);
  const auto c = validate("--from-json '" + (dir / "c" / "old.json").string() + "' --references '" + refs + "' --out '" + (dir / "c").string() + "'");
  INFO(c.out);
  for (const char* key : {"engine", "baseline", "spheres", "samples", "date"})
    CHECK(json_of(dir / "c" / "validation.json").at("stamp").at(key) == "not recorded");
}
