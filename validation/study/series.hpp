#pragma once
// The ground floor's view of a time series: a data table with named columns and units (what the
// figures and the section tables write), one row of a result's series, and what the engine derives
// from a row's stress and fabric tensors (analysis/measurements.hpp, analysis/fabric.hpp).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/types.hpp"
#include "study/results.hpp"

namespace validation {

// A number as every data file writes it (%.10g; NaN as "NaN"), and a label quoted for gnuplot.
std::string format_number(double x);
std::string quoted(const std::string& s);

// One data file: comment lines, a header naming each column with its unit, rows of numbers, and
// optionally a text label per row (written as the first column, quoted) and gnuplot index blocks.
struct Table {
  std::vector<std::string> comments;  // written as "# ..." lines before the header
  std::vector<std::string> columns;   // "name [unit]"
  std::vector<std::string> labels;    // empty, or one per row
  std::vector<std::vector<double>> rows;
  std::vector<std::size_t> block_starts;  // rows that start a new block (two blank lines before)
  std::string text() const;
  std::size_t size() const { return rows.size(); }
  double at(std::size_t row, const std::string& column) const;  // by name (without the unit); throws
};

// A table as text() wrote it, read back (the figure data files, numbers to ten significant digits):
// its comments, its columns (the last comment line before the first row) and rows; labels and
// blocks are not kept. Throws std::runtime_error naming `what` on a row that is not numbers or
// has another count of values than the columns.
Table table_from_text(const std::string& text, const std::string& what);

// A view of one time-series row: `s.at("q")` reads column q at row i.
struct SeriesRow {
  const Columns& series;
  std::size_t i;
  double operator()(const std::string& column) const { return series.at(column).at(i); }
};
std::size_t row_count(const Columns& series);

// The stress tensor of a row (stress_11 ... stress_23) [Pa], and what the engine derives from it:
// p and q (principal values of the full tensor), q/p, sigma_11/sigma_33, and the normalised
// pi-plane point of the axis stresses, pi_plane(diag)/p.
dem::Mat3 stress_of(const SeriesRow& r);
double q_over_p(const dem::Mat3& stress_Pa);
Eigen::Vector2d pi_stress(const dem::Vec3& principal_Pa);

// Fabric ratio F_d / F_m of a row's fabric tensor, "fabric" or "strong_fabric" (paper Eqs. 8-10).
double fabric_ratio_of(const SeriesRow& r, const std::string& which);

// gnuplot variable definitions (values.gp): numbers, strings, and lists of strings as NAME_n and
// NAME_1 ... NAME_n (the scripts read them with value(sprintf(...))).
class GnuplotValues {
 public:
  void number(const std::string& name, double value);
  void text(const std::string& name, const std::string& value);
  void texts(const std::string& name, const std::vector<std::string>& values);
  std::string text_file(const std::string& comment) const;

 private:
  std::vector<std::pair<std::string, std::string>> lines_;
};

}  // namespace validation
