// Figs. 7, 10, 11 (figure_entry.hpp): εv, the coordination number and the sliding fraction at the end
// of each cycle, over every sample of the ensemble (ensemble_cycle_table), and their notes; and the
// second headline check, the slope of q/p against F^s_d/F^s_m of every sample (fig00_slopes).
#include <cmath>

#include "figures/figure_entry.hpp"
#include "judge/quantities.hpp"
#include "figures/figure_bounds.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"

namespace validation {

namespace {

// Figs. 7, 10, 11 of one density: the ensemble's per-cycle mean over the samples, per test, up to
// cycle `last` (the last cycle every test of every sample reached).
void cycle_figure_values(NoteContext& c, Values& v, const std::string& d, int last) {
  const auto& quantities = cycle_quantities();
  MinMax growth, dense_abs, cn0, cn1, cnc, sliding;
  for (int t = 1; t <= 5; ++t) {
    const Table ev = ensemble_cycle_table(c.in.samples, d, t, quantities[0]);
    const Table cn = ensemble_cycle_table(c.in.samples, d, t, quantities[1]);
    const Table sl = ensemble_cycle_table(c.in.samples, d, t, quantities[2]);
    const auto* e1 = cycle_row(ev, 1);
    const auto* ec = cycle_row(ev, last);
    if (e1 && ec) {
      growth.add((*ec)[1] - (*e1)[1]);
      if (d == "loose") v["fig07.loose_test" + std::to_string(t)] = mean_pm_sd((*ec)[1], (*ec)[2]);
    }
    for (const auto& row : ev.rows)
      if (row[0] <= last) dense_abs.add(std::abs(row[1]));
    if (const auto* r = cycle_row(cn, 0)) cn0.add((*r)[1]);
    if (const auto* r = cycle_row(cn, 1)) cn1.add((*r)[1]);
    if (const auto* r = cycle_row(cn, last)) cnc.add((*r)[1]);
    const auto* s1 = cycle_row(sl, 1);
    const auto* sc = cycle_row(sl, last);
    if (s1 && sc) sliding.add((*sc)[1] - (*s1)[1]);
  }
  if (growth.any()) v["fig07.growth_" + d] = range_text(growth.lo, growth.hi);
  if (dense_abs.any()) v["fig07.max_abs_" + d] = fig07_max_abs_text(dense_abs.hi);  // "stays below" it
  v["fig07.verdict_" + d] = d == "dense" ? c.phrase("ev_growth_magnitude", d) : c.phrase("ev_growth", d);
  if (cn0.any()) v["fig10.start_" + d] = range_fixed(cn0.lo, cn0.hi, 2);
  if (cn1.any()) v["fig10.cycle1_" + d] = range_fixed(cn1.lo, cn1.hi, 2);
  if (cnc.any()) v["fig10.last_" + d] = range_fixed(cnc.lo, cnc.hi, 2);
  v["fig10.verdict_" + d] = d == "dense" ? c.phrase("cn_change_magnitude", d) : c.phrase("cn_change", d);
  if (sliding.any()) v["fig11.change_" + d] = range_text(sliding.lo, sliding.hi);
  v["fig11.verdict_" + d] = d == "loose" ? c.phrase("sliding_change", d) : c.phrase("sliding_change_magnitude", d);
}

// The headline check after shearing: the slope of q/p against F^s_d/F^s_m of every sample (the
// validation row's own quantity, over all its tests), by density (1 loose, 2 medium, 3 dense, the
// x of the figure), labelled by sample; the paper's value and the row's tolerance in values.gp.
void fig00_slopes(const FigureSource& src, FigureFolder& out) {
  const std::string quantity = "qp_strong_fabric_slope";
  Table t;
  t.columns = {"density [1]", "slope of q/p against F^s_d/F^s_m [1]"};
  for (std::size_t k = 0; k < src.densities.size(); ++k)
    for (const Sample& s : src.samples) {
      const auto it = s.densities.find(src.densities[k]);
      if (it == s.densities.end() || it->second.tests.empty()) continue;
      const Measured m = compute({quantity, src.densities[k]}, it->second);
      if (!m.value) continue;
      t.labels.push_back(s.name.empty() ? "the sample" : s.name);
      t.rows.push_back({static_cast<double>(k + 1), *m.value});
    }
  out.write("fig00_slopes.dat", t, "the slope of q/p against F^s_d/F^s_m of every sample, all its tests (" + src.results + ")");
  out.values.number("fig00_slopes_rows", static_cast<double>(t.size()));
  double tolerance = NAN;
  for (const Row& r : src.paper)
    if (r.quantity == quantity) tolerance = r.tolerance;
  out.values.number("paper_slope_tolerance", tolerance);
}

}  // namespace

// Figs. 7, 10, 11: per-cycle statistics over every sample of the ensemble; the slopes of every sample.
void cycle_figures_data(const FigureSource& src, FigureFolder& out) {
  fig00_slopes(src, out);
  const std::map<std::string, std::string> files = {
      {"epsv_percent", "fig07_epsv_cycles"}, {"coordination", "fig10_coordination"}, {"sliding_percent", "fig11_sliding"}};
  for (const CycleQuantity& cq : cycle_quantities())
    for (const std::string& d : src.densities)
      for (int t = 1; t <= 5; ++t) {
        std::size_t runs = 0;
        const Table table = ensemble_cycle_table(src.samples, d, t, cq, &runs);
        out.write(files.at(cq.name) + "_" + d + "_test" + std::to_string(t) + ".dat", table,
                  "Figs. 7, 10, 11: " + d + ", Test " + std::to_string(t) + ", " + std::to_string(runs) + " sample(s) of " + src.results);
      }
}

void cycle_figures_notes(NoteContext& c, Values& v) {
  int last = paper_cycles;
  bool any_test = false;
  for (const Sample& s : c.in.samples)
    for (const auto& [d, r] : s.densities)
      for (const TestResult& t : r.tests) last = std::min(last, last_cycle(t.series)), any_test = true;
  if (!any_test || last < 1) return;
  v["cycles.last"] = std::to_string(last);
  for (const std::string& d : paper_densities()) cycle_figure_values(c, v, d, last);
}

}  // namespace validation
