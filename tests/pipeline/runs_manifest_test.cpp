// runs.tsv's one declaration (plan/runs_manifest.hpp): what write_manifest writes reads back whole,
// and validation's study/manifest.hpp, which validation/ and calibration/ use, gives the same lines.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "config/study_config.hpp"
#include "plan/run_plan.hpp"
#include "plan/runs_manifest.hpp"
#include "study/manifest.hpp"

namespace fs = std::filesystem;

TEST_CASE("runs.tsv: what the pipeline writes reads back the same, in the pipeline and in validation/", "[pipeline][manifest]") {
  const std::string out = std::string(DEM_BINARY_DIR) + "/test_tmp/runs_manifest";
  fs::remove_all(out);
  const pipeline::Study study = pipeline::load_study(std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml");
  const auto runs = pipeline::plan_study(study, study.profile("quick"), out, "engine-B schema 4");
  pipeline::write_manifest(runs, study, out, "engine-B schema 4");

  const pipeline::RunsManifest m = pipeline::read_runs_manifest(fs::path(out) / "runs.tsv");
  CHECK(m.engine_source == "engine-B schema 4");
  REQUIRE(m.entries.size() == runs.size());  // no variants: each run once
  CHECK(pipeline::manifest_text(m) == [&] {
    std::ifstream in(fs::path(out) / "runs.tsv");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }());  // written back, the same text

  const std::vector<validation::ManifestLine> read = validation::read_manifest(out);
  REQUIRE(read.size() == m.entries.size());
  CHECK(validation::manifest_engine_source(out) == m.engine_source);
  for (std::size_t i = 0; i < read.size(); ++i) {
    const pipeline::ManifestEntry& e = m.entries[i];
    const auto run = std::find_if(runs.begin(), runs.end(), [&](const pipeline::PlannedRun& r) { return r.name == e.run; });
    REQUIRE(run != runs.end());
    CHECK(e.result == run->result);
    CHECK(e.input_hash == run->hash);
    CHECK(e.seed == (run->seed ? std::to_string(*run->seed) : "-"));
    const validation::ManifestLine& l = read[i];
    CHECK(std::tie(l.variant, l.density, l.test, l.run, l.result, l.starts_from, l.settings, l.seed, l.input_hash) ==
          std::tie(e.variant, e.density, e.test, e.run, e.result, e.starts_from, e.settings, e.seed, e.input_hash));
    CHECK(l.may_fail == e.may_fail);
  }
}

TEST_CASE("runs.tsv: a short line is refused with the file and its line", "[pipeline][manifest]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "runs_manifest_short";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "runs.tsv") << "# engine source E\n# columns\n-\tdense\t-\tdense_prepare\tdense_prepare.h5\t-\t0\n";
  CHECK_THROWS_WITH(pipeline::read_runs_manifest(dir / "runs.tsv"), Catch::Contains("runs.tsv: line 3: 7 fields, 8 expected"));
  CHECK_THROWS_WITH(pipeline::read_runs_manifest(dir / "none.tsv"), Catch::Contains("none.tsv: cannot be read"));
  // A run listed twice for a variant would count its sample twice; under two variants it is shared.
  const std::string line = "\tdense\t-\tdense_prepare\tdense_prepare.h5\t-\t0\tas written\n";
  std::ofstream(dir / "runs.tsv") << "# engine source E\n# columns\n" << "fast" << line << "slow" << line << "fast" << line;
  CHECK_THROWS_WITH(pipeline::read_runs_manifest(dir / "runs.tsv"),
                    Catch::Contains("runs.tsv: line 5: the run 'dense_prepare' again for variant 'fast' (line 3 lists it)"));
  CHECK_THROWS_WITH(validation::read_manifest(dir.string()), Catch::Contains("line 5: the run 'dense_prepare' again"));
}
