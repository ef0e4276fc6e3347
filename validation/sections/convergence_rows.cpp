#include "sections/convergence_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "study/ensemble.hpp"
#include "study/markdown_table.hpp"
#include "study/paths.hpp"

namespace validation {

// The factors of a budget in the table's order, with their names.
std::vector<std::pair<std::string, const FactorError*>> factors_of(const Budget& b) {
  return {{"Δt of the test", &b.time_step}, {"Δt of the preparation", &b.preparation_step}, {"rate", &b.rate}, {"size", &b.size}};
}

namespace {

// A row of the paper study's validation.json and the budget of its quantity at its density, if
// this study measured it: the factor from the budget's units to the row's, and whether cycles 1–2
// of Test 1 stand for the row's cycles.
struct RowBudget {
  const Budget* budget = nullptr;
  double scale = 1;
  bool proxy = false;
};

RowBudget budget_of_row(const nlohmann::json& row, const std::vector<DensityBudgets>& all) {
  // A row's quantity -> the budget's quantity and the factor to the row's units (εv: a fraction in
  // the summary, % in the rows).
  static const std::map<std::string, std::pair<std::string, double>> maps = {
      {"qp_strong_fabric_slope", {"qp_slope", 1}}, {"void_ratio_after_preparation", {"e0", 1}},
      {"coordination_after_preparation", {"coordination", 1}}, {"ev_growth", {"ev_growth_1_2", 100}},
      {"ev_growth_magnitude", {"ev_growth_1_2", 100}}, {"cn_change", {"cn_change_1_2", 1}},
      {"cn_change_magnitude", {"cn_change_1_2", 1}}};
  const std::string quantity = row.at("quantity").get<std::string>(), density = row.value("density", "");
  RowBudget r;
  if (!maps.count(quantity)) return r;
  for (const DensityBudgets& d : all)
    if (d.density == density)
      for (const Budget& x : d.budgets)
        if (x.quantity == maps.at(quantity).first) r.budget = &x, r.scale = maps.at(quantity).second;
  r.proxy = maps.at(quantity).first.find("_1_2") != std::string::npos;
  return r;
}

}  // namespace

std::string budget_number(double x) {
  if (!std::isfinite(x)) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

// The paragraph on the paper study's inconsistent rows: is each miss larger than the budget?
std::string verdict_reading(const std::vector<DensityBudgets>& all, const nlohmann::json& j, const std::string& validation_json) {
  std::ostringstream md;
  MarkdownTable t({"inconsistent row", "miss (ours to paper)", "budget of the settings (far end)", "reading"});
  int n = 0;
  for (const auto& row : j.at("rows")) {
    if (row.value("verdict", "") != "inconsistent") continue;
    ++n;
    const std::string name = row.at("name").get<std::string>(), quantity = row.at("quantity").get<std::string>();
    const std::string density = row.value("density", "");
    const double mean = row.at("mean").get<double>();
    const Region region =
        paper_region(row.at("check").get<std::string>(), row.at("reference").get<double>(), row.value("tolerance", 0.0));
    const double miss = region.contains(mean) ? 0 : std::min(std::abs(mean - region.low), std::abs(mean - region.high));
    const RowBudget rb = budget_of_row(row, all);
    if (!rb.budget) {
      const bool ran = std::any_of(all.begin(), all.end(), [&](const DensityBudgets& d) { return d.density == density; });
      t.row({name, budget_number(miss), "—", !ran ? "not covered: this study did not run the " + density + " density"
                                      : "not covered: the study has no such quantity (one test, two cycles)"});
      continue;
    }
    // The errors' sum as estimated, with each at the far end of its interval, and at its near end
    // (an error whose interval reaches zero adds nothing there): a miss is explained only when
    // even the near end reaches it, and beyond the budget only when the far end does not.
    double point = 0, far = 0, near = 0;
    for (const auto& [factor, f] : factors_of(*rb.budget))
      if (std::isfinite(f->error.value)) {
        const double hw = std::isfinite(f->error.half_width) ? f->error.half_width : std::abs(f->error.value);
        point += std::abs(f->error.value);
        far += std::abs(f->error.value) + hw;
        near += std::max(0.0, std::abs(f->error.value) - hw);
      }
    point *= rb.scale, far *= rb.scale, near *= rb.scale;
    std::string reading = miss > far    ? "larger than the budget: not the settings' error"
                          : miss <= near ? "within the budget even at the near end of its intervals: no evidence against the reproduction"
                                         : "within the intervals of the settings' errors, which are too wide to say whether they explain it: "
                                           "these samples cannot tell";
    if (rb.proxy) reading += " (cycles 1–2 of Test 1 stand for the row's 1–5)";
    t.row({name, budget_number(miss), budget_number(point) + " (≤ " + budget_number(far) + ")", reading});
  }
  if (n == 0) return "";
  md << "\nThe paper study's inconsistent rows (`" << shown_path(validation_json) << "`) against the budget: the miss is the distance "
        "from our ensemble's mean to the paper's region; the budget the sum of the paper's settings' errors in the test's and the "
        "preparation's time step, the rate and the size as estimated (and with each at the far end of its interval), in the row's units; "
        "a miss is explained by the settings only if the sum with each error at the near end of its interval reaches it.\n\n"
     << t.text();
  return md.str();
}

// Is each factor's error known well enough to judge the rows it serves? Every row of the paper
// study whose quantity the budget measures: its scale (the tolerance, or for a one-sided row the
// threshold's distance from zero), the widest half-width of the four factors in the row's units,
// and for each factor wider than the scale the samples that would bring it within.
std::string precision_table(const std::vector<DensityBudgets>& all, const nlohmann::json& j) {
  MarkdownTable t({"row", "scale", "widest 95 % half-width", "of", "within", "samples it would need"});
  int rows = 0, within = 0;
  for (const auto& row : j.at("rows")) {
    const RowBudget rb = budget_of_row(row, all);
    if (!rb.budget) continue;
    const double tol = row.value("tolerance", 0.0) > 0 ? row.value("tolerance", 0.0) : std::abs(row.at("reference").get<double>());
    if (!(tol > 0)) continue;
    double widest = 0;
    std::string of, needs;
    bool known = true;
    for (const auto& [factor, f] : factors_of(*rb.budget)) {
      if (!std::isfinite(f->error.value)) continue;
      const double hw = f->error.half_width * rb.scale;
      if (!std::isfinite(hw)) known = false;
      else if (hw > widest) widest = hw, of = factor;
      if (!(hw <= tol)) {
        const long n = samples_needed(*f, tol / rb.scale);
        needs += (needs.empty() ? "" : "; ") + factor + ": " +
                 (n < 0 ? std::string("cannot say") : std::to_string(n) + (f->across_sizes ? " samples over the sizes (today " +
                                                                             std::to_string(f->samples) + ")" : " per setting (today " +
                                                                             std::to_string(f->samples) + ")"));
      }
    }
    const bool ok = known && widest <= tol;
    ++rows, within += ok;
    t.row({row.at("name").get<std::string>() + (rb.proxy ? ", read on cycles 1–2 of Test 1" : ""), budget_number(tol), known ? budget_number(widest) : "—", of,
           ok ? "yes" : "no", needs.empty() ? "—" : needs});
  }
  if (rows == 0) return "";
  std::ostringstream md;
  md << "\nIs each factor's error known to within the rows it serves? For each row of the paper study that the budget measures: "
        "the row's tolerance (for a one-sided row, its threshold's distance from zero), the widest 95 % half-width of the four "
        "factors in the row's units, and the samples a wider factor would need. " << within << " of " << rows << " rows within.\n\n"
     << t.text();
  return md.str();
}

}  // namespace validation
