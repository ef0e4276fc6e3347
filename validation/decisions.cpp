#include "decisions.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace validation {

namespace {

RowResult evaluate_on(const Row& row, const ReadingResults& samples) {
  std::vector<std::pair<std::string, const DensityResults*>> of_density;
  for (const auto& [name, densities] : samples) {
    const auto it = densities.find(row.density);
    of_density.emplace_back(name, it == densities.end() ? nullptr : &it->second);
  }
  return evaluate(row, of_density);
}

std::string fixed(double x, int digits = 2) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << x;
  return s.str();
}

// Distance from the interval [low, high] to the paper's region (0 when they overlap).
double gap(const RowResult& r) {
  if (!r.spread.low) return std::nan("");
  if (*r.spread.high < r.paper.low) return r.paper.low - *r.spread.high;
  if (*r.spread.low > r.paper.high) return *r.spread.low - r.paper.high;
  return 0;
}

}  // namespace

std::vector<RowDecision> decide(const std::vector<Row>& rows, const std::map<std::string, ReadingResults>& readings,
                                const std::vector<std::string>& order, const std::string& baseline) {
  const auto base = readings.find(baseline);
  if (base == readings.end()) throw std::runtime_error("no results of the baseline reading '" + baseline + "'");
  std::vector<RowDecision> out;
  for (const Row& row : rows) {
    RowDecision d;
    d.row = row;
    d.baseline = evaluate_on(row, base->second);
    for (const std::string& name : order) {
      if (name == baseline) continue;
      const auto it = readings.find(name);
      ReadingEffect e{name, it == readings.end() ? RowResult{} : evaluate_on(row, it->second), std::nullopt};
      if (e.result.valued > 0 && d.baseline.valued > 1 && d.baseline.spread.sd > 0)
        e.shift_sd = (e.result.spread.mean - d.baseline.spread.mean) / d.baseline.spread.sd;
      if (d.baseline.verdict == Verdict::Inconsistent && e.result.verdict == Verdict::Consistent)
        d.made_consistent_by.push_back(name);
      d.readings.push_back(std::move(e));
    }
    d.explanation = explain(d);
    out.push_back(std::move(d));
  }
  return out;
}

std::string explain(const RowDecision& d) {
  if (d.baseline.verdict == Verdict::NotJudged) return "not judged: fewer than 2 samples with a value";
  if (d.baseline.verdict == Verdict::Consistent)
    return "consistent at the baseline: the paper's value lies within the scatter of one sample";
  if (!d.made_consistent_by.empty()) {
    std::string s = "consistent under ";
    for (std::size_t i = 0; i < d.made_consistent_by.size(); ++i) s += (i ? ", " : "") + d.made_consistent_by[i];
    return s;
  }
  if (d.row.rule == "majority") {  // a trend: which reading makes it hold in the most samples
    const ReadingEffect* best = nullptr;
    auto share = [](const RowResult& r) { return r.valued ? static_cast<double>(r.holds) / r.valued : 0.0; };
    for (const ReadingEffect& e : d.readings)
      if (e.result.valued > 0 && (!best || share(e.result) > share(best->result))) best = &e;
    std::string s = "unexplained: no reading makes it hold in more than half of the samples; at the baseline it holds in " +
                    std::to_string(d.baseline.holds) + " of " + std::to_string(d.baseline.valued);
    if (best)
      s += "; most: " + best->reading + " (" + std::to_string(best->result.holds) + " of " + std::to_string(best->result.valued) +
           (best->shift_sd ? ", mean shifted " + fixed(*best->shift_sd) + " sd" : std::string()) + ")";
    return s;
  }
  // Unexplained: say which reading closes most of the gap between our interval and the paper.
  const double base_gap = gap(d.baseline);
  const ReadingEffect* best = nullptr;
  for (const ReadingEffect& e : d.readings)
    if (e.result.verdict != Verdict::NotJudged && (!best || gap(e.result) < gap(best->result))) best = &e;
  std::string s = "unexplained: no reading makes it consistent; the baseline's interval misses the paper by " + fixed(base_gap, 3);
  if (best) {
    s += "; closest: " + best->reading + " (misses by " + fixed(gap(best->result), 3);
    if (best->shift_sd) s += ", mean shifted " + fixed(*best->shift_sd) + " sd";
    s += ")";
  }
  return s;
}

}  // namespace validation
