// The worked example of validating a study of your own against your own references
// (examples/own_references/, validation/README.md): the pipeline runs the study at its `tiny`
// profile (2 samples of 216 spheres, each prepared and sheared in drained triaxial compression to
// 40 % axial strain: about 15 s of CPU), then `validate` judges the example's reference file and a
// file made from what the first validation computed: a row whose value lies in the interval is
// consistent, one placed outside it is inconsistent, a trend that holds in every sample is
// consistent, and a row whose run is missing is not judged (exit 1) while the rows that do not read
// that run are judged.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin";
const std::string example = std::string(DEM_SOURCE_DIR) + "/examples/own_references";

std::string quoted(const std::string& s) { return "'" + s + "'"; }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

const nlohmann::json& row_named(const nlohmann::json& validation, const std::string& name) {
  for (const nlohmann::json& r : validation.at("rows"))
    if (r.at("name") == name) return r;
  FAIL("no row named " << name);
  throw std::logic_error("unreachable");
}

std::string exact(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

}  // namespace

TEST_CASE("validate: the worked example, a study and reference file of your own", "[validate][example][references]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "own_references";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path results = dir / "results";
  const auto study = dem::test::run_command(quoted(bin + "/pipeline") + " " + quoted(example + "/study.yaml") + " --profile tiny --out " +
                                            quoted(results.string()) + " -j 1 --threads 1 2>&1");
  INFO(study.out);
  REQUIRE(study.exit_code == 0);
  const auto validate = [&](const std::string& references, const std::string& out) {
    return dem::test::run_command(quoted(bin + "/validate") + " --results " + quoted(results.string()) + " --references " +
                                  quoted(references) + " --out " + quoted((dir / out).string()) + " --profile tiny 2>&1");
  };

  // The example's own file: every row judged on both samples, none must pass, nothing missing: exit 0.
  const auto own = validate(example + "/references.yaml", "example");
  INFO(own.out);
  CHECK(own.exit_code == 0);
  const nlohmann::json first = read_json(dir / "example" / "validation.json");
  std::ifstream refs(example + "/references.yaml");
  std::size_t rows = 0;
  for (std::string line; std::getline(refs, line);) rows += line.rfind("  - name:", 0) == 0;
  CHECK(first.at("total") == rows);
  CHECK(first.at("not_judged") == 0);
  CHECK(first.at("complete") == true);
  for (const nlohmann::json& r : first.at("rows")) {
    CHECK(r.at("n") == 2);
    CHECK((r.at("verdict") == "consistent" || r.at("verdict") == "inconsistent"));
  }

  // References placed by what the first validation computed, so that their verdicts follow from
  // the rules alone (validation/README.md): the interval of one sample is [low, high].
  const nlohmann::json& peak = row_named(first, "peak friction angle (deg)");
  const nlohmann::json& e_cs = row_named(first, "critical-state void ratio");
  const nlohmann::json& phi_cs = row_named(first, "critical-state friction angle (deg)");
  const double peak_low = peak.at("prediction_interval")[0], peak_mean = peak.at("mean");
  const double e_high = e_cs.at("prediction_interval")[1];
  double phi_cs_min = 1e9;
  for (const nlohmann::json& s : phi_cs.at("per_sample")) phi_cs_min = std::min(phi_cs_min, s.at("value").get<double>());
  const fs::path placed = dir / "placed.yaml";
  std::ofstream(placed)
      << "source: \"placed from the first validation's values\"\nrows:\n"
      // The mean lies in the interval: its region [mean, mean] overlaps it.
      << "  - {name: at the mean, quantity: peak_friction_angle, test: compression, reference: " << exact(peak_mean)
      << ", check: within, source: s, reason: r}\n"
      // [high + 0.01, high + 0.03] lies above the interval.
      << "  - {name: above the interval, quantity: critical_state_void_ratio, reference: " << exact(e_high + 0.02)
      << ", check: within, tolerance: 0.01, source: s, reason: r}\n"
      // At most low - 1: below the interval.
      << "  - {name: at most below it, quantity: peak_friction_angle, test: compression, reference: " << exact(peak_low - 1)
      << ", check: at_most, source: s, reason: r}\n"
      // At least the smallest sample's value: holds in both samples, more than half.
      << "  - {name: holds in every sample, rule: majority, quantity: critical_state_friction_angle, reference: " << exact(phi_cs_min)
      << ", check: at_least, source: s, reason: r}\n"
      // Reads the preparation, which is moved away in one of the two samples below.
      << "  - {name: reads the preparation, quantity: void_ratio_after_preparation, reference: 0.6, check: within, tolerance: 1, source: s, reason: r}\n";
  fs::rename(results / "seed1" / "dense_prepare.h5", dir / "dense_prepare.h5");
  const auto second = validate(placed.string(), "placed");
  INFO(second.out);
  CHECK(second.exit_code == 1);  // a row not judged, a result missing
  CHECK_THAT(second.out, Catch::Contains("1 row(s) not judged (fewer than 2 samples with a value): reads the preparation"));
  const nlohmann::json j = read_json(dir / "placed" / "validation.json");
  CHECK(row_named(j, "at the mean").at("verdict") == "consistent");
  CHECK(row_named(j, "above the interval").at("verdict") == "inconsistent");
  CHECK(row_named(j, "at most below it").at("verdict") == "inconsistent");
  CHECK(row_named(j, "holds in every sample").at("verdict") == "consistent");
  CHECK(row_named(j, "holds in every sample").at("holds_in") == 2);
  CHECK(row_named(j, "reads the preparation").at("verdict") == "not judged");
  CHECK(row_named(j, "reads the preparation").at("n") == 1);
  // Only the runs a row reads are needed: the missing preparation is the one file listed, and the
  // rows on the compression tests are judged on both samples.
  CHECK(j.at("missing_results") == nlohmann::json::array({"seed1/dense_prepare.h5"}));
  CHECK(row_named(j, "above the interval").at("n") == 2);
  CHECK(j.at("complete") == false);
  // With the preparation back, everything is read and judged: exit 0.
  fs::rename(dir / "dense_prepare.h5", results / "seed1" / "dense_prepare.h5");
  const auto third = validate(placed.string(), "placed_again");
  CHECK(third.exit_code == 0);
  CHECK(read_json(dir / "placed_again" / "validation.json").at("not_judged") == 0);
}
