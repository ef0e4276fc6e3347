// A study's manifest (validation/study/manifest.hpp): where a run's result is in a results folder that
// has moved, the study's names, and its samples in the order of their seeds.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "study/manifest.hpp"

namespace fs = std::filesystem;

TEST_CASE("manifest: names, samples and results under the folder given", "[manifest]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "manifest_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    // Written where the study ran (/ran/there), read where it is now (dir); seeds 10 and 2, in that order.
    std::ofstream runs(dir / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (const std::string seed : {"10", "2"})
      for (const std::string v : {"fast", "slow"}) {
        runs << v << "\tdense\t-\tseed" << seed << "/" << v << "_dense_prepare\t/ran/there/seed" << seed << "/" << v
             << "_dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
        runs << v << "\tdense\tcompression\tseed" << seed << "/" << v << "_dense_compression\t/ran/there/seed" << seed << "/" << v
             << "_dense_compression.h5\tseed" << seed << "/" << v << "_dense_prepare\t0\tas written\t" << seed << "\n";
      }
  }
  const auto m = validation::read_manifest(dir.string());
  REQUIRE(m.size() == 8);
  CHECK(validation::variants_of(m) == std::vector<std::string>{"fast", "slow"});
  CHECK(validation::densities_of(m) == std::vector<std::string>{"dense"});
  CHECK(validation::tests_of(m) == std::vector<std::string>{"compression"});
  CHECK(validation::samples_of(m) == std::vector<std::string>{"seed2", "seed10"});  // by seed, not by text
  CHECK(validation::result_under(dir.string(), m[1]) == (dir / "seed10" / "fast_dense_compression.h5").string());
  // A study of one sample: seed "-", results in the folder itself.
  validation::ManifestLine one{"-", "dense", "-", "dense_prepare", "/ran/there/dense_prepare.h5", "-", false, "as written"};
  CHECK(validation::sample_of(one).empty());
  CHECK(validation::result_under(dir.string(), one) == (dir / "dense_prepare.h5").string());
  CHECK(validation::samples_of({one}) == std::vector<std::string>{""});
  CHECK_THROWS_WITH(validation::read_manifest((dir / "nowhere").string()), Catch::Contains("runs.tsv: no manifest"));
}
