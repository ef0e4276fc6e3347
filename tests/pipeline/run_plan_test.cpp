// The pipeline's plan of the paper study: runs, dependencies, resolved scenes and input hashes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "config/study_config.hpp"
#include "exec/scheduler.hpp"
#include "io/particle_csv.hpp"
#include "plan/run_plan.hpp"

namespace {
const std::string study_file = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml";
const std::string out = std::string(DEM_BINARY_DIR) + "/test_tmp/plan";
}  // namespace

TEST_CASE("content_hash is FNV-1a 64", "[pipeline]") {
  // Published FNV-1a 64 test vectors: "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c.
  CHECK(pipeline::content_hash("") == "cbf29ce484222325");
  CHECK(pipeline::content_hash("a") == "af63dc4c8601ec8c");
}

TEST_CASE("the paper study plans a preparation per density and every test after it", "[pipeline]") {
  const pipeline::Study study = pipeline::load_study(study_file);
  const auto runs = pipeline::plan_study(study, study.profile("quick"), out, "engine-A");
  const std::size_t samples = study.profile("quick").seeds.size();
  CHECK(samples == 3);                    // the quick profile's ensemble
  CHECK(study.profile("paper").seeds.size() == 5);
  REQUIRE(runs.size() == samples * 3 * (1 + 5));
  std::set<std::string> names;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& r = runs[i];
    names.insert(r.name);
    const bool prep = r.name.find("_prepare") != std::string::npos;
    if (prep) {
      CHECK(r.depends_on == -1);
      // The quick profile's lattice: 10^3 spheres, with the density's friction.
      const dem::SceneConfig s = dem::scene_from_text(r.scene_text, r.scene_file);
      CHECK(s.particles.lattice.n[0] == 10);
    } else {
      REQUIRE(r.depends_on >= 0);
      const auto& p = runs[static_cast<std::size_t>(r.depends_on)];
      CHECK(p.name.substr(0, p.name.find('_')) == r.name.substr(0, r.name.find('_')));  // same sample and density
      CHECK(static_cast<std::size_t>(r.depends_on) < i);                             // planned before
      const dem::SceneConfig s = dem::scene_from_text(r.scene_text, r.scene_file);
      CHECK(s.particles.path == std::filesystem::absolute(p.result).string());
      // max_repeat: 2 caps every repeat block of the quick profile.
      for (const auto& item : s.stages[0].path) CHECK(item.repeat <= 2);
    }
    CHECK(r.cost > 0);
  }
  CHECK(names.size() == runs.size());
  const dem::SceneConfig loose = dem::scene_from_text(runs[0].scene_text, runs[0].scene_file);
  CHECK(std::get<dem::LinearFrictionLaw>(loose.material.law).tangential.mu == 0.5);
}

TEST_CASE("the manifest names the engine its input hashes are planned for, and each run's hash", "[pipeline]") {
  const pipeline::Study study = pipeline::load_study(study_file);
  const auto runs = pipeline::plan_study(study, study.profile("quick"), out + "/manifest", "engine-A schema 4");
  pipeline::write_manifest(runs, study, out + "/manifest", "engine-A schema 4");
  std::ifstream in(out + "/manifest/runs.tsv");
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line == "# engine source engine-A schema 4");
  REQUIRE(std::getline(in, line));
  CHECK(line.rfind("# variant", 0) == 0);
  std::size_t listed = 0;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, '\t');) f.push_back(cell);
    REQUIRE(f.size() == 10);
    const auto run = std::find_if(runs.begin(), runs.end(), [&](const pipeline::PlannedRun& r) { return r.name == f[3]; });
    REQUIRE(run != runs.end());
    CHECK(f[9] == run->hash);
    ++listed;
  }
  CHECK(listed == runs.size());
}

TEST_CASE("input hashes change with the engine, the scene and the sample a test starts from", "[pipeline]") {
  const pipeline::Study study = pipeline::load_study(study_file);
  const auto a = pipeline::plan_study(study, study.profile("quick"), out, "engine-A");
  const auto a2 = pipeline::plan_study(study, study.profile("quick"), out, "engine-A");
  const auto b = pipeline::plan_study(study, study.profile("quick"), out, "engine-B");
  const auto paper = pipeline::plan_study(study, study.profile("paper"), out, "engine-A");
  std::set<std::string> hashes;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].hash == a2[i].hash);      // deterministic
    CHECK(a[i].hash != b[i].hash);       // engine version
    CHECK(a[i].hash != paper[i].hash);   // profile changes the resolved scene (preparation) or the sample (tests)
    hashes.insert(a[i].hash);
  }
  CHECK(hashes.size() == a.size());
}

TEST_CASE("a copied or renamed study, writing elsewhere, has the same input hashes", "[pipeline]") {
  // The resolved scene's header names the study file and a test names its sample by path: neither
  // changes what a run computes, so neither may change its hash (else a copy reruns everything).
  const std::string copy = std::string(DEM_BINARY_DIR) + "/test_tmp/plan_copy/studies/renamed.yaml";
  std::filesystem::create_directories(std::filesystem::path(copy).parent_path());
  std::filesystem::copy_file(study_file, copy, std::filesystem::copy_options::overwrite_existing);
  // The copy's relative scene paths must still resolve: point them at the shipped scenes.
  std::ifstream in(copy);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  for (std::size_t at; (at = text.find("../../scenes/")) != std::string::npos;)
    text.replace(at, 13, std::string(DEM_SOURCE_DIR) + "/scenes/");
  std::ofstream(copy) << text;
  const pipeline::Study original = pipeline::load_study(study_file);
  const pipeline::Study renamed = pipeline::load_study(copy);
  const auto a = pipeline::plan_study(original, original.profile("quick"), out, "engine-A");
  const auto b = pipeline::plan_study(renamed, renamed.profile("quick"), out + "_elsewhere", "engine-A");
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].scene_text != b[i].scene_text);  // the header (and a test's sample path) differ
    CHECK(a[i].hash == b[i].hash);
  }
}

TEST_CASE("a result counts as up to date only if complete with the same input hash", "[pipeline]") {
  std::filesystem::create_directories(out);
  const std::string missing = out + "/does_not_exist.h5";
  CHECK_FALSE(pipeline::up_to_date(missing, "x"));
  const std::string garbage = out + "/garbage.h5";
  { std::ofstream(garbage) << "not an HDF5 file"; }
  CHECK_FALSE(pipeline::up_to_date(garbage, "x"));  // a truncated or corrupt file is run again
  // ... and the pipeline says why it does not reuse a file that is there.
  CHECK(pipeline::reuse_problem(missing, "x") == "not run yet");
  CHECK(pipeline::reuse_problem(garbage, "x").rfind("unreadable, truncated or corrupt (", 0) == 0);
  CHECK(pipeline::reuse_problem(out, "x") == "not a regular file");
}

TEST_CASE("a study with an unknown profile or a missing scene is refused naming the key", "[pipeline]") {
  const pipeline::Study study = pipeline::load_study(study_file);
  CHECK_THROWS_WITH(study.profile("huge"), Catch::Matchers::Contains("no profile 'huge'") &&
                                               Catch::Matchers::Contains("paper, quick"));
  std::filesystem::create_directories(out);
  const std::string bad = out + "/bad_study.yaml";
  {
    std::ofstream f(bad);
    f << "name: bad\noutput: x\npreparation: nowhere.yaml\ndensities: [{name: loose, friction: 0.5}]\n"
         "tests: [{name: t, scene: nowhere.yaml}]\nprofiles: {paper: {}, quick: {}}\n";
  }
  CHECK_THROWS_WITH(pipeline::load_study(bad), Catch::Matchers::Contains("preparation: no such file"));
}

// A preparation may read its spheres from a file (pipeline/studies/fcc_thornton.yaml reads a CSV of
// an FCC array): the profile's lattice must not be added to it (a scene with both is refused), the
// file is named from the template's folder (the resolved scene lives elsewhere), the cost counts
// the file's spheres, and a seed, which no file obeys, is refused naming the key.
TEST_CASE("a preparation from a particle CSV keeps its file's spheres", "[pipeline]") {
  const std::string fcc = std::string(DEM_SOURCE_DIR) + "/pipeline/studies/fcc_thornton.yaml";
  const pipeline::Study study = pipeline::load_study(fcc);
  const auto runs = pipeline::plan_study(study, study.profile("paper"), out + "_fcc", "engine-A");
  REQUIRE(runs.size() == 1 + 4);
  const dem::SceneConfig prep = dem::scene_from_text(runs[0].scene_text, runs[0].scene_file);
  CHECK(prep.particles.kind == dem::ParticleSource::Kind::Csv);
  CHECK(prep.particles.path ==
        (std::filesystem::path(DEM_SOURCE_DIR) / "scenes/literature/fcc_108.csv").lexically_normal().string());
  CHECK(runs[0].scene_text.find("lattice") == std::string::npos);
  // 108 spheres (3^3 cells of 4) times the steps: the cost of a test is 108 x 0.3 s / 1 us.
  CHECK(runs[1].cost == Approx(108.0 * 300000).epsilon(1e-9));

  const std::filesystem::path dir = std::filesystem::path(out) / "fcc_seeded";
  std::filesystem::create_directories(dir);
  std::ifstream in(fcc);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "paper: {lattice: 20}";
  REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), "paper: {lattice: 20, seeds: 2}");
  const std::string relative = "../../scenes/literature/";
  for (std::size_t at; (at = text.find(relative)) != std::string::npos;)
    text.replace(at, relative.size(), std::string(DEM_SOURCE_DIR) + "/scenes/literature/");
  std::ofstream(dir / "seeded.yaml") << text;
  const pipeline::Study seeded = pipeline::load_study((dir / "seeded.yaml").string());
  try {
    pipeline::plan_study(seeded, seeded.profile("paper"), (dir / "out").string(), "engine-A");
    FAIL("a seeded CSV preparation was planned");
  } catch (const std::exception& e) {
    CHECK_THAT(e.what(), Catch::Contains("profiles.paper.seeds") && Catch::Contains("particles.lattice"));
  }
}

// The CSV the FCC study prepares from is Thornton's array: 3^3 cubic cells of 4 spheres of 4 mm in
// the scene's cell, each touching exactly 12 neighbours (at distance d, within round-off of the
// 17-digit positions) and no two closer. The FCC's next shell is at sqrt(2) d.
TEST_CASE("the FCC study's CSV is a touching face-centred cubic array", "[pipeline]") {
  const std::string dir = std::string(DEM_SOURCE_DIR) + "/scenes/literature/";
  const dem::SceneConfig prep = dem::load_scene(dir + "fcc_prepare.yaml");
  REQUIRE(prep.particles.kind == dem::ParticleSource::Kind::Csv);
  const dem::PeriodicCell cell(prep.particles.cell_m);
  dem::Particles p;
  dem::read_particle_csv(prep.particles.path, cell, prep.material.density_kg_per_m3, p);
  REQUIRE(p.size() == 108);
  const double d = 4e-3;
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(p.radius[i] == d / 2);
    int touching = 0;
    double nearest_other = 1;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const double r = cell.branch(p.s[i], p.s[j]).norm();
      if (std::abs(r - d) < 1e-15) ++touching;
      else nearest_other = std::min(nearest_other, r);
    }
    CHECK(touching == 12);
    CHECK(nearest_other == Approx(std::sqrt(2.0) * d).epsilon(1e-12));
  }
}
