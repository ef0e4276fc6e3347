// The values of the figure notes (report.hpp: figure_values, figure_note): the constants the
// sentences quote, then each figure entry's notes (figures/figure_entry.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "figures/figure_entry.hpp"
#include "judge/quantities.hpp"
#include "report/report.hpp"
#include "study/format.hpp"

namespace validation {

namespace {

// The constants the computations use, for the sentences that quote them, and the cycles a paper
// row reads ("after 5 cycles", "from cycle 1 to 5").
void constant_values(const ReportInputs& in, Values& v) {
  v["paper.particles"] = thousands(std::lround(paper_particles));
  v["cycles.shown"] = std::to_string(paper_cycles);
  v["energy.parting_percent"] = significant(100 * energy_parting_fraction, 2);
  v["shift.clip"] = significant(shift_clip, 2);
  for (const Row& r : in.paper) {
    if (r.quantity == "ev_after_cycle" && r.density == "loose") v["fig06.paper_cycle"] = std::to_string(r.cycle);
    if (r.quantity == "strain_increment_alignment_gain" && r.density == "loose")
      v["fig09.from_cycle"] = std::to_string(r.from_cycle), v["fig09.to_cycle"] = std::to_string(r.to_cycle);
  }
}

}  // namespace

Values figure_values(const ReportInputs& in) {
  Values v;
  constant_values(in, v);
  if (in.samples.empty()) return v;
  auto chosen = std::find_if(in.samples.begin(), in.samples.end(), [&](const Sample& s) { return s.name == in.sample; });
  if (chosen == in.samples.end()) chosen = in.samples.begin();
  v["sample"] = chosen->name.empty() ? "the sample" : chosen->name;
  v["samples_n"] = std::to_string(in.samples.size());
  NoteContext c(in, *chosen);
  for (const FigureEntry& e : figure_entries()) e.notes(c, v);
  return v;
}

std::string figure_note(const std::string& notes_tsv, const std::string& png, const Values& values) {
  std::istringstream in(notes_tsv);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    if (tab == std::string::npos || line.substr(0, tab) != png) continue;
    try {
      return fill(line.substr(tab + 1), values);
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      const auto key = what.find("{{");
      return "*No comparison with the paper: the data it needs (" + (key == std::string::npos ? what : what.substr(key)) +
             ") is not in these results.*";
    }
  }
  return "*No comparison with the paper written for this figure yet.*";
}

}  // namespace validation
