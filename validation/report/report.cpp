#include "report/report.hpp"



#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "analysis/measurements.hpp"
#include "study/ensemble.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/markdown_table.hpp"
#include "judge/quantities.hpp"
#include "judge/weak_verdicts.hpp"
#include "study/columns.hpp"

namespace validation {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\n") - a + 1);
}

const std::vector<std::string>& densities = paper_densities();

}  // namespace

std::string section_name(const std::string& heading_line) {
  std::string name = heading_line.substr(0, heading_line.find_last_not_of("\r\n") + 1);
  name = name.substr(std::min(name.find_first_not_of('#'), name.size()));
  name = trim(name);
  const std::string appendix = "Appendix: ";
  if (name.rfind(appendix, 0) == 0) name = name.substr(appendix.size());
  // A section headed ⚠ by stamp_sections (other_mark: "⚠ ...: ") is still that section.
  if (const std::size_t end = name.find(": "); name.rfind("⚠ ", 0) == 0 && end != std::string::npos) return name.substr(end + 2);
  return name;
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
    } else if (const std::size_t or_at = tag.find(" or \""); or_at != std::string::npos) {
      // {{key or "text"}}: a value that may be absent (a setting no scene gives), said so by `text`.
      if (tag.back() != '"') throw std::runtime_error("template: {{" + tag + "}}: the text after 'or' must be quoted");
      const auto it = values.find(tag.substr(0, or_at));
      out += it == values.end() || it->second.empty() ? tag.substr(or_at + 5, tag.size() - or_at - 6) : it->second;
      i = b + 2;
    } else {
      const auto it = values.find(tag);
      if (it == values.end()) throw std::runtime_error("template: no value for {{" + tag + "}}");
      out += it->second;
      i = b + 2;
    }
  }
  return out;
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

std::string baseline_table(const nlohmann::json& before, const std::vector<RejudgedRow>& now_rows) {
  std::map<std::string, const nlohmann::json*> old;
  if (before.contains("rows"))
    for (const auto& r : before.at("rows")) old[r.value("name", "")] = &r;
  MarkdownTable md({"row", "earlier baseline: mean ± sd (verdict)", "now: mean ± sd (verdict)", "shift / max(earlier sd, resolution)"});
  const auto recorded_verdict = [](const std::string& verdict) {
    return verdict == "consistent" ? Verdict::Consistent : verdict == "inconsistent" ? Verdict::Inconsistent : Verdict::NotJudged;
  };
  for (const RejudgedRow& rr : now_rows) {
    const Row& r = rr.row;
    const RowResult& now = rr.result;
    const std::string now_text = now.valued ? (now.valued > 1 ? mean_pm_sd(now.spread.mean, now.spread.sd) : number(now.spread.mean))
                                            : std::string("—");
    std::string before_text = "not in the earlier baseline", shift = "—";
    if (const auto it = old.find(r.name); it != old.end()) {
      const nlohmann::json& o = *it->second;
      const bool has_mean = o.contains("mean") && o.at("mean").is_number();
      const double sd = o.contains("sd") && o.at("sd").is_number() ? o.at("sd").get<double>() : 0.0;
      before_text = has_mean ? (sd > 0 ? mean_pm_sd(o.at("mean").get<double>(), sd) : number(o.at("mean").get<double>())) : "—";
      before_text += " " + verdict_mark(recorded_verdict(o.value("verdict", "")));
      if (has_mean && now.valued) shift = shift_text(shift_in_sd(now.spread.mean - o.at("mean").get<double>(), sd, r.resolution));
    }
    md.row({r.name, before_text, now_text + " " + verdict_mark(now), shift});
  }
  return md.text();
}

std::string baseline_table(const nlohmann::json& before, const std::vector<Row>& rows, const std::vector<Sample>& samples) {
  std::vector<RejudgedRow> now;
  for (const Row& r : rows) now.push_back({r, r.density, evaluate(r, samples)});
  return baseline_table(before, now);
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
        if (t && t->series.count(col::q_over_p) && !t->series.at(col::q_over_p).empty()) text = significant(t->series.at(col::q_over_p).front(), 2);
        else if (it->second.prepared && it->second.sample.count(col::q_over_p)) text = significant(it->second.sample.at(col::q_over_p), 2);
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
                            c.count(col::stress_11) && c.count(col::stress_22) && c.count(col::stress_33);
          if (!have) continue;
          for (std::size_t i = 0; i < c.at(col::stress_11).size(); ++i) {
            const double p = (c.at(col::stress_11)[i] + c.at(col::stress_22)[i] + c.at(col::stress_33)[i]) / 3;
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

}  // namespace validation
