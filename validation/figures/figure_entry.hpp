#pragma once
// Every figure declared once: one entry per group of figures drawn from the same runs, with the
// data `figure-data figures` writes for them (their figNN_*.dat files and the numbers of values.gp
// their scripts read) and the values their notes in the report read. figure-data and the report
// both go through figure_entries(), in its order; the per-cycle table of Figs. 7, 10, 11 is
// ensemble_cycle_table (figures.hpp), which ensemble-cycles reads too.
//
// A new figure: its entry (or a function in an entry of the same runs) in a file of this folder,
// its script reports/gnuplot/figNN_*.gp, its note in reports/templates/figure_notes.tsv, a test.
#include <string>
#include <vector>

#include "figures/figure_data.hpp"
#include "figures/notes.hpp"

namespace validation {

struct FigureEntry {
  std::string figures;                                // which figures ("Figs. 7, 10, 11")
  void (*data)(const FigureSource&, FigureFolder&);  // their data files and values.gp numbers
  void (*notes)(NoteContext&, Values&);              // the values of their notes
};

const std::vector<FigureEntry>& figure_entries();

// The entries' functions, one file each.
void sample_figures_data(const FigureSource& src, FigureFolder& out);  // Figs. 1, 2 (sample_figures.cpp)
void sample_figures_notes(NoteContext& c, Values& v);
void single_run_figures_data(const FigureSource& src, FigureFolder& out);  // Figs. 3-6, 8, 9, 12, 13 (single_run_figures.cpp)
void single_run_figures_notes(NoteContext& c, Values& v);
void cycle_figures_data(const FigureSource& src, FigureFolder& out);  // Figs. 0 (slopes), 7, 10, 11 (cycle_figures.cpp)
void cycle_figures_notes(NoteContext& c, Values& v);
void energy_figures_data(const FigureSource& src, FigureFolder& out);  // the energy balance (energy_figures.cpp)
void energy_figures_notes(NoteContext& c, Values& v);

// An empty data file with its header, so that every script finds its files (the curve is absent).
Table none_table(const std::string& comment);
// The chosen sample's first stress-path stage: its mean stress [Pa] and stress ratio (1e5 and 1.24
// when no test has one); `shear_friction` gets that test's friction, if any.
struct PathSettings {
  double p = 1e5, R = 1.24;
  std::optional<double> shear_friction;
};
PathSettings path_settings(const FigureSource& src);

}  // namespace validation
