// The column tables of a result (engine/analysis/columns.hpp): /timeseries and /legs are each one
// table of {name, unit, doc, value}, from which the rows, the file's column attributes, `dem
// table`'s headers and engine/README.md's lists all come. These cases check what the one table
// cannot make true by itself: the README shows the tables as they are, and a row of another
// width never reaches a file.
#include <catch2/catch.hpp>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/columns.hpp"
#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "engine/io/io_test_support.hpp"
#include "engine/test_support.hpp"
#include "io/result_writer.hpp"

using namespace dem;

namespace {

// The text of engine/README.md between "<!-- MARKER: begin -->\n" and "<!-- MARKER: end -->".
std::string readme_block(const std::string& marker) {
  const std::string readme = test::read_bytes(std::string(DEM_SOURCE_DIR) + "/engine/README.md");
  const std::string begin = "<!-- " + marker + ": begin -->\n", end = "<!-- " + marker + ": end -->";
  const std::size_t a = readme.find(begin), b = readme.find(end);
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  REQUIRE(a < b);
  return readme.substr(a + begin.size(), b - a - begin.size());
}

}  // namespace

TEST_CASE("engine/README.md lists the columns of /timeseries and /legs as the tables declare them", "[analysis][columns][docs]") {
  // On a difference: paste `build/bin/dem columns` (and `dem columns --legs`) between the markers.
  CHECK(readme_block("dem columns") == columns_markdown(series_columns()));
  CHECK(readme_block("dem columns --legs") == columns_markdown(leg_columns()));
}

TEST_CASE("columns_markdown: a column without a doc joins the row before it when the units agree", "[analysis][columns]") {
  const std::vector<SeriesColumn> columns = {
      {"a_1", "Pa", "stress"}, {"a_2", "Pa", ""}, {"b", "m", ""}, {"c", "m", "length"}, {"d", "1", "|f| / f_n"}, {"d_2", "1", ""}};
  CHECK(columns_markdown(columns) ==
        "| column | unit | meaning |\n"
        "|---|---|---|\n"
        "| `a_1`, `a_2` | Pa | stress |\n"
        "| `b` | m |  |\n"  // another unit: a row of its own, without a meaning
        "| `c` | m | length |\n"
        "| `d`, `d_2` | 1 | \\|f\\| / f_n |\n");  // a '|' in a cell is escaped
}

TEST_CASE("the column tables: unique names, a unit each, rows exactly as wide", "[analysis][columns]") {
  for (const auto* table : {&series_columns(), &leg_columns()}) {
    std::set<std::string> names;
    for (const SeriesColumn& c : *table) {
      INFO(c.name);
      CHECK(names.insert(c.name).second);
      CHECK_FALSE(c.units.empty());
    }
    // The first column of a table documents itself (a doc-less one documents by the one before).
    CHECK_FALSE(table->front().doc.empty());
  }
  const PeriodicCell cell(Vec3(1e-2, 1e-2, 1e-2));  // two spheres of 2 mm, 1.9 mm apart: one contact
  Particles p;
  p.add(Vec3(0.405, 0.5, 0.5), 1e-3, 2650);
  p.add(Vec3(0.595, 0.5, 0.5), 1e-3, 2650);
  const Simulation sim(p, cell, test::material(1e6), test::no_damping(), 1e-7, 1e-4);
  CHECK(measure_row(sim, {}).size() == series_columns().size());
  CHECK(leg_row(LegRecord{}).size() == leg_columns().size());
}

TEST_CASE("a result table refuses a row of another width instead of reading past it", "[analysis][columns][io]") {
  const std::string dir = test::scratch_dir("columns_width");
  h5::Handle f = h5::create_file(dir + "/t.h5");
  ColumnTable table(f, "legs", leg_columns());
  CHECK_THROWS_AS(table.append(std::vector<double>(leg_columns().size() - 1, 0.0)), std::logic_error);
  CHECK_THROWS_AS(table.append(std::vector<double>(leg_columns().size() + 1, 0.0)), std::logic_error);
  CHECK(table.pending_rows() == 0);
  table.append(leg_row(LegRecord{}));
  CHECK(table.pending_rows() == 1);
}
