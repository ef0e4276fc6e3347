// A study of your own (pipeline new, config/study_copy.hpp) and a profile that counts cycles as
// cycles (`cycles`, against `max_repeat`'s cap per repeat block).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "config/scene_config.hpp"
#include "config/study_config.hpp"
#include "config/study_copy.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/atomic_file.hpp"
#include "plan/run_plan.hpp"

namespace fs = std::filesystem;

namespace {

const std::string paper = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml";

// The cycles each test of a plan runs: the sum of its stress path's repeat blocks.
std::map<std::string, int> cycles_per_test(const pipeline::Study& study, const pipeline::Profile& profile) {
  std::map<std::string, int> cycles;
  for (const pipeline::PlannedRun& r : pipeline::plan_study(study, profile, std::string(DEM_BINARY_DIR) + "/test_tmp/cycles", "engine-A")) {
    if (r.name.rfind("seed1/loose_test", 0) != 0) continue;
    const dem::SceneConfig s = dem::scene_from_text(r.scene_text, r.scene_file);
    int n = 0;
    for (const dem::PathItem& item : s.stages[0].path) n += item.repeat;
    cycles[r.name.substr(std::string("seed1/loose_").size())] = n;
  }
  return cycles;
}

}  // namespace

TEST_CASE("pipeline new: the copy's paths resolve from its own folder, its name is its stem", "[pipeline][new]") {
  const fs::path dir = fs::path(dem::test::scratch_dir("study_copy")) / "elsewhere" / "deeper";
  fs::create_directories(dir);
  const std::string to = (dir / "my_study.yaml").string();
  pipeline::write_study_copy(paper, to, false);
  const pipeline::Study copy = pipeline::load_study(to);
  const pipeline::Study original = pipeline::load_study(paper);
  CHECK(copy.name == "my_study");
  // The same scene files as the original's, by absolute path (load_study resolves them).
  CHECK(copy.preparation == original.preparation);
  REQUIRE(copy.tests.size() == original.tests.size());
  for (std::size_t i = 0; i < copy.tests.size(); ++i) CHECK(copy.tests[i].scene == original.tests[i].scene);
  // Its own results folder beside it, not the original's.
  CHECK(copy.output == (dir / "results" / "my_study").lexically_normal().string());
  CHECK(copy.profiles.size() == original.profiles.size());
  SECTION("the copy keeps the original's comments and says where it came from") {
    std::ifstream in(to);
    std::string first;
    std::getline(in, first);
    CHECK(first.find("pipeline new") != std::string::npos);
    CHECK(first.find("paper.yaml") != std::string::npos);
  }
  SECTION("an existing file is refused without --force, replaced with it") {
    CHECK_THROWS_WITH(pipeline::write_study_copy(paper, to, false), Catch::Matchers::Contains("exists"));
    CHECK_NOTHROW(pipeline::write_study_copy(paper, to, true));
  }
  SECTION("a copy of the copy in another folder still resolves") {
    const std::string again = (fs::path(dem::test::scratch_dir("study_copy2")) / "again.yaml").string();
    pipeline::write_study_copy(to, again, false);
    CHECK(pipeline::load_study(again).preparation == original.preparation);
  }
}

TEST_CASE("pipeline new and every atomic write leave the user's FILE.tmp alone", "[pipeline][new][integrity]") {
  // Found by a hostile sweep: `pipeline new keep.yaml` wrote its copy to keep.yaml.tmp, a fixed
  // name, and so truncated and then renamed away a file of the user's by that name. The class swept:
  // the study copy, a refused copy (its check fails and the new file is removed), and the shared
  // atomic writer every tool uses (io/atomic_file.hpp). Each must leave keep.yaml.tmp byte for
  // byte, and no file of its own beside it.
  const std::string dir = dem::test::scratch_dir("study_copy_tmp");
  const std::string keep = dir + "/keep.yaml", mine = "the user's own notes\n";
  const auto leftovers = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().rfind("keep.yaml.tmp.", 0) == 0) ++n;
    return n;
  };
  dem::test::write_text(keep + ".tmp", mine);
  pipeline::write_study_copy(paper, keep, false);
  CHECK(pipeline::load_study(keep).name == "keep");
  CHECK(dem::test::read_bytes(keep + ".tmp") == mine);
  CHECK(leftovers() == 0);
  // A copy whose check fails (a study without a preparation scene), with --force over keep.yaml.
  dem::test::write_text(dir + "/broken.yaml", "name: broken\ndensities: [{name: d, friction: 0.5}]\n");
  CHECK_THROWS(pipeline::write_study_copy(dir + "/broken.yaml", keep, true));
  CHECK(pipeline::load_study(keep).name == "keep");  // the earlier copy stays
  CHECK(dem::test::read_bytes(keep + ".tmp") == mine);
  CHECK(leftovers() == 0);
  dem::write_file_atomically(keep, "name: written\n");
  CHECK(dem::test::read_bytes(keep) == "name: written\n");
  CHECK(dem::test::read_bytes(keep + ".tmp") == mine);
  CHECK(leftovers() == 0);
}

TEST_CASE("pipeline new: the rewritten paths, line by line", "[pipeline][new]") {
  // From /a/b/s.yaml to /a/c/d/n.yaml: ../x from /a/b is /a/x, which is ../../x from /a/c/d.
  const std::string text =
      "name: s   # a comment: scene: keep/me.yaml\n"
      "output: ../results/s\n"
      "preparation: \"../x/prep.yaml\"\n"
      "tests:\n"
      "  - {name: t1, scene: ../x/t1.yaml, set: {material.friction: 0.3, output.interval: 500}}\n"
      "variants:\n"
      "  - {name: v, prepare: {particles.csv: here.csv}}\n"
      "  - {name: w, prepare: {particles: {csv: /abs/p.csv, cell: [1, 1, 1]}}}\n";
  const std::string copy = pipeline::study_copy_text(text, "/a/b/s.yaml", "/a/c/d/n.yaml");
  CHECK(copy.find("\nname: n   # a comment: scene: keep/me.yaml\n") != std::string::npos);
  CHECK(copy.find("\noutput: results/n\n") != std::string::npos);
  CHECK(copy.find("\npreparation: \"../../x/prep.yaml\"\n") != std::string::npos);
  CHECK(copy.find("{name: t1, scene: ../../x/t1.yaml, set: {material.friction: 0.3, output.interval: 500}}") != std::string::npos);
  CHECK(copy.find("{particles.csv: ../../b/here.csv}") != std::string::npos);
  CHECK(copy.find("{csv: /abs/p.csv, cell: [1, 1, 1]}") != std::string::npos);  // absolute paths stay
}

TEST_CASE("pipeline new: --from names a shipped study or a file", "[pipeline][new]") {
  const std::string folder = std::string(DEM_SOURCE_DIR) + "/pipeline/studies";
  CHECK(fs::equivalent(pipeline::find_study("paper", {"/nonexistent", folder}), paper));
  CHECK(pipeline::find_study(paper, {}) == paper);
  CHECK_THROWS_WITH(pipeline::find_study("papr", {folder}), Catch::Matchers::Contains("shipped: ") &&
                                                             Catch::Matchers::Contains("paper"));
}

TEST_CASE("profiles: cycles counts the cycles of each test, max_repeat caps each repeat block", "[pipeline][new][cycles]") {
  // The paper's tests have 10 (5 + 5), 5, 5, 5 and 30 (10 + 10 + 5 + 5) cycles in 2, 1, 1, 1 and 4
  // repeat blocks (docs/method.md#stress-paths).
  const pipeline::Study study = pipeline::load_study(paper);
  pipeline::Profile p = study.profile("quick");
  p.max_repeat = 0;
  p.cycles = 0;
  CHECK(cycles_per_test(study, p) == std::map<std::string, int>{{"test1", 10}, {"test2", 5}, {"test3", 5}, {"test4", 5}, {"test5", 30}});
  p.max_repeat = 1;  // one cycle per block: Test 1 runs 2, Test 5 runs 4
  CHECK(cycles_per_test(study, p) == std::map<std::string, int>{{"test1", 2}, {"test2", 1}, {"test3", 1}, {"test4", 1}, {"test5", 4}});
  p.max_repeat = 0;
  p.cycles = 1;  // one cycle of every test
  CHECK(cycles_per_test(study, p) == std::map<std::string, int>{{"test1", 1}, {"test2", 1}, {"test3", 1}, {"test4", 1}, {"test5", 1}});
  p.cycles = 7;  // the blocks in order keep what is left: Test 1 5 + 2, Test 5 7 of its first 10
  CHECK(cycles_per_test(study, p) == std::map<std::string, int>{{"test1", 7}, {"test2", 5}, {"test3", 5}, {"test4", 5}, {"test5", 7}});
}

TEST_CASE("profiles: cycles and max_repeat together are refused, naming the key", "[pipeline][new][cycles]") {
  const fs::path dir = dem::test::scratch_dir("study_cycles_both");
  const std::string copy = (dir / "both.yaml").string();
  pipeline::write_study_copy(paper, copy, true);
  std::string text;
  {
    std::ifstream in(copy);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string from = "quick: {lattice: 10, max_repeat: 2, seeds: 3}";
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), "quick: {lattice: 10, max_repeat: 2, cycles: 1, seeds: 3}");
  std::ofstream(copy, std::ios::trunc) << text;
  CHECK_THROWS_WITH(pipeline::load_study(copy), Catch::Matchers::Contains("profiles.quick.cycles") &&
                                                Catch::Matchers::Contains("not both"));
}

TEST_CASE("pipeline new --output --variant: a study of one variant with its results elsewhere", "[pipeline][new]") {
  // What make open-choices-check writes: calibration_paper.yaml with a calibration's best set as
  // its one variant, its results in a folder named from the current folder.
  const std::string from = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/calibration_paper.yaml";
  const fs::path dir = dem::test::scratch_dir("study_copy_variant");
  const std::string to = (dir / "studies" / "best.yaml").string();
  fs::create_directories(dir / "studies");
  pipeline::CopyChanges changes;
  changes.output = (dir / "results" / "best").string();
  changes.variants = {"{name: best, set: {material.friction: 0.3}}"};
  pipeline::write_study_copy(from, to, false, changes);
  const pipeline::Study copy = pipeline::load_study(to);
  CHECK(copy.name == "best");
  CHECK(copy.output == (dir / "results" / "best").lexically_normal().string());
  REQUIRE(copy.variants.size() == 1);
  CHECK(copy.variants[0].name == "best");
  CHECK(copy.preparation == pipeline::load_study(from).preparation);
  const std::string text = dem::test::read_bytes(to);
  CHECK(text.find("\noutput: ../results/best\n") != std::string::npos);  // written relative to the copy
  SECTION("a study with variants of its own is refused, naming it") {
    const std::string stability = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/stability.yaml";
    CHECK_THROWS_WITH(pipeline::write_study_copy(stability, to, true, changes), Catch::Matchers::Contains("stability.yaml: has variants of its own"));
    CHECK(pipeline::load_study(to).name == "best");  // the earlier copy stays
  }
  SECTION("an empty or multi-line variant is refused, naming --variant") {
    changes.variants = {" "};
    CHECK_THROWS_WITH(pipeline::write_study_copy(from, to, true, changes), Catch::Matchers::Contains("--variant"));
    changes.variants = {"{name: a}\nname: b"};
    CHECK_THROWS_WITH(pipeline::write_study_copy(from, to, true, changes), Catch::Matchers::Contains("one variant on one line"));
  }
}
