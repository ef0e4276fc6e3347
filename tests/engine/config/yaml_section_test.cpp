// The one YAML entry point (config/yaml_section.hpp: parse_yaml, load_yaml): the tree a reader
// walks, aliases expanded, is measured before it exists, and every reader of the project goes
// through it.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;
using dem::ConfigError;

namespace {

// Nine anchors, each a list of ten aliases of the one before: 1 KB of text, 10^9 leaves when
// walked (yaml-cpp shares the aliased nodes, so building the tree alone costs nothing).
std::string alias_bomb() {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int k = 1; k <= 9; ++k) {
    const std::string prev = "*a" + std::to_string(k - 1);
    text += "a" + std::to_string(k) + ": &a" + std::to_string(k) + " [";
    for (int i = 0; i < 10; ++i) text += (i ? ", " : "") + prev;
    text += "]\n";
  }
  return text;
}

// A sequence of `lists` aliases of one anchored list of nine scalars, then `scalars` scalars.
// Nodes as walked: the root, the anchored list (1 + 9 = 10 nodes) once written and `lists` - 1
// times through its alias, and the scalars: 1 + 10 lists + scalars.
std::string aliased_lists(int lists, int scalars) {
  std::string text = "[&a [1, 1, 1, 1, 1, 1, 1, 1, 1]";
  for (int i = 1; i < lists; ++i) text += ", *a";
  for (int i = 0; i < scalars; ++i) text += ", 1";
  return text + "]\n";
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

TEST_CASE("YAML: aliases count as the nodes they expand to, up to max_yaml_nodes", "[config][yaml]") {
  REQUIRE(dem::max_yaml_nodes == 1'000'000);
  // 1 + 10 x 99,999 + 9 = 1,000,000 nodes: read; one scalar more: refused, naming the line.
  const YAML::Node at_bound = dem::parse_yaml(aliased_lists(99'999, 9), "bound.yaml");
  CHECK(at_bound.size() == 99'999 + 9);
  CHECK(at_bound[99'998].size() == 9);
  CHECK_THROWS_WITH(dem::parse_yaml(aliased_lists(99'999, 10), "bound.yaml"),
                    "bound.yaml: line 1: more than 1000000 YAML nodes once its aliases (*name) are expanded, as a reader walks "
                    "them (an alias bomb?)");
  // An alias is counted where it stands, however many aliases of aliases lead there.
  CHECK(dem::parse_yaml("a: &a [1, 2]\nb: &b [*a, *a]\nc: [*b, *b]\n", "small.yaml")["c"][1][0][1].as<int>() == 2);
}

TEST_CASE("YAML: an alias bomb is refused at once, naming the file and the line", "[config][yaml]") {
  const std::string bomb = alias_bomb();
  REQUIRE(bomb.size() < 1024);
  const auto start = std::chrono::steady_clock::now();
  // Line 6: a5 holds 10 aliases of a4 (11,111 nodes each), and the tree passes 10^6 there.
  CHECK_THROWS_WITH(dem::scene_from_text(bomb, "bomb.yaml"),
                    Catch::Matchers::StartsWith("bomb.yaml: line 6: more than 1000000 YAML nodes once its aliases"));
  // The measure reads the text once: milliseconds. Walking the tree (what readers did) took
  // minutes; a second is far above the one and far below the other.
  CHECK(seconds_since(start) < 1.0);
}

TEST_CASE("YAML: an alias inside the node it names is refused (the tree would be a cycle)", "[config][yaml]") {
  CHECK_THROWS_WITH(dem::parse_yaml("name: x\nloop: &a [1, *a]\n", "cycle.yaml"),
                    "cycle.yaml: line 2: an alias inside the node its anchor names: the tree would contain itself without end");
  CHECK_THROWS_WITH(dem::parse_yaml("m: &m {k: {j: *m}}\n", "cycle.yaml"), Catch::Matchers::StartsWith("cycle.yaml: line 1: an alias inside"));
}

TEST_CASE("YAML: the nesting is measured with aliases expanded", "[config][yaml]") {
  // Under the root mapping, l0 nests 4 lists and each lk 4 lists around an alias of l(k-1):
  // lk reaches 1 + 4 (k + 1) levels when walked, though no line of the text nests more than 5.
  const auto text = [](int last) {
    std::string t = "l0: &l0 [[[[1]]]]\n";
    for (int k = 1; k <= last; ++k) t += "l" + std::to_string(k) + ": &l" + std::to_string(k) + " [[[[*l" + std::to_string(k - 1) + "]]]]\n";
    return t;
  };
  CHECK_NOTHROW(dem::parse_yaml(text(6), "deep.yaml"));  // 29 levels
  // l7: 33 levels, on line 8.
  CHECK_THROWS_WITH(dem::parse_yaml(text(7), "deep.yaml"), "deep.yaml: nested more than 32 levels deep (line 8; a scene or study nests a few)");
}

TEST_CASE("YAML: every reader of the project goes through parse_yaml or load_yaml", "[config][yaml]") {
  // yaml-cpp's own entry points measure nothing: outside config/yaml_section.cpp they are not called.
  const std::regex direct(R"(YAML::(Load|LoadFile|LoadAll|LoadAllFromFile)\s*\()");
  std::vector<std::string> found;
  for (const char* folder : {"engine", "pipeline", "validation", "calibration"})
    for (const auto& e : fs::recursive_directory_iterator(fs::path(DEM_SOURCE_DIR) / folder)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      if (e.path().filename() == "yaml_section.cpp") continue;
      std::ifstream in(e.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n)
        if (std::regex_search(line, direct)) found.push_back(e.path().string() + ":" + std::to_string(n));
    }
  INFO([&] {
    std::string s;
    for (const auto& f : found) s += f + "\n";
    return s;
  }());
  CHECK(found.empty());
}

TEST_CASE("YAML: an alias bomb as a scene, study, calibration or reference file is refused by every tool", "[yaml][cli]") {
  const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/";
  const std::string dir = dem::test::scratch_dir("yaml_bomb");
  const std::string bomb = alias_bomb();
  dem::test::write_text(dir + "/bomb.yaml", bomb);
  // A study whose preparation is the bomb (the pipeline reads the preparation as a template).
  const std::string src = DEM_SOURCE_DIR;
  dem::test::write_text(dir + "/study.yaml", "name: s\noutput: results\npreparation: bomb.yaml\ndensities: [{name: dense, friction: 0.0}]\n"
                                             "tests: [{name: t, scene: " + src + "/scenes/tests/triaxial_drained.yaml}]\n"
                                             "profiles: {quick: {lattice: 4, seeds: 1}}\n");
  dem::test::write_text(dir + "/good_study.yaml", "name: s\noutput: results\npreparation: " + src + "/scenes/prepare_dense.yaml\n"
                                                  "densities: [{name: dense, friction: 0.0}]\n"
                                                  "tests: [{name: t, scene: " + src + "/scenes/tests/triaxial_drained.yaml}]\n"
                                                  "profiles: {quick: {lattice: 4, seeds: 1}}\n");
  dem::test::write_text(dir + "/cal.yaml", "name: c\nstudy: good_study.yaml\nreferences: bomb.yaml\nreport: report\n"
                                           "parameters: [{name: friction, keys: material.friction, uniform: [0.1, 0.9]}]\n");
  fs::create_directories(dir + "/results");
  struct Case {
    std::string what, command, file;
  };
  const std::vector<Case> cases = {  // each error names the file as the tool was given it
      {"dem run", "'" + bin + "dem' run bomb.yaml --out r.h5", "bomb.yaml"},
      {"pipeline --plan, the study", "'" + bin + "pipeline' bomb.yaml --plan", "bomb.yaml"},
      {"pipeline --plan, its preparation", "'" + bin + "pipeline' study.yaml --plan --profile quick", "bomb.yaml"},
      {"calibrate, the calibration file", "'" + bin + "calibrate' bomb.yaml --plan", "bomb.yaml"},
      {"calibrate, its references", "'" + bin + "calibrate' cal.yaml --plan", "bomb.yaml"},
      {"validate, the references", "'" + bin + "validate' --results results --references bomb.yaml --out out", "bomb.yaml"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const auto start = std::chrono::steady_clock::now();
    // `timeout` turns a tool that walks the 10^9 nodes into exit 124 instead of a stuck test.
    const auto r = dem::test::run_command("cd '" + dir + "' && timeout 60 " + c.command + " 2>&1");
    const double took = seconds_since(start);
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("more than 1000000 YAML nodes once its aliases") != std::string::npos);
    CHECK(r.out.find(c.file) != std::string::npos);
    CHECK(r.out.find("line 6") != std::string::npos);
    CHECK(took < 10.0);  // a tool's start and its refusal; walking the bomb took minutes
  }
}
