#pragma once
// The cells of one Markdown table line ("| a | b \| c |"), split at the '|' that are not escaped
// and trimmed, for the tests that read tables back (not a test file itself: no _test suffix).
// `escaped`: Read turns "\|" back into '|' (the cell's text); Keep leaves "\|" (the Markdown, as
// a cell-width limit counts it).
#include <string>
#include <vector>

namespace dem::test {

enum class Escaped { Read, Keep };

inline std::vector<std::string> markdown_cells(const std::string& line, Escaped escaped = Escaped::Read) {
  std::vector<std::string> cells;
  std::string c;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') c += escaped == Escaped::Read ? "|" : "\\|", ++i;
    else if (line[i] == '|') {
      const auto a = c.find_first_not_of(' '), b = c.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : c.substr(a, b - a + 1));
      c.clear();
    } else c += line[i];
  }
  return cells;
}

}  // namespace dem::test
