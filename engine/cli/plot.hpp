#pragma once
// `dem plot`: a quick look at results, one column against another, several results overlaid,
// drawn by gnuplot into a PNG or onto the terminal. draw_plot draws given series; the Python
// module's plot (python/) calls the same function.
#include <string>
#include <vector>

namespace dem {

struct PlotSeries {
  std::string key;            // its line's name in the key
  std::vector<double> x, y;   // the points, joined in order (NaN: a gap)
};

struct PlotText {
  std::string xlabel, ylabel, title;
  std::string out;   // FILE.png; for term "dumb" a text file, or "" for standard output
  std::string term;  // "png" or "dumb" (text)
};

// Draws the series with gnuplot. Throws std::invalid_argument for a term it does not know or a
// png without `out`, std::runtime_error naming the reason when gnuplot cannot be run or fails.
void draw_plot(const std::vector<PlotSeries>& series, const PlotText& text);

// "name [unit]" of a column of the engine's /timeseries (or /legs) table, the name alone for a
// dimensionless one; throws std::invalid_argument naming the table when there is no such column.
std::string axis_label(const std::string& column, bool legs);

struct PlotArgs {
  std::vector<std::string> results;  // RESULT.h5 files (a .partial is drawn, and its key says so)
  std::string x, y;                  // column names of /timeseries (or /legs)
  std::string out;                   // FILE.png; "" draws on the terminal
  std::string term;                  // "png" or "dumb" ("": png with --out, dumb without)
  std::string title;
  bool legs = false;
};

// `dem plot`. Exit status: 0 drawn, 1 gnuplot failed, 2 bad input (a result or column that is not there).
int plot(const PlotArgs& args);

}  // namespace dem
