#include "study/markdown_table.hpp"

#include <stdexcept>
#include <utility>

#include "study/format.hpp"

namespace validation {

MarkdownTable::MarkdownTable(std::vector<std::string> headings, std::vector<Align> align)
    : headings_(std::move(headings)), align_(std::move(align)) {
  if (headings_.empty()) throw std::invalid_argument("a Markdown table needs at least one column");
  if (align_.size() > headings_.size())
    throw std::invalid_argument("a Markdown table of " + std::to_string(headings_.size()) + " columns given " +
                                std::to_string(align_.size()) + " alignments");
  align_.resize(headings_.size(), Align::Unset);
}

MarkdownTable& MarkdownTable::row(std::vector<std::string> cells) {
  if (cells.size() != headings_.size())
    throw std::invalid_argument("a Markdown table row of " + std::to_string(cells.size()) + " cells in a table of " +
                                std::to_string(headings_.size()) + " columns (first cell: '" +
                                (cells.empty() ? std::string() : cells.front()) + "')");
  rows_.push_back(std::move(cells));
  return *this;
}

namespace {

bool starts_code_point(char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += starts_code_point(c);
  return n;
}

// `s` cut to at most `points` code points, at the last space before them when there is one.
std::string cut(const std::string& s, std::size_t points) {
  std::size_t kept = 0, at = 0;
  for (; at < s.size(); ++at)
    if (starts_code_point(s[at]) && kept++ == points) break;
  const std::size_t space = s.rfind(' ', at);
  return s.substr(0, space != std::string::npos && space > at / 2 ? space : at);
}

std::string line(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const std::string& c : cells) {
    out += ' ';
    out += c;
    out += " |";
  }
  return out + "\n";
}

}  // namespace

std::string MarkdownTable::text() const {
  std::vector<std::string> heads;
  for (const std::string& h : headings_) heads.push_back(cell(h));
  std::string out = line(heads) + "|";
  for (Align a : align_)
    out += a == Align::Left ? ":---|" : a == Align::Center ? ":---:|" : a == Align::Right ? "---:|" : "---|";
  out += "\n";
  std::string notes;
  int n = 0;
  for (const auto& r : rows_) {
    std::vector<std::string> cells;
    for (std::size_t k = 0; k < r.size(); ++k) {
      std::string c = cell(r[k]);
      if (code_points(c) > cell_limit) {
        const std::string mark = "… (note " + std::to_string(++n) + ")";
        const std::string row = cell(r[0]);  // the note names its column and its row's first cell
        const std::string label = code_points(row) <= 100 ? row : cut(row, 100) + "…";
        notes += "\nNote " + std::to_string(n) + " (" + heads[k] + (k > 0 ? ", " + label : std::string()) + "): " + c + "\n";
        c = cut(c, cell_limit / 2) + mark;
      }
      cells.push_back(std::move(c));
    }
    out += line(cells);
  }
  return out + notes;
}

}  // namespace validation
