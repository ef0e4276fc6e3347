#pragma once
// The figures of each compare-runs mode's section, declared once: the static gnuplot scripts
// (reports/gnuplot/<script>.gp) that draw them from the data files the mode wrote, run in the
// section's folder with GNUPLOT_LIB set to the scripts' folder (where style.gp is). A figure that
// plots a data file drawn only with an option (the critical state's rates.dat, with --rates) is
// drawn when that file has a data row, and its image removed when it has none.
#include <string>
#include <vector>

namespace sections {

struct SectionFigure {
  std::string script;  // reports/gnuplot/<script>.gp
  std::string needs;   // a data file of the section's folder it plots that may hold no row ("": always drawn)
  std::string image;   // the image it draws, removed when `needs` has no row
};

// The figures of `mode` (convergence, stability, decisions, critical-state, liquefaction), in
// the order they are drawn; none for a mode without figures.
const std::vector<SectionFigure>& section_figures(const std::string& mode);

// Draws `mode`'s figures in `out` with the scripts of `gnuplot_dir`. Returns 0, or 1 when gnuplot
// is not there or a script fails (the message names the script and the folder).
int draw_section(const std::string& mode, const std::string& out, const std::string& gnuplot_dir);

}  // namespace sections
