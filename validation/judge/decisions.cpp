#include "judge/decisions.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "study/ensemble.hpp"
#include "study/format.hpp"
#include "judge/quantities.hpp"

namespace validation {

namespace {

// The row on samples that lack runs it reads: no value in any of them, so not judged.
RowResult without_runs(const Row& row, const ReadingResults& samples) {
  std::vector<RowResult::PerSample> none;
  for (const Sample& s : samples) none.push_back({s.name, {std::nullopt, "runs missing"}});
  return judge_values(row, std::move(none));
}

// "seed1 test2, seed2 test1": at most `shown` of them, then how many more.
std::string listed(const std::vector<std::string>& runs, std::size_t shown = 4) {
  std::string s;
  for (std::size_t i = 0; i < runs.size() && i < shown; ++i) s += (i ? ", " : "") + runs[i];
  if (runs.size() > shown) s += " and " + std::to_string(runs.size() - shown) + " more";
  return s;
}

// Distance from the interval [low, high] to the paper's region (0 when they overlap).
double gap(const RowResult& r) {
  if (!r.spread.low) return std::nan("");
  if (*r.spread.high < r.paper.low) return r.paper.low - *r.spread.high;
  if (*r.spread.low > r.paper.high) return *r.spread.low - r.paper.high;
  return 0;
}

// "a (1.00 sd, t = 2.50), b (...)": the readings named, with their shifts.
std::string with_shifts(const RowDecision& d, const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    s += (i ? ", " : "") + names[i];
    for (const ReadingEffect& e : d.readings)
      if (e.reading == names[i] && e.shift_sd)
        s += " (" + shift_phrase(*e.shift_sd) + (e.t ? ", t = " + fixed(*e.t) : std::string()) + ")";
  }
  return s;
}

}  // namespace

std::vector<std::string> missing_runs(const Row& row, const ReadingResults& samples) {
  std::vector<std::string> out;
  const Reads reads = reads_of(row.quantity);
  for (const Sample& s : samples) {
    const std::string who = s.name.empty() ? "the sample" : s.name;
    const auto it = s.densities.find(row.density);
    if (it == s.densities.end()) {
      out.push_back(who + " " + row.density);
      continue;
    }
    for (const std::string& run : it->second.missing_runs) {
      const bool reads_it = reads == Reads::Preparation
                                ? run == "prepare"
                                : run != "prepare" && (reads == Reads::TestAmongTests || row.test.empty() || run == row.test);
      if (reads_it) out.push_back(who + " " + run);
    }
  }
  return out;
}

std::vector<RowDecision> decide(const std::vector<Row>& rows, const std::map<std::string, ReadingResults>& readings,
                                const std::vector<std::string>& order, const std::string& baseline,
                                const std::map<std::string, RowResult>& full) {
  const auto base = readings.find(baseline);
  if (base == readings.end()) throw std::runtime_error("no results of the baseline reading '" + baseline + "'");
  std::vector<RowDecision> out;
  for (const Row& row : rows) {
    RowDecision d;
    d.row = row;
    d.baseline_missing = missing_runs(row, base->second);
    d.baseline = d.baseline_missing.empty() ? evaluate(row, base->second) : without_runs(row, base->second);
    if (const auto f = full.find(row.name); f != full.end()) d.full = f->second;
    const Verdict reference = d.full ? d.full->verdict : d.baseline.verdict;
    for (const std::string& name : order) {
      if (name == baseline) continue;
      const auto it = readings.find(name);
      ReadingEffect e;
      e.reading = name;
      if (it != readings.end()) e.missing = missing_runs(row, it->second);
      e.result = it == readings.end() ? RowResult{} : e.missing.empty() ? evaluate(row, it->second) : without_runs(row, it->second);
      if (e.result.valued > 0 && d.baseline.valued > 1 && std::max(d.baseline.spread.sd, row.resolution) > 0)
        e.shift_sd = shift_in_sd(e.result.spread.mean - d.baseline.spread.mean, d.baseline.spread.sd, row.resolution);
      if (d.full && e.result.valued > 0 && d.baseline.valued > 0)
        e.full = shifted(row, *d.full, e.result.spread.mean - d.baseline.spread.mean);
      const Spread& b = d.baseline.spread;
      const Spread& r = e.result.spread;
      if (b.n > 1 && r.n > 1) {
        const double se = std::sqrt(b.sd * b.sd / b.n + r.sd * r.sd / r.n);
        const double diff = std::abs(r.mean - b.mean);
        if (se > 0) e.t = diff / se;
        e.resolved = se > 0 ? *e.t > t_quantile(0.95, b.n + r.n - 2) : diff > 0;
      }
      const Verdict under = d.full ? (e.full ? e.full->verdict : Verdict::NotJudged) : e.result.verdict;
      if (reference == Verdict::Inconsistent && under == Verdict::Consistent)
        (e.resolved ? d.made_consistent_by : d.unresolved_by).push_back(name);
      d.readings.push_back(std::move(e));
    }
    d.judged = d.baseline_missing.empty() &&
               std::any_of(d.readings.begin(), d.readings.end(), [](const ReadingEffect& e) { return e.result.valued > 0; });
    d.outcome = outcome_of(d);
    d.explanation = explain(d);
    out.push_back(std::move(d));
  }
  return out;
}

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::NotJudged: return "not judged";
    case Outcome::Consistent: return "consistent";
    case Outcome::Explained: return "explained";
    case Outcome::WithinScatter: return "within scatter";
    case Outcome::Unexplained: return "unexplained";
  }
  return "not judged";
}

Outcome outcome_from_string(const std::string& text) {
  std::string names;
  for (Outcome o : {Outcome::NotJudged, Outcome::Consistent, Outcome::Explained, Outcome::WithinScatter, Outcome::Unexplained}) {
    if (text == to_string(o)) return o;
    names += std::string(names.empty() ? "" : ", ") + "'" + to_string(o) + "'";
  }
  throw std::runtime_error("`outcome` '" + text + "' is none of " + names);
}

namespace {

// The row as the study judges it: on the full-size ensemble when given, else on the baseline.
const RowResult& judged_base(const RowDecision& d) { return d.full ? *d.full : d.baseline; }

// The readings not judged for runs they lack ("<reading> lacks <runs>; ..."; "" when none).
std::string lacking_runs(const RowDecision& d) {
  std::string lacking;
  for (const ReadingEffect& e : d.readings)
    if (!e.missing.empty()) lacking += (lacking.empty() ? "" : "; ") + e.reading + " lacks " + listed(e.missing);
  return lacking;
}

// The explanation of a row the study judged (explain() adds the readings that lack runs).
std::string explain_judged(const RowDecision& d);

}  // namespace

Outcome outcome_of(const RowDecision& d) {
  if (!d.baseline_missing.empty() || (!d.judged && !lacking_runs(d).empty())) return Outcome::NotJudged;
  const RowResult& base = judged_base(d);
  if (base.verdict == Verdict::NotJudged) return Outcome::NotJudged;
  if (base.verdict == Verdict::Consistent) return Outcome::Consistent;
  if (!d.made_consistent_by.empty()) return Outcome::Explained;
  if (d.row.rule == "majority" && judge(base.spread, base.paper) == Verdict::Consistent) return Outcome::WithinScatter;
  return Outcome::Unexplained;
}

std::string explain(const RowDecision& d) {
  if (!d.baseline_missing.empty()) return "not judged: the baseline lacks runs this row reads (" + listed(d.baseline_missing) + ")";
  // The readings not judged for runs they lack, said after the rest.
  const std::string lacking = lacking_runs(d);
  if (!d.judged && !lacking.empty()) return "not judged: no reading has every run this row reads (" + lacking + ")";
  const std::string not_judged = lacking.empty() ? "" : "; not judged under a reading that lacks runs this row reads (" + lacking + ")";
  return explain_judged(d) + not_judged;
}

namespace {

std::string explain_judged(const RowDecision& d) {
  const RowResult& base = judged_base(d);
  const std::string where = d.full ? "the full-size ensemble" : "the baseline";
  const Outcome outcome = outcome_of(d);
  if (outcome == Outcome::NotJudged) return "not judged: fewer than 2 samples with a value";
  if (outcome == Outcome::Consistent) return "consistent on " + where + " (within the scatter of one sample)";
  if (outcome == Outcome::Explained) {
    std::string s = "consistent under " + with_shifts(d, d.made_consistent_by);
    if (d.full) s += ", its shift of the mean applied to the full-size ensemble";
    return s;
  }
  const std::string unresolved =
      d.unresolved_by.empty() ? ""
                              : "; would be consistent under " + with_shifts(d, d.unresolved_by) +
                                    ", but the shift is not resolved by the decisions study's samples (one-sided t test, 95 %)";
  // A reading's row as judged: on the full-size ensemble with its shift applied, or on its own samples.
  auto judged = [&](const ReadingEffect& e) -> const RowResult& { return d.full && e.full ? *e.full : e.result; };
  if (d.row.rule == "majority") {  // a trend: which reading makes it hold in the most samples
    const ReadingEffect* best = nullptr;
    auto share = [](const RowResult& r) { return r.valued ? static_cast<double>(r.holds) / r.valued : 0.0; };
    for (const ReadingEffect& e : d.readings)
      if (e.result.valued > 0 && (!best || share(judged(e)) > share(judged(*best)))) best = &e;
    // Within scatter: the trend holds in too few samples, but the interval of one sample reaches
    // the paper's region, so a single sample (the paper's) could show it.
    const bool scatter = outcome == Outcome::WithinScatter;
    std::string s = std::string(scatter ? "no reading does: within scatter (the interval of one sample reaches the paper's "
                                          "region, so one sample can show it)"
                                        : "unexplained: no reading makes it hold in more than half of the samples") +
                    "; on " + where + " it holds in " + std::to_string(base.holds) + " of " + std::to_string(base.valued);
    if (best)
      s += "; most: " + best->reading + " (" + std::to_string(judged(*best).holds) + " of " + std::to_string(judged(*best).valued) +
           (best->shift_sd ? ", mean shifted " + shift_phrase(*best->shift_sd) : std::string()) + ")";
    return s + unresolved;
  }
  // Unexplained: say which reading closes most of the gap between our interval and the paper.
  const double base_gap = gap(base);
  const ReadingEffect* best = nullptr;
  for (const ReadingEffect& e : d.readings)
    if (judged(e).verdict != Verdict::NotJudged && (!best || gap(judged(e)) < gap(judged(*best)))) best = &e;
  std::string s = "unexplained: no reading makes it consistent; the interval of " + where + " misses the paper by " + fixed(base_gap, 3);
  if (best) {
    s += "; closest: " + best->reading + " (misses by " + fixed(gap(judged(*best)), 3);
    if (best->shift_sd) s += ", mean shifted " + shift_phrase(*best->shift_sd);
    s += ")";
  }
  return s + unresolved;
}

}  // namespace

}  // namespace validation
