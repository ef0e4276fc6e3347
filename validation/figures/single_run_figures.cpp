// Figs. 3-6, 8, 9, 12, 13 (figure_entry.hpp): the runs of the chosen sample, one test at a time,
// and the values of their notes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/measurements.hpp"
#include "figures/figure_entry.hpp"
#include "judge/quantities.hpp"
#include "study/columns.hpp"
#include "figures/figure_bounds.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/settings.hpp"

namespace validation {

namespace {

const std::vector<std::string>& densities = paper_densities();

// Fig. 9: one arrow scale per test across the densities (a panel row of the figure), so that
// arrows of different lengths look different: the smallest of the densities' own scales (the one
// that keeps the longest increment of any of them at about 0.12).
std::map<int, double> fig09_scales(const FigureSource& src) {
  std::map<int, double> scale;
  for (int t = 1; t <= 5; ++t)
    for (const std::string& d : src.densities)
      if (const TestResult* test = find_test(src.chosen.densities.at(d), t)) {
        const int c2 = std::min(5, last_cycle(test->series));
        const double s = arrow_scale(test->series, {1, c2});
        scale[t] = scale.count(t) ? std::min(scale[t], s) : s;
      }
  return scale;
}

// What the single-run figures collect across the tests: the target paths written, the tables of
// Figs. 12-13 (for their common axis).
struct SingleRunTables {
  std::set<int> targets_done;
  std::vector<Table> fabric, strong;
};

// Figs. 3-6, 8, 9, 12, 13 of one test `dt` (<density>_test<N>) that was not run: empty files.
void test_not_run(const std::string& d, int t, const std::string& run, FigureFolder& out) {
  const std::string dt = d + "_test" + std::to_string(t);
  for (const std::string& name : {"fig03_" + dt, "fig04_q_p_" + dt, "fig05_qp_epsd_" + dt, "fig06_epsv_" + dt, "fig12_fabric_" + dt,
                                  "fig13_strong_fabric_" + dt, "fig09_" + dt + "_cycle1", "fig09_" + dt + "_cycle5",
                                  "fig09_" + dt + "_cycle1_path", "fig09_" + dt + "_cycle5_path"})
    out.write(name + ".dat", none_table("not run"), run);
  if (t == 5) out.write("fig08_test5_" + d + ".dat", none_table("not run"), run), out.values.texts("fig08_titles_" + d, {});
  out.values.number("fig09_scale_" + dt, 1);
  out.values.number("fig09_cycle5_" + dt, 5);
}

// Figs. 3-6, 8, 9, 12, 13 of one test of the chosen sample.
void test_figures(const std::string& d, const TestResult& test, double fig09_scale, const std::string& run, SingleRunTables& tables,
                  FigureFolder& out) {
  const int t = test.number;
  const std::string dt = d + "_test" + std::to_string(t);
  const Columns& s = test.series;
  if (!tables.targets_done.count(t)) {
    out.write("fig03_test" + std::to_string(t) + "_target.dat", target_path(test.legs),
              "Fig. 3: target path of Test " + std::to_string(t) + " (" + run + ")");
    tables.targets_done.insert(t);
  }
  out.write("fig03_" + dt + ".dat", stress_path(s), "Fig. 3: " + run);
  out.write("fig04_q_p_" + dt + ".dat", q_against_p(s), "Fig. 4: " + run);
  out.write("fig05_qp_epsd_" + dt + ".dat", qp_against_deviatoric_strain(s, 5), "Fig. 5: " + run);
  out.write("fig06_epsv_" + dt + ".dat", volumetric_strain_against(s, t, 5), "Fig. 6: " + run);
  tables.fabric.push_back(qp_against_fabric(s, "fabric", 5));
  tables.strong.push_back(qp_against_fabric(s, "strong_fabric", 5));
  out.write("fig12_fabric_" + dt + ".dat", tables.fabric.back(), "Fig. 12: " + run);
  out.write("fig13_strong_fabric_" + dt + ".dat", tables.strong.back(), "Fig. 13: " + run);
  if (t == 5) {
    std::vector<std::string> titles;
    out.write("fig08_test5_" + d + ".dat", test5_blocks(s, test.legs, titles), "Fig. 8: " + run);
    out.values.texts("fig08_titles_" + d, titles);
  }
  // Fig. 9: cycles 1 and 5 (the last cycle run if fewer), one arrow scale for both.
  const int c2 = std::min(5, last_cycle(s));
  out.values.number("fig09_scale_" + dt, fig09_scale);
  out.values.number("fig09_cycle5_" + dt, c2);
  for (const auto& [c, tag] : std::vector<std::pair<int, std::string>>{{1, "cycle1"}, {c2, "cycle5"}}) {
    out.write("fig09_" + dt + "_" + tag + ".dat", strain_increments(s, c, fig09_scale), "Fig. 9: " + run);
    out.write("fig09_" + dt + "_" + tag + "_path.dat", cycle_stress_path(s, c), "Fig. 9: " + run);
  }
}

// Fig. 3: the worst leg's RMS tracking error (% of p) of each density's tests.
// Fig. 4: the range of p over every row of every test, and the target q of the legs.
void fig03_fig04_values(NoteContext& c, Values& v) {
  MinMax q_target;
  double p_target_sum = 0;
  int p_target_n = 0;
  for (const std::string& d : densities) {
    const DensityResults* r = c.results_of(d);
    if (!r || r->tests.empty()) continue;
    double worst = -1;
    int worst_test = 0;
    MinMax p;
    for (const TestResult& t : r->tests) {
      for (const char* col : {"rms_error_1", "rms_error_2", "rms_error_3"})
        if (t.legs.count(col))
          for (double e : t.legs.at(col))
            if (100 * e > worst) worst = 100 * e, worst_test = t.number;
      if (t.series.count(col::p))
        for (double x : t.series.at(col::p)) p.add(x / 1e3);
      if (t.legs.count(col::target_1))
        for (std::size_t k = 0; k < t.legs.at(col::target_1).size(); ++k) {
          const dem::Vec3 s(t.legs.at(col::target_1)[k], t.legs.at(col::target_2)[k], t.legs.at(col::target_3)[k]);
          q_target.add(dem::deviator_stress(dem::Mat3(s.asDiagonal())) / 1e3);
          p_target_sum += s.mean() / 1e3, ++p_target_n;
        }
    }
    if (worst >= 0) v["fig03.worst_" + d] = significant(worst, 2), v["fig03.worst_test_" + d] = std::to_string(worst_test);
    if (p.any()) v["fig04.p_" + d] = fig04_p_text(p);  // "stays within" it
  }
  if (q_target.any()) v["fig04.q_target"] = fixed_unsigned_zero(q_target.hi, 1);
  if (p_target_n) v["fig04.p_target"] = fixed_unsigned_zero(p_target_sum / p_target_n, 1);
}

// Fig. 6: εv (%) at the end of the last cycle shown (the paper's, or fewer if a test ran fewer)
// of each test of the chosen sample.
void fig06_values(NoteContext& c, Values& v) {
  int last = paper_cycles;
  for (const std::string& d : densities)
    if (const DensityResults* r = c.results_of(d))
      for (const TestResult& t : r->tests) last = std::min(last, last_cycle(t.series));
  v["fig06.cycle"] = std::to_string(last);
  for (const std::string& d : densities) {
    const DensityResults* r = c.results_of(d);
    if (!r) continue;
    MinMax ev;
    for (const TestResult& t : r->tests)
      if (const auto x = at_cycle_end(t, col::volumetric_strain, last)) ev.add(100 * *x);
    if (ev.any()) v["fig06.range_" + d] = range_text(ev.lo, ev.hi);
  }
  v["fig06.paper_loose"] = c.paper("ev_after_cycle", "loose");
  v["fig06.verdict_loose"] = c.phrase("ev_after_cycle", "loose");
}

// Fig. 13: the slope of q/p against the strong fabric ratio, per sample (the validation row).
void fig13_values(NoteContext& c, Values& v) {
  for (const std::string& d : densities) {
    const RowResult* r = c.values_of("qp_strong_fabric_slope", d);
    if (!r || r->valued == 0) continue;
    MinMax m;
    for (const auto& ps : r->samples)
      if (ps.measured.value) m.add(*ps.measured.value);
    v["fig13.slope_" + d] = r->valued > 1 ? mean_pm_sd(r->spread.mean, r->spread.sd) : fixed_unsigned_zero(r->spread.mean, 2);
    v["fig13.range_" + d] = range_fixed(m.lo, m.hi, 2);
    v["fig13.verdict_" + d] = c.phrase("qp_strong_fabric_slope", d);
    v["fig13.inside_" + d] = std::to_string(r->holds) + " of " + std::to_string(r->valued);
  }
  v["fig13.paper"] = c.paper("qp_strong_fabric_slope", "loose");
}

// Fig. 5: the largest εd (%) of each density's tests, cycles <= paper_cycles. Fig. 12: the largest
// fabric ratio and q/p of the chosen sample's tests, the same cycles. Fig. 8: Test 5's εv after its
// last cycle.
void fig05_fig08_fig12_values(NoteContext& c, Values& v) {
  MinMax fabric_all, qp_all;
  for (const std::string& d : densities) {
    const DensityResults* r = c.results_of(d);
    if (!r) continue;
    MinMax ed;
    for (const TestResult& t : r->tests) {
      if (!t.series.count(col::cycle)) continue;
      const auto& cyc = t.series.at(col::cycle);
      for (std::size_t i = 0; i < cyc.size(); ++i) {
        if (cyc[i] > paper_cycles) continue;
        if (t.series.count(col::deviatoric_strain)) ed.add(100 * t.series.at(col::deviatoric_strain)[i]);
        if (t.series.count("fabric_ratio")) fabric_all.add(t.series.at("fabric_ratio")[i]);
        if (t.series.count(col::q_over_p)) qp_all.add(t.series.at(col::q_over_p)[i]);
      }
      if (t.number == 5)
        if (const auto x = at_cycle_end(t, col::volumetric_strain, last_cycle(t.series))) {
          v["fig08.ev_" + d] = significant(100 * *x, 2);
          v["fig08.cycles"] = std::to_string(last_cycle(t.series));
        }
    }
    if (ed.any()) v["fig05.max_ed_" + d] = significant(ed.hi, 2);
  }
  if (fabric_all.any()) v["fig12.max_fabric"] = significant(fabric_all.hi, 2);
  if (qp_all.any()) v["fig12.max_qp"] = significant(qp_all.hi, 2);
}

// Fig. 9: the mean turn of the strain increments towards the path from cycle 1 to 5 (the rows).
void fig09_values(NoteContext& c, Values& v) {
  for (const auto& [quantity, d] : std::vector<std::pair<std::string, std::string>>{
           {"strain_increment_alignment_gain", "loose"}, {"strain_increment_alignment_gain_magnitude", "dense"}}) {
    const RowResult* r = c.values_of(quantity, d);
    if (!r || r->valued == 0) continue;
    v["fig09.turn_" + d] = r->valued > 1 ? mean_pm_sd(r->spread.mean, r->spread.sd) : significant(r->spread.mean, 2);
    v["fig09.verdict_" + d] = c.phrase(quantity, d);
  }
}

// The cell's shear stresses over the chosen sample's tests: the largest |sigma_ij| (i != j), and
// relative to p in the same row.
void shear_values(NoteContext& c, Values& v) {
  double shear_max = -1, shear_ratio = 0;
  std::string shear_run;
  for (const std::string& d : densities)
    if (const DensityResults* r = c.results_of(d))
      for (const TestResult& t : r->tests) {
        if (!t.series.count(col::stress_12) || !t.series.count(col::p)) continue;
        const auto& p = t.series.at(col::p);
        for (const char* col : {"stress_12", "stress_13", "stress_23"})
          for (std::size_t i = 0; i < p.size(); ++i) {
            const double s = std::abs(t.series.at(col)[i]);
            if (s > shear_max) shear_max = s, shear_ratio = p[i] > 0 ? s / p[i] : 0, shear_run = d + "_test" + std::to_string(t.number);
          }
      }
  if (shear_max < 0) return;
  v["shear.max_kPa"] = significant(shear_max / 1e3, 2);
  v["shear.max_percent_of_p"] = significant(100 * shear_ratio, 2);
  v["shear.run"] = shear_run;
}

}  // namespace

// The single-run figures of every test of the chosen sample, then what they share: the targets
// of Figs. 3-4 and the common axis of Figs. 12-13.
void single_run_figures_data(const FigureSource& src, FigureFolder& out) {
  const PathSettings sc = path_settings(src);
  const std::map<int, double> scale = fig09_scales(src);
  SingleRunTables tables;
  for (const std::string& d : src.densities) {
    std::vector<std::string> present;
    for (int t = 1; t <= 5; ++t) {
      const std::string dt = d + "_test" + std::to_string(t);
      const TestResult* test = find_test(src.chosen.densities.at(d), t);
      out.values.number("has_" + dt, test ? 1 : 0);
      const std::string run = src.from + "/" + dt;
      if (!test) {
        test_not_run(d, t, run, out);
        continue;
      }
      present.push_back(std::to_string(t));
      test_figures(d, *test, scale.at(t), run, tables, out);
    }
    out.values.number("has_" + d, present.empty() ? 0 : 1);
    out.values.text("fig14_tests_" + d, joined(present, ", "));
  }
  for (int t = 1; t <= 5; ++t)
    if (!tables.targets_done.count(t))
      out.write("fig03_test" + std::to_string(t) + "_target.dat", none_table("not run"), "Fig. 3: target path of Test " + std::to_string(t));
  out.write("fig03_states.dat", named_states(sc.p, sc.R), "Fig. 3: named states of the tests' stress paths");
  const Table q = target_q(sc.p, sc.R);
  out.write("fig04_targets.dat", q, "Fig. 4: target deviator stress");
  out.values.number("q_tc_kPa", q.rows[0][0]);
  out.values.number("q_te_kPa", q.rows[1][0]);
  std::vector<const Table*> all_fabric, all_strong;
  for (const Table& t : tables.fabric) all_fabric.push_back(&t);
  for (const Table& t : tables.strong) all_strong.push_back(&t);
  out.values.number("fig12_max", square_axis_max(all_fabric));
  out.values.number("fig13_max", square_axis_max(all_strong));
}

void single_run_figures_notes(NoteContext& c, Values& v) {
  fig03_fig04_values(c, v);
  fig06_values(c, v);
  fig13_values(c, v);
  fig05_fig08_fig12_values(c, v);
  fig09_values(c, v);
  shear_values(c, v);
}

}  // namespace validation
