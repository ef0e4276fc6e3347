// The column names the tools read (validation/study/columns.hpp) are the engine's: each is a
// column of the time series or of /legs as the engine declares them (a renamed column fails here).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "study/columns.hpp"

namespace {

bool declared(const std::vector<dem::SeriesColumn>& table, const std::string& name) {
  return std::any_of(table.begin(), table.end(), [&](const dem::SeriesColumn& c) { return c.name == name; });
}

}  // namespace

TEST_CASE("every column name the tools read is one the engine writes", "[validation][columns]") {
  for (const char* name : validation::col::series_names) {
    INFO(name);
    CHECK(declared(dem::series_columns(), name));
  }
  for (const char* name : validation::col::legs_names) {
    INFO(name);
    CHECK(declared(dem::leg_columns(), name));
  }
  // and the check can fail: a name the engine does not write is not found
  CHECK_FALSE(declared(dem::series_columns(), "volumetric_strain_percent"));
}
