#pragma once
// What `figure-data figures` writes: every figure's data files (figNN_*.dat, columns named with
// units) and values.gp, the numbers the static scripts in reports/gnuplot/ read. One function per
// figure (or group of figures drawn from the same runs) in figure_data.cpp; the report's notes on
// the same figures are computed in report/figure_notes.cpp from the same tables (figures.hpp).
#include <string>
#include <vector>

#include "figures/figures.hpp"
#include "study/results.hpp"

namespace validation {

// A folder of data files and the values.gp written beside them.
class FigureFolder {
 public:
  explicit FigureFolder(std::string out);
  // `t` as OUT/name, its first comment line `what` (which figure, from which run).
  void write(const std::string& name, const Table& t, const std::string& what);
  int files() const { return files_; }
  GnuplotValues values;

 private:
  std::string out_;
  int files_ = 0;
};

// What the figures are drawn from: the ensemble, the sample of the single-run figures, the paper's
// rows, the densities of the study and how the folders are named in the files' comments.
struct FigureSource {
  const std::vector<Sample>& samples;
  const Sample& chosen;
  std::string sample_label;  // the chosen sample's name in the files ("seed1")
  std::string from;          // the chosen sample's folder, as written into the files
  std::string results;       // the results folder, as written into the files
  std::vector<Row> paper;
  std::vector<std::string> densities;
};

// Every figure's data into `out`, and the numbers its scripts read into out.values (values.gp is
// the caller's to write, with its own comment line).
void write_figure_data(const FigureSource& src, FigureFolder& out);

}  // namespace validation
