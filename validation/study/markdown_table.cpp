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

std::string line(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const std::string& c : cells) {
    out += ' ';
    out += cell(c);
    out += " |";
  }
  return out + "\n";
}

}  // namespace

std::string MarkdownTable::text() const {
  std::string out = line(headings_) + "|";
  for (Align a : align_)
    out += a == Align::Left ? ":---|" : a == Align::Center ? ":---:|" : a == Align::Right ? "---:|" : "---|";
  out += "\n";
  for (const auto& r : rows_) out += line(r);
  return out;
}

}  // namespace validation
