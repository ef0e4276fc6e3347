#pragma once
// Which runs of a study a reference row reads: its selectors (variant, density, test) resolved
// against the names the study's manifest (runs.tsv) gives them, and what its quantity reads
// (quantities.hpp: the preparation, the tests, or every test with one named).
#include <string>
#include <vector>

#include "study/manifest.hpp"
#include "judge/rows.hpp"

namespace validation {

struct RowRuns {
  std::string variant = "-";       // as runs.tsv writes it ("-": a study without variants)
  std::string density;
  bool preparation = false;        // the density's preparation
  std::vector<std::string> tests;  // the tests it reads, in the manifest's order
};

// A selector left out takes the study's only value; a study with several needs it named. Throws
// dem::ConfigError naming the row (Row::origin), the key and the names the study has when a
// selector names what the study (`study`: its manifest's path, for the message) does not have,
// names none of several, or does not fit the quantity (a test for a quantity of the preparation,
// no test for an ordering).
RowRuns resolve_runs(const Row& row, const std::vector<ManifestLine>& manifest, const std::string& study);

}  // namespace validation
