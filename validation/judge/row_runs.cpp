#include "judge/row_runs.hpp"

#include <algorithm>

#include "config/yaml_section.hpp"
#include "judge/quantities.hpp"

namespace validation {

namespace {

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

[[noreturn]] void refuse(const Row& row, const std::string& key, const std::string& what) {
  throw dem::ConfigError(row.origin + "." + key + ": " + what);
}

// The value of selector `key`: the row's, which must be one of `names`, or the only one.
std::string select(const Row& row, const std::string& key, const std::string& given, const std::vector<std::string>& names,
                   const std::string& plural, const std::string& study) {
  if (!given.empty()) {
    if (std::find(names.begin(), names.end(), given) != names.end()) return given;
    if (names.empty()) refuse(row, key, "the study (" + study + ") has no " + plural + ", so '" + given + "' names nothing; leave `" + key + "` out");
    refuse(row, key, "the study (" + study + ") has no " + key + " '" + given + "'; its " + plural + ": " + listed(names));
  }
  if (names.size() > 1)
    refuse(row, key, "the study (" + study + ") has " + std::to_string(names.size()) + " " + plural + " (" + listed(names) +
                         "): name the one this row reads with `" + key + "`");
  return names.empty() ? "-" : names.front();
}

}  // namespace

RowRuns resolve_runs(const Row& row, const std::vector<ManifestLine>& manifest, const std::string& study) {
  RowRuns runs;
  runs.variant = select(row, "variant", row.variant, variants_of(manifest), "variants", study);
  runs.density = select(row, "density", row.density, densities_of(manifest), "densities", study);
  std::vector<ManifestLine> of_density;
  for (const ManifestLine& l : manifest)
    if (l.variant == runs.variant && l.density == runs.density) of_density.push_back(l);
  const std::vector<std::string> tests = tests_of(of_density);
  const Reads reads = reads_of(row.quantity);
  if (reads == Reads::Preparation) {
    if (!row.test.empty())
      refuse(row, "test", "quantity '" + row.quantity + "' is read from the preparation, not a test: leave `test` out");
    runs.preparation = true;
    return runs;
  }
  if (tests.empty()) refuse(row, "quantity", "quantity '" + row.quantity + "' reads tests, and the study (" + study + ") has none");
  if (!row.test.empty()) {
    if (std::find(tests.begin(), tests.end(), row.test) == tests.end())
      refuse(row, "test", "the study (" + study + ") has no test '" + row.test + "'" +
                              (runs.density == "-" ? "" : " of density " + runs.density) + "; its tests: " + listed(tests));
  } else if (reads == Reads::TestAmongTests) {
    refuse(row, "test", "quantity '" + row.quantity + "' compares one test with the others: name it with `test` (the study's tests: " +
                            listed(tests) + ")");
  }
  runs.tests = reads == Reads::Tests && !row.test.empty() ? std::vector<std::string>{row.test} : tests;
  return runs;
}

}  // namespace validation
