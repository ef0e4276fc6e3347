#include "report.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/measurements.hpp"
#include "ensemble.hpp"
#include "format.hpp"
#include "markdown_table.hpp"
#include "quantities.hpp"

namespace validation {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\n") - a + 1);
}

const std::vector<std::string> densities = {"loose", "medium", "dense"};

std::string fixed_text(double x, int decimals) {
  if (!std::isfinite(x)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // "-0.00" -> "0.00"
  return s;
}

// "lo–hi" with `decimals`, one value if both print alike.
std::string range_fixed(double lo, double hi, int decimals) {
  const std::string a = fixed_text(lo, decimals), b = fixed_text(hi, decimals);
  return a == b ? a : a + "–" + b;
}

// An energy [J]: three significant digits, in powers of ten below 0.01 J.
std::string energy_text(double x) {
  if (!std::isfinite(x)) return "—";
  if (x != 0 && std::abs(x) < 1e-2) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", x);
    return buf;
  }
  return significant(x, 3);
}

// A percentage that may be at rounding level: two significant digits, in powers of ten below 0.001.
std::string percent_small(double x) {
  if (!std::isfinite(x)) return "—";
  if (x != 0 && std::abs(x) < 1e-3) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", x);
    return buf;
  }
  return significant(x, 2);
}

const TestResult* find_test(const DensityResults& r, int t) {
  for (const TestResult& x : r.tests)
    if (x.number == t) return &x;
  return nullptr;
}

struct MinMax {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double x) { lo = std::min(lo, x), hi = std::max(hi, x); }
  bool any() const { return lo <= hi; }
};

// A per-cycle statistics table's row of cycle c (cycle_statistics: cycle, mean, sd, n, min, max).
const std::vector<double>* cycle_row(const Table& t, int c) {
  for (const auto& r : t.rows)
    if (static_cast<int>(r[0]) == c) return &r;
  return nullptr;
}

}  // namespace

namespace {

// The text before the first level-2 heading, then each "## heading" section in order.
std::pair<std::string, std::vector<std::pair<std::string, std::string>>> sections_of(const std::string& text) {
  std::pair<std::string, std::vector<std::pair<std::string, std::string>>> out;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    end = end == std::string::npos ? text.size() : end + 1;
    const std::string line = text.substr(at, end - at);
    if (line.rfind("## ", 0) == 0) out.second.emplace_back(line.substr(0, line.find_last_not_of("\r\n") + 1), "");
    (out.second.empty() ? out.first : out.second.back().second) += line;
    at = end;
  }
  return out;
}

}  // namespace

std::string keep_sections_without_inputs(const std::string& fresh, const std::string& previous, std::vector<std::string>& kept) {
  const auto now = sections_of(fresh), before = sections_of(previous);
  std::string out = now.first;
  for (const auto& section : now.second) {
    const auto& [heading, text] = section;  // a lambda takes the pair (clang 14 captures no structured binding)
    const auto old = std::find_if(before.second.begin(), before.second.end(), [&](const auto& s) { return s.first == section.first; });
    if (text.find(inputs_not_here) != std::string::npos && old != before.second.end()) {
      out += old->second;
      kept.push_back(heading.substr(3));
    } else {
      out += text;
    }
  }
  return out;
}

std::string fill(const std::string& t, const Values& values) {
  std::string out;
  std::size_t i = 0;
  while (i < t.size()) {
    const std::size_t a = t.find("{{", i);
    if (a == std::string::npos) {
      out += t.substr(i);
      break;
    }
    out += t.substr(i, a - i);
    const std::size_t b = t.find("}}", a);
    if (b == std::string::npos) throw std::runtime_error("template: '{{' without '}}'");
    const std::string tag = trim(t.substr(a + 2, b - a - 2));
    if (tag.rfind("#if ", 0) == 0) {
      const std::string key = trim(tag.substr(4));
      int depth = 1;
      std::size_t j = b + 2, else_at = std::string::npos, else_end = 0, end_at = 0, end_end = 0;
      while (depth > 0) {
        const std::size_t c = t.find("{{", j);
        if (c == std::string::npos) throw std::runtime_error("template: {{#if " + key + "}} without {{/if}}");
        const std::size_t d = t.find("}}", c);
        if (d == std::string::npos) throw std::runtime_error("template: '{{' without '}}'");
        const std::string inner = trim(t.substr(c + 2, d - c - 2));
        if (inner.rfind("#if ", 0) == 0) ++depth;
        else if (inner == "/if" && --depth == 0) end_at = c, end_end = d + 2;
        else if (inner == "else" && depth == 1) else_at = c, else_end = d + 2;
        j = d + 2;
      }
      const auto it = values.find(key);
      const bool on = it != values.end() && !it->second.empty();
      if (on) out += fill(t.substr(b + 2, (else_at == std::string::npos ? end_at : else_at) - (b + 2)), values);
      else if (else_at != std::string::npos) out += fill(t.substr(else_end, end_at - else_end), values);
      i = end_end;
    } else {
      const auto it = values.find(tag);
      if (it == values.end()) throw std::runtime_error("template: no value for {{" + tag + "}}");
      out += it->second;
      i = b + 2;
    }
  }
  return out;
}

std::string range_text(double lo, double hi) {
  const double m = std::max(std::abs(lo), std::abs(hi));
  if (!(m > 0) || !std::isfinite(m)) return range_fixed(lo, hi, 0);
  int e = static_cast<int>(std::floor(std::log10(m)));
  if (std::round(m / std::pow(10.0, e - 1)) >= 100) ++e;
  return range_fixed(lo, hi, std::max(0, 1 - e));
}

std::string verdict_phrase(Verdict v) {
  return v == Verdict::Consistent ? "as in the paper" : v == Verdict::Inconsistent ? "unlike the paper" : "not judged";
}

Values figure_values(const ReportInputs& in) {
  Values v;
  // The constants the computations below use, for the sentences that quote them.
  v["paper.particles"] = thousands(std::lround(paper_particles));
  v["cycles.shown"] = std::to_string(paper_cycles);
  v["energy.parting_percent"] = significant(100 * energy_parting_fraction, 2);
  v["shift.clip"] = significant(shift_clip, 2);
  // The cycles a paper row reads, for the sentences about it ("after 5 cycles", "from cycle 1 to 5").
  for (const Row& r : in.paper) {
    if (r.quantity == "ev_after_cycle" && r.density == "loose") v["fig06.paper_cycle"] = std::to_string(r.cycle);
    if (r.quantity == "strain_increment_alignment_gain" && r.density == "loose")
      v["fig09.from_cycle"] = std::to_string(r.from_cycle), v["fig09.to_cycle"] = std::to_string(r.to_cycle);
  }
  if (in.samples.empty()) return v;
  auto chosen = std::find_if(in.samples.begin(), in.samples.end(), [&](const Sample& s) { return s.name == in.sample; });
  if (chosen == in.samples.end()) chosen = in.samples.begin();
  v["sample"] = chosen->name.empty() ? "the sample" : chosen->name;
  v["samples_n"] = std::to_string(in.samples.size());
  const auto results_of = [&](const std::string& d) -> const DensityResults* {
    const auto it = chosen->densities.find(d);
    return it == chosen->densities.end() ? nullptr : &it->second;
  };
  // The verdict of the validation row about (quantity, density), judged on the same samples.
  std::map<std::string, RowResult> judged;
  const auto row_result = [&](const std::string& quantity, const std::string& density) -> const RowResult* {
    for (const Row& r : in.rows)
      if (r.quantity == quantity && r.density == density) {
        auto it = judged.find(r.name);
        if (it == judged.end()) it = judged.emplace(r.name, evaluate(r, in.samples)).first;
        return &it->second;
      }
    return nullptr;
  };
  const auto phrase = [&](const std::string& quantity, const std::string& density) {
    const RowResult* r = row_result(quantity, density);
    return r ? verdict_phrase(r->verdict) : std::string("not judged at this size: no row in this profile");
  };
  // A row's values on these samples even when the profile does not judge it (the quick profile
  // leaves out rows that need the full size): the data are shown, the verdict is not.
  std::map<std::string, RowResult> valued;
  const auto values_of = [&](const std::string& quantity, const std::string& density) -> const RowResult* {
    if (const RowResult* r = row_result(quantity, density)) return r;
    for (const Row& r : in.paper)
      if (r.quantity == quantity && r.density == density) {
        auto it = valued.find(r.name);
        if (it == valued.end()) it = valued.emplace(r.name, evaluate(r, in.samples)).first;
        return &it->second;
      }
    return nullptr;
  };
  const auto paper = [&](const std::string& quantity, const std::string& density) {
    const auto x = paper_value(in.paper, quantity, density);
    return x ? number(*x) : std::string("—");
  };

  // Fig. 2: the cell side of each prepared sample, scaled to the paper's sample size.
  for (const std::string& d : densities) {
    const DensityResults* r = results_of(d);
    if (!r || !r->prepared) continue;
    const double volume = r->sample.at("cell_length_1") * r->sample.at("cell_length_2") * r->sample.at("cell_length_3");
    const auto n = r->sample.find("particles");
    const double scale = n != r->sample.end() && n->second > 0 ? paper_particles / n->second : 1;
    v["fig02.side_" + d] = fixed_text(100 * std::cbrt(volume * scale), 2);
    v["fig02.paper_" + d] = paper("cell_side_cm_after_preparation", d);
    v["fig02.verdict_" + d] = phrase("cell_side_cm_after_preparation", d);
  }

  // Fig. 3: the worst leg's RMS tracking error (% of p) of each density's tests.
  // Fig. 4: the range of p over every row of every test, and the target q of the legs.
  MinMax q_target;
  double p_target_sum = 0;
  int p_target_n = 0;
  for (const std::string& d : densities) {
    const DensityResults* r = results_of(d);
    if (!r || r->tests.empty()) continue;
    double worst = -1;
    int worst_test = 0;
    MinMax p;
    for (const TestResult& t : r->tests) {
      for (const char* c : {"rms_error_1", "rms_error_2", "rms_error_3"})
        if (t.legs.count(c))
          for (double e : t.legs.at(c))
            if (100 * e > worst) worst = 100 * e, worst_test = t.number;
      if (t.series.count("p"))
        for (double x : t.series.at("p")) p.add(x / 1e3);
      if (t.legs.count("target_1"))
        for (std::size_t k = 0; k < t.legs.at("target_1").size(); ++k) {
          const dem::Vec3 s(t.legs.at("target_1")[k], t.legs.at("target_2")[k], t.legs.at("target_3")[k]);
          q_target.add(dem::deviator_stress(dem::Mat3(s.asDiagonal())) / 1e3);
          p_target_sum += s.mean() / 1e3, ++p_target_n;
        }
    }
    if (worst >= 0) v["fig03.worst_" + d] = significant(worst, 2), v["fig03.worst_test_" + d] = std::to_string(worst_test);
    if (p.any()) v["fig04.p_" + d] = range_fixed(p.lo, p.hi, 2);
  }
  if (q_target.any()) v["fig04.q_target"] = fixed_text(q_target.hi, 1);
  if (p_target_n) v["fig04.p_target"] = fixed_text(p_target_sum / p_target_n, 1);

  // Fig. 6: εv (%) at the end of the last cycle shown (the paper's, or fewer if a test ran fewer) of each
  // test of the chosen sample.
  {
    int c = paper_cycles;
    for (const std::string& d : densities)
      if (const DensityResults* r = results_of(d))
        for (const TestResult& t : r->tests) c = std::min(c, last_cycle(t.series));
    v["fig06.cycle"] = std::to_string(c);
    for (const std::string& d : densities) {
      const DensityResults* r = results_of(d);
      if (!r) continue;
      MinMax ev;
      for (const TestResult& t : r->tests)
        if (const auto x = at_cycle_end(t, "volumetric_strain", c)) ev.add(100 * *x);
      if (ev.any()) v["fig06.range_" + d] = range_text(ev.lo, ev.hi);
    }
    v["fig06.paper_loose"] = paper("ev_after_cycle", "loose");
    v["fig06.verdict_loose"] = phrase("ev_after_cycle", "loose");
  }

  // Figs. 7, 10, 11: the ensemble's per-cycle mean over the samples, per test.
  const auto table_of = [&](const CycleQuantity& q, const std::string& d, int t) {
    std::vector<const TestResult*> tests;
    for (const Sample& s : in.samples)
      if (const auto it = s.densities.find(d); it != s.densities.end())
        if (const TestResult* x = find_test(it->second, t)) tests.push_back(x);
    return cycle_statistics(tests, q);
  };
  const auto& quantities = cycle_quantities();
  // The last cycle every test of every sample reached (at most the paper's).
  int c_all = paper_cycles;
  bool any_test = false;
  for (const Sample& s : in.samples)
    for (const auto& [d, r] : s.densities)
      for (const TestResult& t : r.tests) c_all = std::min(c_all, last_cycle(t.series)), any_test = true;
  if (any_test && c_all >= 1) {
    v["cycles.last"] = std::to_string(c_all);
    for (const std::string& d : densities) {
      MinMax growth, dense_abs, cn0, cn1, cnc, sliding;
      for (int t = 1; t <= 5; ++t) {
        const Table ev = table_of(quantities[0], d, t), cn = table_of(quantities[1], d, t), sl = table_of(quantities[2], d, t);
        const auto* e1 = cycle_row(ev, 1);
        const auto* ec = cycle_row(ev, c_all);
        if (e1 && ec) {
          growth.add((*ec)[1] - (*e1)[1]);
          if (d == "loose") v["fig07.loose_test" + std::to_string(t)] = mean_pm_sd((*ec)[1], (*ec)[2]);
        }
        for (const auto& row : ev.rows)
          if (row[0] <= c_all) dense_abs.add(std::abs(row[1]));
        if (const auto* r = cycle_row(cn, 0)) cn0.add((*r)[1]);
        if (const auto* r = cycle_row(cn, 1)) cn1.add((*r)[1]);
        if (const auto* r = cycle_row(cn, c_all)) cnc.add((*r)[1]);
        const auto* s1 = cycle_row(sl, 1);
        const auto* sc = cycle_row(sl, c_all);
        if (s1 && sc) sliding.add((*sc)[1] - (*s1)[1]);
      }
      if (growth.any()) v["fig07.growth_" + d] = range_text(growth.lo, growth.hi);
      if (dense_abs.any()) v["fig07.max_abs_" + d] = significant(dense_abs.hi, 2);
      v["fig07.verdict_" + d] = d == "dense" ? phrase("ev_growth_magnitude", d) : phrase("ev_growth", d);
      if (cn0.any()) v["fig10.start_" + d] = range_fixed(cn0.lo, cn0.hi, 2);
      if (cn1.any()) v["fig10.cycle1_" + d] = range_fixed(cn1.lo, cn1.hi, 2);
      if (cnc.any()) v["fig10.last_" + d] = range_fixed(cnc.lo, cnc.hi, 2);
      v["fig10.verdict_" + d] = d == "dense" ? phrase("cn_change_magnitude", d) : phrase("cn_change", d);
      if (sliding.any()) v["fig11.change_" + d] = range_text(sliding.lo, sliding.hi);
      v["fig11.verdict_" + d] = d == "loose" ? phrase("sliding_change", d) : phrase("sliding_change_magnitude", d);
    }
  }

  // Fig. 13: the slope of q/p against the strong fabric ratio, per sample (the validation row).
  for (const std::string& d : densities) {
    const RowResult* r = values_of("qp_strong_fabric_slope", d);
    if (!r || r->valued == 0) continue;
    MinMax m;
    for (const auto& ps : r->samples)
      if (ps.measured.value) m.add(*ps.measured.value);
    v["fig13.slope_" + d] = r->valued > 1 ? mean_pm_sd(r->spread.mean, r->spread.sd) : fixed_text(r->spread.mean, 2);
    v["fig13.range_" + d] = range_fixed(m.lo, m.hi, 2);
    v["fig13.verdict_" + d] = phrase("qp_strong_fabric_slope", d);
  }
  v["fig13.paper"] = paper("qp_strong_fabric_slope", "loose");

  // Fig. 5: the largest εd (%) of each density's tests, cycles <= paper_cycles. Fig. 12: the largest
  // fabric ratio and q/p of the chosen sample's tests, the same cycles. Fig. 8: Test 5's εv after its last cycle.
  {
    MinMax fabric_all, qp_all;
    for (const std::string& d : densities) {
      const DensityResults* r = results_of(d);
      if (!r) continue;
      MinMax ed;
      for (const TestResult& t : r->tests) {
        if (!t.series.count("cycle")) continue;
        const auto& cyc = t.series.at("cycle");
        for (std::size_t i = 0; i < cyc.size(); ++i) {
          if (cyc[i] > paper_cycles) continue;
          if (t.series.count("deviatoric_strain")) ed.add(100 * t.series.at("deviatoric_strain")[i]);
          if (t.series.count("fabric_ratio")) fabric_all.add(t.series.at("fabric_ratio")[i]);
          if (t.series.count("q_over_p")) qp_all.add(t.series.at("q_over_p")[i]);
        }
        if (t.number == 5)
          if (const auto x = at_cycle_end(t, "volumetric_strain", last_cycle(t.series))) {
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
  for (const auto& [quantity, d] : std::vector<std::pair<std::string, std::string>>{
           {"strain_increment_alignment_gain", "loose"}, {"strain_increment_alignment_gain_magnitude", "dense"}}) {
    const RowResult* r = values_of(quantity, d);
    if (!r || r->valued == 0) continue;
    v["fig09.turn_" + d] = r->valued > 1 ? mean_pm_sd(r->spread.mean, r->spread.sd) : significant(r->spread.mean, 2);
    v["fig09.verdict_" + d] = phrase(quantity, d);
  }

  // The energy balance of Test 1 of each density (the energy figure).
  bool old_first_row = false;
  for (const std::string& d : densities) {
    const DensityResults* r = results_of(d);
    const TestResult* t = r ? find_test(*r, 1) : nullptr;
    if (!t) continue;
    try {
      const EnergyCurves c = energy_curves(t->series);
      old_first_row = old_first_row || c.baseline_row > 0;
      v["energy.work_" + d] = energy_text(c.work_total_J());
      v["energy.closure_" + d] = percent_small(100 * c.closure_relative_to_work());
      if (const auto at = c.parting_time_s(energy_parting_fraction)) v["energy.parts_at_" + d] = significant(*at, 3);
    } catch (const std::out_of_range&) {
      // a result without the energy columns: no keys, the note says the data is missing
    }
  }
  if (old_first_row) v["energy.old_first_row"] = "yes";

  // The cell's shear stresses over the chosen sample's tests: the largest |sigma_ij| (i != j), and
  // relative to p in the same row.
  double shear_max = -1, shear_ratio = 0;
  std::string shear_run;
  for (const std::string& d : densities)
    if (const DensityResults* r = results_of(d))
      for (const TestResult& t : r->tests) {
        if (!t.series.count("stress_12") || !t.series.count("p")) continue;
        const auto& p = t.series.at("p");
        for (const char* c : {"stress_12", "stress_13", "stress_23"})
          for (std::size_t i = 0; i < p.size(); ++i) {
            const double s = std::abs(t.series.at(c)[i]);
            if (s > shear_max) shear_max = s, shear_ratio = p[i] > 0 ? s / p[i] : 0, shear_run = d + "_test" + std::to_string(t.number);
          }
      }
  if (shear_max >= 0) {
    v["shear.max_kPa"] = significant(shear_max / 1e3, 2);
    v["shear.max_percent_of_p"] = significant(100 * shear_ratio, 2);
    v["shear.run"] = shear_run;
  }
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

std::string energy_table(const std::vector<std::pair<std::string, const Columns*>>& runs) {
  MarkdownTable md({"run", "curves from", "work by the cell (J)", "change of stored (J)", "dissipated by damping (J)", "by sliding (J)",
                    "largest gap / the run's work", "largest closure error (engine: / (stored at start + work))"});
  for (const auto& [name, series] : runs) {
    try {
      const EnergyCurves c = energy_curves(*series);
      if (c.time_s.empty()) continue;
      double engine_worst = 0;
      for (double e : series->at("energy_closure_error")) engine_worst = std::max(engine_worst, e);
      char err[32];
      std::snprintf(err, sizeof err, "%.1e", engine_worst);
      md.row({name, "row " + std::to_string(c.baseline_row + 1) + " (t = " + number(c.time_s.front()) + " s)",
              energy_text(c.work_total_J()), energy_text(c.stored_change_J.back()), energy_text(c.damping_J.back()),
              energy_text(c.friction_J.back()), percent_small(100 * c.closure_relative_to_work()) + " %", err});
    } catch (const std::out_of_range&) {
      md.row({name, "—", "no energy columns in this result", "", "", "", "", ""});
    }
  }
  return md.text();
}

std::string baseline_table(const nlohmann::json& before, const std::vector<Row>& rows, const std::vector<Sample>& samples) {
  std::map<std::string, const nlohmann::json*> old;
  if (before.contains("rows"))
    for (const auto& r : before.at("rows")) old[r.value("name", "")] = &r;
  MarkdownTable md({"row", "earlier baseline: mean ± sd (verdict)", "now: mean ± sd (verdict)", "shift / max(earlier sd, resolution)"});
  const auto mark = [](const std::string& verdict) {
    return verdict == "consistent" ? "✅" : verdict == "inconsistent" ? "❌" : "—";
  };
  for (const Row& r : rows) {
    const RowResult now = evaluate(r, samples);
    const std::string now_text = now.valued ? (now.valued > 1 ? mean_pm_sd(now.spread.mean, now.spread.sd) : number(now.spread.mean))
                                            : std::string("—");
    std::string before_text = "not in the earlier baseline", shift = "—";
    if (const auto it = old.find(r.name); it != old.end()) {
      const nlohmann::json& o = *it->second;
      const bool has_mean = o.contains("mean") && o.at("mean").is_number();
      const double sd = o.contains("sd") && o.at("sd").is_number() ? o.at("sd").get<double>() : 0.0;
      before_text = has_mean ? (sd > 0 ? mean_pm_sd(o.at("mean").get<double>(), sd) : number(o.at("mean").get<double>())) : "—";
      before_text += std::string(" ") + mark(o.value("verdict", ""));
      if (has_mean && now.valued) shift = shift_text(shift_in_sd(now.spread.mean - o.at("mean").get<double>(), sd, r.resolution));
    }
    md.row({r.name, before_text, now_text + " " + mark(to_string(now.verdict)), shift});
  }
  return md.text();
}

std::string state_a_table(const std::vector<Sample>& samples) {
  std::vector<std::string> headings = {"sample"};
  headings.insert(headings.end(), densities.begin(), densities.end());
  MarkdownTable md(headings);
  for (const Sample& s : samples) {
    std::vector<std::string> cells = {s.name.empty() ? "the sample" : s.name};
    for (const std::string& d : densities) {
      const auto it = s.densities.find(d);
      std::string text = "—";
      if (it != s.densities.end()) {
        // The start of shearing: the first row of a test (the saved sample), else the preparation's last row.
        const TestResult* t = it->second.tests.empty() ? nullptr : &it->second.tests.front();
        if (t && t->series.count("q_over_p") && !t->series.at("q_over_p").empty()) text = significant(t->series.at("q_over_p").front(), 2);
        else if (it->second.prepared && it->second.sample.count("q_over_p")) text = significant(it->second.sample.at("q_over_p"), 2);
      }
      cells.push_back(text);
    }
    md.row(cells);
  }
  return md.text();
}

std::string shear_control_table(const std::vector<Sample>& samples) {
  std::vector<std::string> headings = {"sample"};
  for (const std::string& d : densities) headings.push_back(d + ": max |γ| / max |σ_ij|/p");
  MarkdownTable md(headings);
  const char* gammas[] = {"shear_strain_12", "shear_strain_13", "shear_strain_23"};
  const char* shears[] = {"stress_12", "stress_13", "stress_23"};
  for (const Sample& s : samples) {
    std::vector<std::string> cells = {s.name.empty() ? "the sample" : s.name};
    for (const std::string& d : densities) {
      const auto it = s.densities.find(d);
      double gamma = -1, ratio = -1;
      if (it != s.densities.end())
        for (const TestResult& t : it->second.tests) {
          const Columns& c = t.series;
          const bool have = std::all_of(std::begin(gammas), std::end(gammas), [&](const char* k) { return c.count(k) > 0; }) &&
                            std::all_of(std::begin(shears), std::end(shears), [&](const char* k) { return c.count(k) > 0; }) &&
                            c.count("stress_11") && c.count("stress_22") && c.count("stress_33");
          if (!have) continue;
          for (std::size_t i = 0; i < c.at("stress_11").size(); ++i) {
            const double p = (c.at("stress_11")[i] + c.at("stress_22")[i] + c.at("stress_33")[i]) / 3;
            for (int k = 0; k < 3; ++k) {
              gamma = std::max(gamma, std::abs(c.at(gammas[k])[i]));
              if (p > 0) ratio = std::max(ratio, std::abs(c.at(shears[k])[i]) / p);
            }
          }
        }
      cells.push_back(gamma < 0 ? "—" : significant(gamma, 2) + " / " + (ratio < 0 ? "—" : significant(ratio, 2)));
    }
    md.row(cells);
  }
  return md.text();
}

namespace {

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

void check_previous_report(const std::string& previous, const std::string& fresh, const std::string& what) {
  if (const std::size_t at = dem::first_non_text(previous); at != std::string::npos)
    throw std::runtime_error(what + " is not a report: binary content at byte " + std::to_string(at) +
                             " (an HDF5 or other binary file?); give an earlier reports/index.md");
  const std::string title = first_line(fresh), theirs = first_line(previous);
  if (theirs != title)
    throw std::runtime_error(what + " is not a report of this template: its first line is '" +
                             (theirs.size() > 80 ? theirs.substr(0, 80) + "..." : theirs) + "', expected '" + title + "'");
  if (previous.find("\nGenerated on ") == std::string::npos)
    throw std::runtime_error(what + " is not a report of this template: it has no 'Generated on' line");
  const auto sections = sections_of(fresh).second;
  const std::string last = sections.empty() ? "" : sections.back().first;
  if (previous.empty() || previous.back() != '\n' || (!last.empty() && previous.find("\n" + last + "\n") == std::string::npos))
    throw std::runtime_error(what + " is cut short: it ends before its last section '" + last + "' (a truncated copy?)");
}

}  // namespace validation
