// Ensembles of samples (study key seeds) and the decisions study's variant keys: every run once
// per seed in its own folder, on that seed's sample; per_test changes one test, per_density one
// density's tests; shearing with the preparation friction follows the density; bad input names the key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "config/scene_config.hpp"
#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"

namespace fs = std::filesystem;

namespace {

const std::string two_densities =
    "name: e\noutput: out\npreparation: prep.yaml\n"
    "densities: [{name: loose, friction: 0.5}, {name: dense, friction: 0.0}]\n"
    "tests: [{name: test1, scene: test.yaml}, {name: test2, scene: test.yaml}]\n";

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  pipeline::test::write_tiny_scenes(dir, "1.0e-4", "1.0e-4");
  return dir;
}

pipeline::Study load(const fs::path& dir, const std::string& text) {
  std::ofstream(dir / "study.yaml") << text;
  return pipeline::load_study((dir / "study.yaml").string());
}

std::map<std::string, pipeline::PlannedRun> plan(const fs::path& dir, const std::string& text, const std::string& profile = "quick") {
  const pipeline::Study study = load(dir, text);
  std::map<std::string, pipeline::PlannedRun> m;
  for (const auto& r : pipeline::plan_study(study, study.profile(profile), (dir / "out").string(), "engine-A")) m[r.name] = r;
  return m;
}

dem::SceneConfig scene(const pipeline::PlannedRun& r) { return dem::scene_from_text(r.scene_text, r.scene_file); }

}  // namespace

TEST_CASE("seeds: every run once per sample, in the sample's folder, on the sample's own grains", "[pipeline][ensemble]") {
  const fs::path dir = fresh("ensemble_seeds");
  const auto r = plan(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2, seeds: [7, 3]}}\n");
  REQUIRE(r.size() == 12);  // 2 seeds x 2 densities x (preparation + 2 tests)
  for (const char* seed : {"seed7", "seed3"})
    for (const char* run : {"loose_prepare", "loose_test1", "loose_test2", "dense_prepare", "dense_test1", "dense_test2"}) {
      const std::string name = std::string(seed) + "/" + run;
      REQUIRE(r.count(name) == 1);
      CHECK(r.at(name).result == (dir / "out" / seed / (std::string(run) + ".h5")).string());
    }
  CHECK(scene(r.at("seed7/loose_prepare")).particles.lattice.seed == 7);
  CHECK(scene(r.at("seed3/dense_prepare")).particles.lattice.seed == 3);
  CHECK(*r.at("seed7/dense_test2").seed == 7);
  // A test starts from its own seed's sample, and its hash follows that sample's.
  CHECK(scene(r.at("seed3/loose_test1")).particles.path == fs::absolute(r.at("seed3/loose_prepare").result).string());
  CHECK(r.at("seed3/loose_test1").hash != r.at("seed7/loose_test1").hash);
  // The profile's seeds override the study's; `seeds: N` means 1..N; without seeds, one sample as before.
  const auto paper = plan(dir, two_densities + "seeds: 2\nprofiles: {paper: {lattice: 2}, quick: {lattice: 2, seeds: [5]}}\n", "paper");
  CHECK(paper.count("seed1/loose_prepare") == 1);
  CHECK(paper.count("seed2/dense_test2") == 1);
  CHECK(paper.size() == 12);
  const auto single = plan(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n");
  CHECK(single.count("loose_prepare") == 1);
  CHECK_FALSE(single.at("loose_prepare").seed);
  CHECK(scene(single.at("loose_prepare")).particles.lattice.seed == 1);  // the template's
}

TEST_CASE("seeds: bad input names the key", "[pipeline][ensemble]") {
  const fs::path dir = fresh("ensemble_bad");
  const std::string profiles = "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n";
  const auto message = [&](const std::string& text) {
    try {
      load(dir, text);
    } catch (const dem::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message(two_densities + "seeds: 0\n" + profiles), Catch::Contains("seeds") && Catch::Contains("[1, 1000]"));
  CHECK_THAT(message(two_densities + "seeds: [1, 2, 1]\n" + profiles), Catch::Contains("listed twice"));
  CHECK_THAT(message(two_densities + "seeds: [-1]\n" + profiles), Catch::Contains(">= 0"));
  CHECK_THAT(message(two_densities + "seeds: many\n" + profiles), Catch::Contains("seeds"));
  CHECK_THAT(message(two_densities + "seeds: 2\n" + profiles + "variants: [{name: a, prepare: {particles.lattice.seed: 4}}]\n"),
             Catch::Contains("prepare.particles.lattice.seed") && Catch::Contains("seeds choose the samples"));
  // Found by a hostile sweep: the same key in preparation_set made seed 2 a copy of seed 1, and
  // validate judged "2 samples" with sd 0. Every way of setting the seed is swept: the key itself,
  // and the mappings around it, which replace it (the pipeline sets the seed before the overrides).
  CHECK_THAT(message(two_densities + "seeds: 2\n" + profiles + "preparation_set: {particles.lattice.seed: 4}\n"),
             Catch::Contains("study.yaml: preparation_set.particles.lattice.seed: the study's seeds choose the samples; "
                             "preparation_set cannot set the seed of an ensemble"));
  CHECK_THAT(message(two_densities + profiles + "preparation_set: {particles.lattice: {n: [2, 2, 2], spacing: 5.0e-3}}\n"
                     "variants: [{name: a}]\n" "seeds: 2\n"),
             Catch::Contains("preparation_set.particles.lattice: replaces particles.lattice, and with it the seed"));
  CHECK_THAT(message(two_densities + "seeds: [3, 4]\n" + profiles + "variants: [{name: a, prepare: {particles: {csv: p.csv, cell: [1, 1, 1]}}}]\n"),
             Catch::Contains("prepare.particles: replaces particles, and with it the seed"));
  // A profile's seeds make an ensemble too; without seeds the template's one sample may take any seed.
  CHECK_THAT(message(two_densities + "profiles: {paper: {lattice: 2, seeds: 2}}\npreparation_set: {particles.lattice.seed: 4}\n"),
             Catch::Contains("preparation_set.particles.lattice.seed"));
  CHECK(message(two_densities + profiles + "preparation_set: {particles.lattice.seed: 4}\n") == "accepted");
  CHECK_THAT(message(two_densities + profiles + "variants: [{name: a, per_test: {test9: {numerics.time_step: 1.0e-6}}}]\n"),
             Catch::Contains("per_test.test9") && Catch::Contains("test1, test2"));
  CHECK_THAT(message(two_densities + profiles + "variants: [{name: a, per_density: {medium: {material.friction: 0.2}}}]\n"),
             Catch::Contains("per_density.medium") && Catch::Contains("loose, dense"));
  CHECK_THAT(message(two_densities + profiles + "variants: [{name: a, per_density: []}]\n"), Catch::Contains("per_density"));
}

TEST_CASE("per_test changes one test; shearing with the preparation friction follows the density", "[pipeline][ensemble]") {
  const fs::path dir = fresh("ensemble_variants");
  const auto r = plan(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n"
                                           "variants:\n"
                                           "  - {name: base}\n"
                                           "  - {name: slow2, per_test: {test2: {\"stages[0].duration\": 2.0e-4}}}\n"
                                           "  - {name: prepmu, shear_with_preparation_friction: true}\n");
  CHECK(scene(r.at("slow2_loose_test2")).stages[0].duration_s == 2e-4);
  CHECK(scene(r.at("slow2_loose_test1")).stages[0].duration_s == 1e-4);  // the other test as written ...
  CHECK(r.at("slow2_loose_test1").hash == r.at("base_loose_test1").hash);  // the same computation (join_studies copies it)
  CHECK(dem::friction_coefficient(scene(r.at("prepmu_dense_test1")).material.law) == 0.0);  // the dense sample's preparation friction
  CHECK(dem::friction_coefficient(scene(r.at("prepmu_loose_test1")).material.law) == 0.5);
  CHECK(dem::friction_coefficient(scene(r.at("base_dense_test1")).material.law) == 0.5);   // the test scene's shearing friction
  // per_density: the named density's tests only; its preparation and the other density as written.
  const auto pd = plan(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n"
                                            "variants: [{name: base}, {name: dmu, per_density: {dense: {material.friction: 0.25}}}]\n");
  CHECK(dem::friction_coefficient(scene(pd.at("dmu_dense_test1")).material.law) == 0.25);
  CHECK(dem::friction_coefficient(scene(pd.at("dmu_dense_test2")).material.law) == 0.25);
  CHECK(pd.at("dmu_loose_test1").hash == pd.at("base_loose_test1").hash);
  CHECK(pd.at("dmu_dense_test1").hash != pd.at("base_dense_test1").hash);
  CHECK(pd.count("dmu_dense_prepare") == 0);  // the preparation is base's, shared
  // join_studies: a test whose resolved scene is the baseline's but for its name is a copy of it.
  const pipeline::Study study = load(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n"
                                                          "variants: [{name: base}, {name: slow2, per_test: {test2: {\"stages[0].duration\": 2.0e-4}}}]\n");
  const auto joined = pipeline::join_studies({{"e", pipeline::plan_study(study, study.profile("quick"), (dir / "out").string(), "engine-A")}});
  std::map<std::string, std::string> copy_of;
  for (const auto& run : joined)
    if (run.copy_of >= 0) copy_of[run.name] = joined[static_cast<std::size_t>(run.copy_of)].name;
  // slow2's test1 of each density; and, since the tiny study's two tests are one scene, each test2 of base.
  CHECK(copy_of == std::map<std::string, std::string>{{"slow2_loose_test1", "base_loose_test1"},
                                                      {"slow2_dense_test1", "base_dense_test1"},
                                                      {"base_loose_test2", "base_loose_test1"},
                                                      {"base_dense_test2", "base_dense_test1"}});
}

TEST_CASE("preparation_set reaches every variant's preparation and no test; a variant's own keys win", "[pipeline][ensemble]") {
  const fs::path dir = fresh("ensemble_preparation_set");
  const std::string study = "name: e\noutput: out\npreparation: prep.yaml\n"
                            "preparation_set: {numerics.max_energy_error: 0.5}\n"
                            "densities: [{name: loose, friction: 0.5}]\n"
                            "tests: [{name: test1, scene: test.yaml}]\n"
                            "profiles: {quick: {lattice: 2}}\n";
  const auto r = plan(dir, study + "variants: [{name: base}, {name: own, prepare: {numerics.max_energy_error: 0.2}}]\n");
  CHECK(scene(r.at("base_loose_prepare")).max_energy_error == 0.5);
  CHECK(scene(r.at("own_loose_prepare")).max_energy_error == 0.2);   // the variant's, applied after
  CHECK(scene(r.at("base_loose_test1")).max_energy_error == 0.05);   // the engine's default: tests as written
  // Without variants (the paper study's form) too; an empty or misspelt key is refused with its path.
  CHECK(scene(plan(dir, study).at("loose_prepare")).max_energy_error == 0.5);
  std::string empty = study;
  empty.replace(empty.find("{numerics.max_energy_error: 0.5}"), 32, "{}");
  CHECK_THROWS_WITH(load(dir, empty), Catch::Contains("preparation_set"));
  std::string misspelt = study;
  misspelt.replace(misspelt.find("max_energy_error"), 16, "max_energy_eror");
  CHECK_THROWS_WITH(plan(dir, misspelt), Catch::Contains("max_energy_eror"));
}

TEST_CASE("the input hash covers the bytes of the particle file a preparation reads", "[pipeline][inputs]") {
  const fs::path dir = fresh("inputs_csv");
  const auto write_csv = [&](const std::string& second_radius) {
    std::ofstream(dir / "parts.csv") << "x,y,z,radius\n0.005,0.005,0.005,0.002\n0.015,0.005,0.005," << second_radius << "\n";
  };
  const std::string study = two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\n"
                            "variants:\n"
                            "  - {name: lattice}\n"
                            "  - {name: csv, prepare: {particles: {csv: parts.csv, cell: [0.02, 0.02, 0.02]}}}\n";
  write_csv("0.0018");
  const auto a = plan(dir, study);
  const auto same = plan(dir, study);
  write_csv("0.0017");  // the same file name, other bytes
  const auto b = plan(dir, study);
  CHECK(a.at("csv_loose_prepare").hash == same.at("csv_loose_prepare").hash);
  CHECK(a.at("csv_loose_prepare").hash != b.at("csv_loose_prepare").hash);
  CHECK(a.at("csv_dense_test1").hash != b.at("csv_dense_test1").hash);        // a test follows its sample
  CHECK(a.at("lattice_loose_prepare").hash == b.at("lattice_loose_prepare").hash);  // runs that do not read it stay
  CHECK(a.at("lattice_dense_test2").hash == b.at("lattice_dense_test2").hash);
  fs::remove(dir / "parts.csv");
  CHECK_THROWS_AS(plan(dir, study), dem::ConfigError);
}

TEST_CASE("a variant written by variant_yaml reads back the same in a study", "[pipeline][ensemble]") {
  const fs::path dir = fresh("variant_yaml");
  pipeline::Variant v;
  v.name = "i2s005";
  v.set = {{"damping.form", "local"}};
  v.prepare = {{"stages[0].hold.unbalanced_force_ratio", "0.0031622776601683794"}, {"stages[0].zero_shear_stress", "false"}};
  v.test = {{"material.contact_damping", "0.05"}};
  v.per_test = {{"test2", {{"stages[0].path", "[TC1, {repeat: 2, path: [TC2, TC3]}]"}}}};
  v.per_density = {{"dense", {{"material.friction", "0.125"}}}};
  const std::string yaml = pipeline::variant_yaml(v);
  INFO(yaml);
  const pipeline::Study study = load(dir, two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2}}\nvariants: [" + yaml + "]\n");
  REQUIRE(study.variants.size() == 1);
  const pipeline::Variant& back = study.variants[0];
  CHECK(back.name == v.name);
  CHECK(back.set == v.set);
  CHECK(back.prepare == v.prepare);
  CHECK(back.test == v.test);
  CHECK(back.per_test == v.per_test);
  CHECK(back.per_density == v.per_density);
  CHECK_FALSE(back.shear_with_preparation_friction);
}

TEST_CASE("a variant's own seeds replace the profile's for it alone; --variant keeps some variants", "[pipeline][ensemble]") {
  const fs::path dir = fresh("ensemble_variant_seeds");
  const std::string text = two_densities + "profiles: {paper: {lattice: 2}, quick: {lattice: 2, seeds: 2}}\n"
                           "variants: [{name: ref}, {name: big, prepare: {particles.lattice.n: [3, 3, 3]}, seeds: [2, 5, 6]}]\n";
  const auto r = plan(dir, text);
  // ref on seeds 1, 2 and big on 2, 5, 6: 5 samples x 2 densities x (preparation + 2 tests).
  CHECK(r.size() == 30);
  CHECK(r.count("seed1/ref_loose_prepare") == 1);
  CHECK(r.count("seed5/ref_loose_prepare") == 0);
  CHECK(r.count("seed1/big_loose_prepare") == 0);
  for (const char* s : {"seed2", "seed5", "seed6"}) CHECK(r.count(std::string(s) + "/big_dense_test2") == 1);
  CHECK(scene(r.at("seed6/big_dense_prepare")).particles.lattice.seed == 6);
  CHECK(scene(r.at("seed6/big_dense_prepare")).particles.lattice.n[0] == 3);

  // Own seeds without an ensemble to replace: refused, naming the key.
  const auto message = [&](const std::string& t, const std::string& profile) {
    try {
      plan(dir, t, profile);
    } catch (const dem::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message(two_densities + "profiles: {paper: {lattice: 2}}\nvariants: [{name: a, seeds: 3}]\n", "paper"),
             Catch::Contains("seeds") && Catch::Contains("no seeds"));
  // An ensemble in one profile only: a profile without seeds has no samples to replace.
  CHECK_THAT(message(text, "paper"), Catch::Contains("big") && Catch::Contains("no seeds"));

  // keep_variants: the named ones in the study's order; an unknown name lists the study's.
  pipeline::Study study = load(dir, text);
  pipeline::keep_variants(study, {"big"});
  REQUIRE(study.variants.size() == 1);
  CHECK(study.variants.front().name == "big");
  CHECK_THROWS_WITH(pipeline::keep_variants(study, {"nope"}), Catch::Contains("--variant nope") && Catch::Contains("big"));
}
