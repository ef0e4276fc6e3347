// Which runs of a study a reference row reads (validation/judge/row_runs.hpp): its selectors against the
// names of a hand-made manifest, and the refusals, each naming the row, the key and the study's names.
#include <catch2/catch.hpp>

#include "config/yaml_section.hpp"
#include "judge/row_runs.hpp"

using validation::ManifestLine;

namespace {

// A study of variants a and b, densities loose and dense, tests t1 and t2, seeds 1 and 2; the
// preparation lines have test "-".
std::vector<ManifestLine> manifest(bool variants = true) {
  std::vector<ManifestLine> m;
  for (const std::string seed : {"1", "2"})
    for (const std::string& v : variants ? std::vector<std::string>{"a", "b"} : std::vector<std::string>{"-"})
      for (const std::string d : {"loose", "dense"})
        for (const std::string t : {"-", "t1", "t2"})
          m.push_back({v, d, t, "run", "/elsewhere/seed" + seed + "/" + d + "_" + t + ".h5", "-", false, "as written", seed});
  return m;
}

const std::string origin = "refs.yaml: rows[0] (\"x\")";

validation::Row row(const std::string& quantity, const std::string& variant, const std::string& density, const std::string& test) {
  validation::Row r;
  r.name = "x", r.quantity = quantity, r.variant = variant, r.density = density, r.test = test, r.origin = origin;
  return r;
}

std::string refusal(const validation::Row& r, const std::vector<ManifestLine>& m) {
  try {
    validation::resolve_runs(r, m, "DIR/runs.tsv");
  } catch (const dem::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a row's runs: its variant, density and test, or the study's only one", "[references][selectors]") {
  const auto m = manifest();
  auto r = validation::resolve_runs(row("peak_friction_angle", "b", "dense", "t2"), m, "DIR/runs.tsv");
  CHECK(r.variant == "b");
  CHECK(r.density == "dense");
  CHECK_FALSE(r.preparation);
  CHECK(r.tests == std::vector<std::string>{"t2"});
  r = validation::resolve_runs(row("peak_friction_angle", "a", "loose", ""), m, "DIR/runs.tsv");  // no test: every test
  CHECK(r.tests == std::vector<std::string>{"t1", "t2"});
  r = validation::resolve_runs(row("void_ratio_after_preparation", "a", "loose", ""), m, "DIR/runs.tsv");
  CHECK(r.preparation);
  CHECK(r.tests.empty());
  r = validation::resolve_runs(row("ev_lead", "a", "loose", "t1"), m, "DIR/runs.tsv");  // an ordering reads every test
  CHECK(r.tests == std::vector<std::string>{"t1", "t2"});
  // A study without variants ("-" in runs.tsv) and with one density needs neither named.
  std::vector<ManifestLine> one;
  for (const ManifestLine& l : manifest(false))
    if (l.density == "dense") one.push_back(l);
  r = validation::resolve_runs(row("ev_growth", "", "", ""), one, "DIR/runs.tsv");
  CHECK(r.variant == "-");
  CHECK(r.density == "dense");
  CHECK(r.tests == std::vector<std::string>{"t1", "t2"});
}

TEST_CASE("a row's selectors that the study does not have are refused, with its names", "[references][selectors]") {
  const auto m = manifest();
  CHECK(refusal(row("ev_growth", "c", "loose", ""), m) == "refs.yaml: rows[0] (\"x\").variant: the study (DIR/runs.tsv) has no variant 'c'; its variants: a, b");
  CHECK(refusal(row("ev_growth", "", "loose", ""), m) ==
        "refs.yaml: rows[0] (\"x\").variant: the study (DIR/runs.tsv) has 2 variants (a, b): name the one this row reads with `variant`");
  CHECK(refusal(row("ev_growth", "a", "medium", ""), m) == "refs.yaml: rows[0] (\"x\").density: the study (DIR/runs.tsv) has no density 'medium'; its densities: loose, dense");
  CHECK(refusal(row("ev_growth", "a", "loose", "t3"), m) == "refs.yaml: rows[0] (\"x\").test: the study (DIR/runs.tsv) has no test 't3' of density loose; its tests: t1, t2");
  CHECK(refusal(row("void_ratio_after_preparation", "a", "loose", "t1"), m) ==
        "refs.yaml: rows[0] (\"x\").test: quantity 'void_ratio_after_preparation' is read from the preparation, not a test: leave `test` out");
  CHECK(refusal(row("ev_lag", "a", "loose", ""), m) ==
        "refs.yaml: rows[0] (\"x\").test: quantity 'ev_lag' compares one test with the others: name it with `test` (the study's tests: t1, t2)");
  CHECK(refusal(row("ev_growth", "a", "", ""), m) ==
        "refs.yaml: rows[0] (\"x\").density: the study (DIR/runs.tsv) has 2 densities (loose, dense): name the one this row reads with `density`");
  CHECK_THAT(refusal(row("ev_growth", "a", "loose", ""), manifest(false)), Catch::Contains("has no variants, so 'a' names nothing"));
}
