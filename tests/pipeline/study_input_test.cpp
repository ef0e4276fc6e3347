// Bad study files: each is refused before anything runs, with a message naming the file, the key
// (with its line where there is one) and what is allowed. The expected fragments are the parts a
// user needs to fix the file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

struct BadStudy {
  std::string what, text;
  std::vector<std::string> expected;  // fragments of the message, besides the file name
};

const std::string good_tail =
    "tests: [{name: t1, scene: t.yaml}]\n"
    "profiles: {paper: {lattice: 20}, quick: {lattice: 10}}\n";
const std::string head = "name: s\noutput: out\npreparation: prep.yaml\n";
const std::string density = "densities: [{name: loose, friction: 0.5}]\n";

const std::vector<BadStudy> catalogue = {
    {"empty file", "", {"the file is empty"}},
    {"a list, not a mapping", "- a\n- b\n", {"must be a mapping", "got a list"}},
    {"missing name", "output: out\npreparation: prep.yaml\n" + density + good_tail, {"name: missing"}},
    {"empty name", "name: \"\"\noutput: out\npreparation: prep.yaml\n" + density + good_tail, {"name: must be non-empty text"}},
    {"duplicate key", "name: s\n" + head + density + good_tail, {"name: duplicate key", "line 2"}},
    {"misspelt key", head + "densites: [{name: loose, friction: 0.5}]\n" + good_tail, {"densities: must be a non-empty list"}},
    {"negative friction", head + "densities: [{name: loose, friction: -1}]\n" + good_tail,
     {"densities[0].friction", "must be in [0, 10]", "got -1", "line 4"}},
    {"friction not a number", head + "densities: [{name: loose, friction: high}]\n" + good_tail,
     {"densities[0].friction", "must be a number", "'high'"}},
    {"huge lattice", head + density + "tests: [{name: t1, scene: t.yaml}]\nprofiles: {paper: {lattice: 1.0e9}, quick: {}}\n",
     {"profiles.paper.lattice", "[2, 100]"}},
    {"negative max_repeat", head + density + "tests: [{name: t1, scene: t.yaml}]\nprofiles: {paper: {}, quick: {max_repeat: -2}}\n",
     {"profiles.quick.max_repeat", "[0, 1000000]"}},
    {"no profile", head + density + "tests: [{name: t1, scene: t.yaml}]\nprofiles: {}\n",
     {"profiles", "must be a non-empty mapping"}},
    {"unknown profile key", head + density + "tests: [{name: t1, scene: t.yaml}]\nprofiles: {paper: {latice: 20}, quick: {}}\n",
     {"profiles.paper", "latice"}},
    {"duplicate density name", head + "densities: [{name: loose, friction: 0.5}, {name: loose, friction: 0}]\n" + good_tail,
     {"densities[1].name", "duplicate name 'loose'"}},
    {"test scene missing", head + density + "tests: [{name: t1, scene: nowhere.yaml}]\nprofiles: {paper: {}, quick: {}}\n",
     {"tests[0].scene", "no such file", "nowhere.yaml"}},
    {"preparation missing", "name: s\noutput: out\npreparation: gone.yaml\n" + density + good_tail,
     {"preparation", "no such file", "gone.yaml"}},
    {"empty density list", head + "densities: []\n" + good_tail, {"densities: must be a non-empty list"}},
    {"broken YAML", head + "densities: [{name: loose, friction: 0.5}\n" + good_tail, {"not valid YAML", "line"}},
    // variants: scene overrides per setting of the study
    {"misspelt variant key", head + density + good_tail + "variants: [{name: a, sett: {numerics.time_step: 1.0e-6}}]\n",
     {"variants[0]", "unknown key 'sett'", "did you mean 'set'"}},
    {"override path not a key path", head + density + good_tail + "variants: [{name: a, set: {\"numerics..time_step\": 1}}]\n",
     {"variants[0].set", "'numerics..time_step' is not a scene key path"}},
    {"override of the run name", head + density + good_tail + "variants: [{name: a, set: {name: x}}]\n",
     {"variants[0].set.name", "is set by the pipeline", "allowed: any other scene key"}},
    {"test override of its sample", head + density + good_tail + "variants: [{name: a, test: {particles.state: x.h5}}]\n",
     {"variants[0].test.particles.state", "is set by the pipeline"}},
    {"particles for preparation and tests", head + density + good_tail + "variants: [{name: a, set: {particles.lattice.n: [2, 2, 2]}}]\n",
     {"variants[0].set.particles.lattice.n", "put it under prepare:"}},
    {"two time steps", head + density + good_tail + "variants: [{name: a, time_step_fraction: 0.1, set: {numerics.time_step: 1.0e-6}}]\n",
     {"variants[0].time_step_fraction", "keep one"}},
    {"zero time step fraction", head + density + good_tail + "variants: [{name: a, time_step_fraction: 0}]\n",
     {"variants[0].time_step_fraction", "got 0"}},
    {"duplicate variant", head + density + good_tail + "variants: [{name: a}, {name: a}]\n",
     {"variants[1].name", "duplicate name 'a'"}},
    {"variant name with a slash", head + density + good_tail + "variants: [{name: a/b}]\n",
     {"variants[0].name", "'a/b' contains a path separator"}},  // the rule of every name that becomes a path
    {"empty override mapping", head + density + good_tail + "variants: [{name: a, set: {}}]\n",
     {"variants[0].set", "non-empty mapping of scene key paths"}},
    {"may_fail not a boolean", head + density + good_tail + "variants: [{name: a, may_fail: maybe}]\n",
     {"variants[0].may_fail", "true or false", "maybe"}},
    {"test override of the run name", head + density + "tests: [{name: t1, scene: t.yaml, set: {name: x}}]\n" +
     "profiles: {paper: {lattice: 20}, quick: {lattice: 10}}\n", {"tests[0].set.name", "is set by the pipeline"}},
    // names that become paths; numbers read one way
    {"density name with a path in it", head + "densities: [{name: loose, friction: 0.5}, {name: x/../loose, friction: 0}]\n" + good_tail,
     {"densities[1].name", "'x/../loose' contains a path separator", "part of file names"}},
    {"density name '..'", head + "densities: [{name: .., friction: 0.5}]\n" + good_tail, {"densities[0].name", "contains '..'"}},
    {"hidden density name", head + "densities: [{name: .loose, friction: 0.5}]\n" + good_tail, {"densities[0].name", "starts with a dot"}},
    {"test name with a separator", head + density + "tests: [{name: 'a\\b', scene: t.yaml}]\nprofiles: {paper: {}, quick: {}}\n",
     {"tests[0].name", "contains a path separator"}},
    {"test name with a tab", head + density + "tests: [{name: \"a\\tb\", scene: t.yaml}]\nprofiles: {paper: {}, quick: {}}\n",
     {"tests[0].name", "contains a control character"}},
    {"seeds with a leading zero", head + density + good_tail + "seeds: 010\n", {"seeds", "'010'", "a leading zero is refused", "write 10"}},
    {"a seed with a leading zero", head + density + good_tail + "seeds: [1, 010]\n", {"seeds", "'010'", "a leading zero is refused"}},
    {"hexadecimal seeds", head + density + good_tail + "seeds: 0x10\n", {"seeds", "'0x10'", "hexadecimal"}},
    {"friction that underflows", head + "densities: [{name: loose, friction: 1e-400}]\n" + good_tail,
     {"densities[0].friction", "'1e-400'", "would read as 0"}},
    {"lattice with a leading zero", head + density + "tests: [{name: t1, scene: t.yaml}]\nprofiles: {paper: {lattice: 020}, quick: {}}\n",
     {"profiles.paper.lattice", "'020'", "a leading zero is refused", "write 20"}},
};

}  // namespace

TEST_CASE("bad study files are refused naming the file, the key and what is allowed", "[pipeline][input]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "bad_studies";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "prep.yaml") << "name: p\n";
  std::ofstream(dir / "t.yaml") << "name: t\n";
  {  // the good study the cases are made from loads
    const std::string good = (dir / "good.yaml").string();
    std::ofstream(good) << head << density << good_tail;
    CHECK_NOTHROW(pipeline::load_study(good));
  }
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    const BadStudy& c = catalogue[i];
    const std::string file = (dir / ("bad" + std::to_string(i) + ".yaml")).string();
    std::ofstream(file) << c.text;
    INFO(c.what);
    try {
      pipeline::load_study(file);
      FAIL("accepted: " << c.what);
    } catch (const dem::ConfigError& e) {
      const std::string msg = e.what();
      INFO(msg);
      CHECK(msg.find(file) != std::string::npos);
      for (const std::string& f : c.expected) CHECK(msg.find(f) != std::string::npos);
    }
  }
  SECTION("a directory or a missing file instead of a study") {
    CHECK_THROWS_WITH(pipeline::load_study(dir.string()), Catch::Matchers::Contains("is a directory"));
    CHECK_THROWS_WITH(pipeline::load_study((dir / "absent.yaml").string()), Catch::Matchers::Contains("absent.yaml"));
  }
}

TEST_CASE("every study name that becomes part of a file name is checked, by one rule", "[pipeline][input][names]") {
  // Found in review: densities `loose` and `x/../loose` mapped to one result file (4 runs "ran",
  // 2 files existed, one density's test ran from the other's sample). The class swept: each name
  // that becomes a path (densities[].name, tests[].name, variants[].name: results, scenes and
  // logs are <variant>_<density>_<test>.h5) against each way a name can leave its folder or
  // collide: a separator, '..', a leading dot, a control character (a newline would also break
  // runs.tsv), nothing at all.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "study_names";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "prep.yaml") << "name: p\n";
  std::ofstream(dir / "t.yaml") << "name: t\n";
  struct Bad {
    std::string name, why;  // the name as YAML (double-quoted), what the message says
  };
  const std::vector<Bad> names = {{"x/../loose", "contains a path separator"}, {"a/b", "contains a path separator"},
                                  {"a\\\\b", "contains a path separator"}, {"..", "contains '..'"},
                                  {"a..b", "contains '..'"},                {".", "starts with a dot"},
                                  {".hidden", "starts with a dot"},         {"a\\nb", "contains a control character"},
                                  {"a\\tb", "contains a control character"}};
  const auto study = [&](const std::string& d, const std::string& t, const std::string& v) {
    return head + "densities: [{name: \"" + d + "\", friction: 0.5}]\ntests: [{name: \"" + t + "\", scene: t.yaml}]\n" +
           "profiles: {paper: {lattice: 20}, quick: {lattice: 10}}\nvariants: [{name: \"" + v + "\"}]\n";
  };
  const std::string file = (dir / "s.yaml").string();
  std::ofstream(file) << study("loose", "t1", "v1");
  REQUIRE_NOTHROW(pipeline::load_study(file));  // the base: each case changes one name
  int refused = 0;
  for (const std::string key : {"densities[0].name", "tests[0].name", "variants[0].name"})
    for (const Bad& b : names) {
      INFO(key << " = " << b.name);
      std::ofstream(file, std::ios::trunc) << (key[0] == 'd' ? study(b.name, "t1", "v1")
                                               : key[0] == 't' ? study("loose", b.name, "v1")
                                                               : study("loose", "t1", b.name));
      try {
        pipeline::load_study(file);
        FAIL("accepted");
      } catch (const dem::ConfigError& e) {
        const std::string msg = e.what();
        INFO(msg);
        CHECK(msg.find(file + ": " + key + ": ") != std::string::npos);
        CHECK(msg.find(b.why) != std::string::npos);
        CHECK(msg.find("no / or \\, no '..', no leading dot") != std::string::npos);
        ++refused;
      }
    }
  CHECK(refused == 27);
  // Names that are plain file names stay allowed (the critical-state study's `extension_mu0.5`).
  for (const std::string ok : {"extension_mu0.5", "hold_ufr_1e-2", "Dichte"}) {
    std::ofstream(file, std::ios::trunc) << study(ok, ok + std::string("_t"), "v1");  // density and test names differ
    CHECK_NOTHROW(pipeline::load_study(file));
  }
}

TEST_CASE("pipeline: an --out that is a file and a --throughput out of range are refused, exit 2", "[pipeline][input]") {
  const std::string bin = std::string(DEM_BINARY_DIR) + "/bin";
  if (!fs::exists(bin + "/pipeline")) return;
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "pipeline_bad_options";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  const std::string study = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml";
  const auto run = [&](const std::string& args) {
    return dem::test::run_command("'" + bin + "/pipeline' '" + study + "' " + args + " 2>&1");
  };
  auto r = run("--profile quick --plan --out '" + (dir / "file").string() + "'");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Matchers::Contains("--out '" + (dir / "file").string() + "' is not a folder"));
  // 1e-300 particle-steps/s made --plan print a 63-digit number of hours.
  r = run("--profile quick --plan --throughput 1e-300");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Matchers::Contains("--throughput 1e-300 particle-steps/s is outside 1000 to 1e+12 particle-steps/s"));
}
