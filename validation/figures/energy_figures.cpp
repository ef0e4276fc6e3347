// The energy balance (figure_entry.hpp): every run of the chosen sample, and the note's work,
// closure and parting time of each density's Test 1.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "figures/figure_entry.hpp"
#include "figures/figure_bounds.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"

namespace fs = std::filesystem;

namespace validation {

// The energy balance of every run of the chosen sample (results of an engine without the energy
// columns are noted and left out).
void energy_figures_data(const FigureSource& src, FigureFolder& out) {
  for (const std::string& d : src.densities) {
    std::vector<std::pair<std::string, const Columns*>> runs;
    Columns prepare_series;
    const std::string f = (fs::path(src.chosen.dir) / (d + "_prepare.h5")).string();
    if (is_complete(f)) {
      prepare_series = read_columns(f, "timeseries");
      runs.emplace_back(d + "_prepare", &prepare_series);
    }
    for (const TestResult& t : src.chosen.densities.at(d).tests) runs.emplace_back(d + "_test" + std::to_string(t.number), &t.series);
    for (const auto& [run, series] : runs) {
      try {
        out.write("fig_energy_" + run + ".dat", energy_balance(*series), "energy balance of " + src.from + "/" + run);
      } catch (const std::out_of_range& e) {
        std::fprintf(stderr, "note: %s/%s: no energy balance (%s)\n", src.from.c_str(), run.c_str(), e.what());
      }
    }
  }
}

// The energy balance of Test 1 of each density (the energy figure).
void energy_figures_notes(NoteContext& c, Values& v) {
  bool old_first_row = false;
  for (const std::string& d : paper_densities()) {
    const DensityResults* r = c.results_of(d);
    const TestResult* t = r ? find_test(*r, 1) : nullptr;
    if (!t) continue;
    try {
      const EnergyCurves e = energy_curves(t->series);
      old_first_row = old_first_row || e.baseline_row > 0;
      v["energy.work_" + d] = energy_text(e.work_total_J());
      v["energy.closure_" + d] = energy_closure_text(e.closure_relative_to_work());  // "at most" it
      if (const auto at = e.parting_time_s(energy_parting_fraction)) v["energy.parts_at_" + d] = significant(*at, 3);
    } catch (const std::out_of_range&) {
      // a result without the energy columns: no keys, the note says the data is missing
    }
  }
  if (old_first_row) v["energy.old_first_row"] = "yes";
}

}  // namespace validation
