#include "analysis/columns.hpp"

namespace dem {

namespace {

// A table cell's text: '|' (as in |net force|) would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (const char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

}  // namespace

std::string columns_markdown(const std::vector<SeriesColumn>& columns) {
  std::string out = "| column | unit | meaning |\n|---|---|---|\n";
  for (std::size_t c = 0; c < columns.size();) {
    std::string names = "`" + columns[c].name + "`";
    std::size_t next = c + 1;
    for (; next < columns.size() && columns[next].doc.empty() && columns[next].units == columns[c].units; ++next)
      names += ", `" + columns[next].name + "`";
    out += "| " + names + " | " + cell(columns[c].units) + " | " + cell(columns[c].doc) + " |\n";
    c = next;
  }
  return out;
}

}  // namespace dem
