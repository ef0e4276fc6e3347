// The Markdown table writer every compare-runs mode uses: its exact text, written out by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "study/format.hpp"
#include "study/markdown_table.hpp"

using validation::MarkdownTable;

TEST_CASE("markdown table: heading, delimiter and rows, one line each", "[markdown-table][format]") {
  MarkdownTable t({"case", "steps"});
  t.row({"base", "1200"}).row({"dt 0.5", "—"});
  // "| " before each cell, " |" after it; the delimiter has one "---|" per column.
  CHECK(t.text() ==
        "| case | steps |\n"
        "|---|---|\n"
        "| base | 1200 |\n"
        "| dt 0.5 | — |\n");
  CHECK(t.columns() == 2);
  CHECK(t.rows() == 2);
  // No rows: the heading and the delimiter alone.
  CHECK(MarkdownTable({"a"}).text() == "| a |\n|---|\n");
}

TEST_CASE("markdown table: column alignment in the delimiter row, and a row must fill every column", "[markdown-table][format]") {
  // Unset ---, Left :---, Center :---:, Right ---:; columns beyond the alignments given are Unset.
  MarkdownTable t({"a", "b", "c", "d", "e"}, {MarkdownTable::Align::Unset, MarkdownTable::Align::Left, MarkdownTable::Align::Center,
                                             MarkdownTable::Align::Right});
  CHECK(t.text() == "| a | b | c | d | e |\n|---|:---|:---:|---:|---|\n");
  // A short or a long row would put every later cell under the wrong heading: refused, with both counts.
  CHECK_THROWS_WITH(t.row({"1", "2", "3", "4"}), Catch::Contains("4 cells") && Catch::Contains("5 columns"));
  CHECK_THROWS_AS(t.row({"1", "2", "3", "4", "5", "6"}), std::invalid_argument);
  CHECK(t.rows() == 0);
  CHECK_THROWS_AS(MarkdownTable({}), std::invalid_argument);
  CHECK_THROWS_AS(MarkdownTable({"a"}, {MarkdownTable::Align::Left, MarkdownTable::Align::Left}), std::invalid_argument);
  // Empty cells keep their place: "|  |" (the space after "|" and the one before the next "|").
  MarkdownTable gaps({"within", "variant", "settings"});
  gaps.row({"1 %", "none", ""});
  CHECK(gaps.text() == "| within | variant | settings |\n|---|---|---|\n| 1 % | none |  |\n");
}

TEST_CASE("markdown table: a '|' or a newline in a cell or a heading cannot break the table", "[markdown-table][format]") {
  // A variant named "dt2|x" and a two-line message: the '|' escaped as "\|", the newline a space.
  MarkdownTable t({"variant", "a|b"});
  t.row({"dt2|x", "stopped:\nnon-finite force"});
  CHECK(t.text() ==
        "| variant | a\\|b |\n"
        "|---|---|\n"
        "| dt2\\|x | stopped: non-finite force |\n");
  // Escaped once: the writer escapes what it is given, so callers pass raw text (cell(cell(x)) would
  // add a second backslash).
  CHECK(validation::cell("a|b") == "a\\|b");
}

TEST_CASE("markdown table: numbers keep the digits their formatter chose", "[markdown-table][format]") {
  // The writer takes text, so "0.10" stays "0.10" (a writer taking doubles would print 0.1) and a
  // missing value is the formatter's "—". Hand-derived: 2.675 is 2.674999999999999822... in binary,
  // so two decimals round it down; 1234.5 is exact, and printf rounds an exact half to even.
  MarkdownTable t({"x", "fixed(x, 2)", "fixed(x, 0)", "number(x)"});
  for (const double x : {0.1, 2.675, 1234.5, -0.004, std::nan("")})
    t.row({validation::number(x), validation::fixed(x, 2), validation::fixed(x, 0), validation::number(x)});
  CHECK(t.text() ==
        "| x | fixed(x, 2) | fixed(x, 0) | number(x) |\n"
        "|---|---|---|---|\n"
        "| 0.1 | 0.10 | 0 | 0.1 |\n"
        "| 2.675 | 2.67 | 3 | 2.675 |\n"
        "| 1234.5 | 1234.50 | 1234 | 1234.5 |\n"
        "| -0.004 | -0.00 | -0 | -0.004 |\n"
        "| nan | — | — | nan |\n");
}
