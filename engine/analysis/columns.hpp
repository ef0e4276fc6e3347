#pragma once
// A table of result columns, each declared once: its name, unit, meaning and how its value is
// computed. The time series (analysis/time_series.cpp) and /legs (analysis/legs.cpp) are such
// tables; from each come the row of values, the column names and units of the result file
// (io/result_writer.cpp: `units` and `doc` attributes), `dem table`'s `name [unit]` headers and
// the column list of engine/README.md (`dem columns`, checked by tests/engine/analysis/columns_test.cpp).
#include <cstddef>
#include <string>
#include <vector>

namespace dem {

// What a result file and its readers know of a column.
struct SeriesColumn {
  std::string name, units, doc;
};

// One entry of a table: the column and its value, a pure function of `In` (what a row is computed
// from). A captureless lambda converts to `value`.
template <class In>
struct ColumnDef {
  const char* name;
  const char* units;
  const char* doc;  // "" for a component documented by the entry before it (stress_22 after stress_11)
  double (*value)(const In&);
};

template <class In, std::size_t N>
std::vector<SeriesColumn> describe(const ColumnDef<In> (&table)[N]) {
  std::vector<SeriesColumn> columns;
  columns.reserve(N);
  for (const ColumnDef<In>& c : table) columns.push_back({c.name, c.units, c.doc});
  return columns;
}

// One row: every column's value from `in`, in the table's order.
template <class In, std::size_t N>
std::vector<double> measure(const ColumnDef<In> (&table)[N], const In& in) {
  std::vector<double> row(N);
  for (std::size_t c = 0; c < N; ++c) row[c] = table[c].value(in);
  return row;
}

// A Markdown table of the columns (`name` | unit | meaning), as engine/README.md lists them: a
// column without a doc joins the row of the column before it when they share the unit
// (`stress_11`, `stress_22`, ... | Pa | contact stress, ...). A '|' in a unit or doc is escaped.
std::string columns_markdown(const std::vector<SeriesColumn>& columns);

}  // namespace dem
