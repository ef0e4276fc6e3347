#include "rows.hpp"

#include "config/yaml_section.hpp"

namespace validation {

std::vector<Row> load_references(const std::string& file, const std::string& profile) {
  dem::Section root = dem::Section::load_file(file);
  root.text("source", std::nullopt, "where the reference values come from");
  std::vector<Row> rows;
  for (dem::Section& s : root.list("rows", "the checked statements")) {
    Row r;
    r.name = s.text("name", std::nullopt, "row name");
    r.quantity = s.text("quantity", std::nullopt, "what is computed");
    if (!known_quantity(r.quantity)) s.fail("quantity", "unknown quantity '" + r.quantity + "'");
    r.density = s.choice("density", {"loose", "medium", "dense"}, std::nullopt, "which sample");
    r.reference = s.number("reference", "", {-1e9, 1e9}, std::nullopt, "reference value");
    r.check = s.choice("check", {"within", "at_least", "at_most"}, std::nullopt, "how measured and reference compare");
    r.tolerance = s.number("tolerance", "", {0, 1e9}, 0.0, "allowed |measured - reference| for check: within");
    r.resolution = s.number("resolution", "", {0, 1e9}, 0.0,
                            "the smallest difference that means something (shifts are counted in max(sd, resolution))");
    r.must_pass = s.boolean("must_pass", false, "an inconsistent verdict fails the validation");
    r.reason = s.text("reason", std::nullopt, "why this tolerance");
    r.source = s.text("source", std::nullopt, "table, figure or section of the paper");
    r.group = s.text("group", std::string("other"), "the report's group of rows (one tornado chart each)");
    r.rule = s.choice("rule", {"interval", "majority"}, std::string("interval"),
                      "interval: the paper's region overlaps the 95 % prediction interval of one sample; "
                      "majority: the statement holds in more than half of the samples (trends, orderings)");
    r.cycle = static_cast<int>(s.integer("cycle", 0, 1000, 0, "cycle for per-cycle quantities"));
    r.from_cycle = static_cast<int>(s.integer("from_cycle", 0, 1000, 0, "first cycle of a change"));
    r.to_cycle = static_cast<int>(s.integer("to_cycle", 0, 1000, 0, "last cycle of a change"));
    r.test = static_cast<int>(s.integer("test", 0, 5, 0, "the test an ordering row is about (ev_lead, ev_lag)"));
    bool keep = profile == "paper";
    if (s.has("quick")) {
      dem::Section q = s.child("quick", "tolerance and must_pass of the row for the quick profile");
      const double tol = q.number("tolerance", "", {0, 1e9}, r.tolerance, "tolerance at the quick size");
      const bool must = q.boolean("must_pass", false, "must be consistent at the quick size");
      const std::string why = q.text("reason", std::nullopt, "why the quick tolerance differs");
      q.finish();
      if (profile == "quick") r.tolerance = tol, r.must_pass = must, r.reason = why, keep = true;
    }
    s.finish();
    if (keep) rows.push_back(r);
  }
  root.finish();
  return rows;
}

RowResult judge_values(const Row& row, std::vector<RowResult::PerSample> samples) {
  RowResult out;
  out.paper = paper_region(row.check, row.reference, row.tolerance);
  std::vector<double> values;
  for (const RowResult::PerSample& ps : samples)
    if (ps.measured.value) {
      values.push_back(*ps.measured.value);
      out.holds += out.paper.contains(*ps.measured.value);
    }
  out.samples = std::move(samples);
  out.valued = static_cast<int>(values.size());
  out.spread = spread(values);
  if (row.rule == "majority")
    out.verdict = out.valued < 2 ? Verdict::NotJudged : 2 * out.holds > out.valued ? Verdict::Consistent : Verdict::Inconsistent;
  else
    out.verdict = judge(out.spread, out.paper);
  return out;
}

RowResult shifted(const Row& row, const RowResult& r, double by) {
  std::vector<RowResult::PerSample> samples = r.samples;
  for (RowResult::PerSample& ps : samples)
    if (ps.measured.value) *ps.measured.value += by;
  return judge_values(row, std::move(samples));
}

RowResult evaluate(const Row& row, const std::vector<std::pair<std::string, const DensityResults*>>& samples) {
  std::vector<RowResult::PerSample> values;
  for (const auto& [name, results] : samples)
    values.push_back({name, results ? compute({row.quantity, row.density, row.cycle, row.from_cycle, row.to_cycle, row.test}, *results)
                                    : Measured{std::nullopt, "no results"}});
  return judge_values(row, std::move(values));
}

RowResult evaluate(const Row& row, const std::vector<Sample>& samples) {
  std::vector<std::pair<std::string, const DensityResults*>> of_density;
  for (const Sample& s : samples) {
    const auto it = s.densities.find(row.density);
    of_density.emplace_back(s.name, it == s.densities.end() ? nullptr : &it->second);
  }
  return evaluate(row, of_density);
}

}  // namespace validation
