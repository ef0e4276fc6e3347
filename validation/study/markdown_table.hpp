#pragma once
// The Markdown tables the validation tools write (GitHub's pipe tables): a heading row, the
// delimiter row, then one line per row:
//   | case | outcome |
//   |---|---|
//   | base | ran |
// Every heading and cell goes through cell() (format.hpp): a '|' in it is escaped and a newline
// becomes a space, so text taken from results, settings or messages cannot end a cell or a row.
// Cells are written as given: numbers keep the digits their formatter chose ("0.10", "—"). A cell
// longer than cell_limit code points (a sentence, a message, a list of settings) is written cut at a
// word with "… (note N)" and in full in a numbered note under the table, so that every table line
// stays readable and nothing is lost.
#include <cstddef>
#include <string>
#include <vector>

namespace validation {

// The longest cell a table line holds, in code points (as written, escapes included).
inline constexpr std::size_t cell_limit = 200;

class MarkdownTable {
 public:
  // How a column's text is aligned, written in the delimiter row: ---, :---, :---:, ---:.
  enum class Align { Unset, Left, Center, Right };

  // `align` gives the first columns' alignment; the others (and all, when it is empty) are Unset.
  // Throws std::invalid_argument without headings or with more alignments than headings.
  explicit MarkdownTable(std::vector<std::string> headings, std::vector<Align> align = {});

  // Appends a row. Throws std::invalid_argument, naming both counts, unless it has one cell per
  // column: a short row would shift every cell after the gap into the wrong column.
  MarkdownTable& row(std::vector<std::string> cells);

  std::size_t columns() const { return headings_.size(); }
  std::size_t rows() const { return rows_.size(); }

  // The table, every line ending in '\n'; an empty cell is "|  |". Cells over cell_limit: cut,
  // each in full in a note after the table ("\nNote N (<column>, <row's first cell>): <text>\n").
  std::string text() const;

 private:
  std::vector<std::string> headings_;
  std::vector<Align> align_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace validation
