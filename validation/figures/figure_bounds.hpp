#pragma once
// The bounds the figure notes state ("p stays within", "|εv| stays below", "differ by at most"),
// each worded by bound_text (study/format.hpp) from the unrounded extreme of the figure's data: from
// the results when they are here (the notes' computations, figures/*_figures.cpp), and from the
// figure data files the notes describe (reports/figures/*.dat, every value to ten significant
// digits) when the report is written again without them, so that a key read back from an older
// study_values.json, worded before bounds were rounded outwards, is worded again from the data.
#include <filesystem>
#include <optional>
#include <string>

#include "figures/notes.hpp"

namespace validation {

// "lo–hi" that the values from lo to hi stay within, at `decimals` decimals (lo rounded down, hi up).
std::string within_text(double lo, double hi, int decimals);

// Fig. 4: p [kPa] of every row of the chosen sample's tests of density `d`: "98.83–99.98".
std::string fig04_p_text(const MinMax& p_kPa);
// Fig. 7: the largest |mean εv| [%] up to the last cycle shown, that |εv| stays below.
std::string fig07_max_abs_text(double max_abs_percent);
// The energy figure: the largest gap over the run's work, a fraction, that the gap is at most (in %).
std::string energy_closure_text(double fraction);

// The keys fig04.p_<d>, fig07.max_abs_<d> (up to `last_cycle`) and energy.closure_<d>, for every
// density whose data files `figures` holds (fig04_q_p_<d>_test<N>.dat, fig07_epsv_cycles_<d>_test<N>.dat,
// fig_energy_<d>_test1.dat); a density without its files: its key left as it is. A file there that
// cannot be read throws std::runtime_error naming it.
void add_figure_bounds(Values& v, const std::filesystem::path& figures, std::optional<int> last_cycle);

}  // namespace validation
