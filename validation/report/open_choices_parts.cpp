#include "report/open_choices_parts.hpp"

#include <algorithm>

#include "judge/validation_file.hpp"
#include "judge/verdicts.hpp"
#include "judge/weak_verdicts.hpp"
#include "report/other_sections.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "study/posterior_summary.hpp"
#include "study/settings.hpp"
#include "study/stamp.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

using Part = PosteriorSummary::Part;

// The part judging a row, and the row there; none when no part does.
std::pair<const Part*, const Part::Row*> judged_in(const std::vector<Part>& parts, const std::string& row) {
  for (const Part& p : parts)
    for (const Part::Row& r : p.rows)
      if (r.name == row && r.judged_sets > 0) return {&p, &r};
  return {nullptr, nullptr};
}

// "set i3s004, the posterior's best prediction ... (all 7 rows: 0.21; this row: 0.45; measured
// 0.040 ± 0.007 on 3 samples)": the probabilities it gave that one sample agrees, and what the
// set's samples gave once scored.
std::string confirmed_words(const Part::Confirmed& c, const std::string& row) {
  std::string out = "set " + c.set + validation::chosen_words(c.chosen) +
                    " (all " + std::to_string(c.rows.size()) + " rows: " + significant(c.probability, 2);
  for (const Part::Confirmed::Row& r : c.rows)
    if (r.name == row) {
      out += "; this row: " + significant(r.probability, 2);
      if (r.measured)
        out += "; measured " + mean_pm_sd(r.measured->mean, r.measured->sd) + " on " + std::to_string(r.measured->samples) + " samples";
    }
  return out + ")";
}

// The largest probability the posterior at the part's size gives one sample of agreeing with the
// row, at random points of its surface's region; "—" before the part has it.
std::string reach_cell(const Part& part, const std::string& row) {
  if (part.reach)
    for (const auto& [name, most] : part.reach->rows)
      if (name == row) return significant(most, 2) + " (" + std::to_string(part.reach->points) + " points)";
  return "—";
}

// The answer for a row the paper study misses, from the part's sets.
std::string answer(const Part& part, const Part::Row& r) {
  const std::string all = std::to_string(part.rows.size());
  if (r.consistent_sets > 0 && r.most_with && *r.most_with == static_cast<int>(part.rows.size()))
    return "✅ consistent together with all " + all + " rows of its density" + (r.set_with_most ? " in set " + *r.set_with_most : std::string());
  if (r.consistent_sets > 0)
    return "consistent in " + std::to_string(r.consistent_sets) + " set(s), never together with all " + all + " rows of its density (at most " +
           std::to_string(r.most_with.value_or(0)) + (r.set_with_most ? ", set " + *r.set_with_most : std::string()) + ")";
  std::string out = "❌ in none";
  if (part.confirmed.empty()) out += "; no set confirmed the posterior's prediction yet";
  for (const Part::Confirmed& c : part.confirmed) {
    const auto at = std::find_if(c.rows.begin(), c.rows.end(), [&](const Part::Confirmed::Row& x) { return x.name == r.name; });
    const bool scored = at != c.rows.end() && at->consistent.has_value();
    out += scored ? ", not even in " + confirmed_words(c, r.name) : "; " + confirmed_words(c, r.name) + ", not scored yet";
  }
  return out;
}

}  // namespace

std::string open_choices_parts_text(const fs::path& report, const std::vector<Row>& rows) {
  const fs::path posterior_file = report / "calibration" / "paper_open_choices" / "posterior.json", paper_file = report / "validation.json";
  std::error_code ec;
  if (!fs::exists(posterior_file, ec) || !fs::exists(paper_file, ec)) return "";
  const PosteriorSummary posterior = read_posterior_summary(posterior_file.string());
  if (posterior.parts.empty()) return "";
  const std::vector<RejudgedRow> in_paper =
      judge_recorded(read_validation_file(paper_file.string()), rows, paper_file.string(), "the paper's reference file");
  const Stamp paper_stamp = read_paper_stamp(report);

  std::string out = "The calibration runs its sets at the paper's size one density at a time (each density's rows depend on its own "
                    "readings), each part on its own samples (`calibration/paper_open_choices/section.md`; ledgers "
                    "`scored_sets.<profile>-<density>.json`).";
  // Each part's sets and rows; then the stamps, one sentence for the parts that share one.
  std::vector<std::string> counts;
  std::vector<std::pair<std::string, std::vector<std::string>>> stamps;  // a stamp's sentence, the densities of its parts
  for (const Part& p : posterior.parts) {
    counts.push_back(joined(p.densities, " and ") + " " + std::to_string(p.scored_sets) + " set(s) on " + std::to_string(p.rows.size()) + " rows");
    std::string s = stamp_sentence(p.stamp) + ".";
    if (p.stamp.engine_source != paper_stamp.engine_source) s += " ⚠ Another engine than the paper study's (`" + paper_stamp.engine_source + "`).";
    if (p.stamp.baseline != paper_stamp.baseline) s += " The baseline is not the paper study's (`" + paper_stamp.baseline + "`).";
    const auto same = std::find_if(stamps.begin(), stamps.end(), [&](const auto& x) { return x.first == s; });
    if (same == stamps.end()) stamps.push_back({s, p.densities});
    else same->second.insert(same->second.end(), p.densities.begin(), p.densities.end());
  }
  out += " Scored so far: " + joined(counts, "; ") + ".";
  for (const auto& [s, densities] : stamps) out += stamps.size() == 1 ? " " + s : " (" + joined(densities, ", ") + ") " + s;
  // The reach's column once some part has it (the posterior at the paper's size, every part with its discrepancy).
  const bool reached = std::any_of(posterior.parts.begin(), posterior.parts.end(), [](const Part& p) { return p.reach.has_value(); });
  std::vector<std::string> head = {"row the paper study misses", "the paper study", "consistent at the paper's size in (of the sets judging it)",
                                   "answer at the paper's size"};
  if (reached) head.push_back("the posterior's largest probability that one sample agrees, at random points of its region");
  MarkdownTable table(head);
  const auto row_of = [&](std::vector<std::string> cells, const std::string& reach) {
    if (reached) cells.push_back(reach);
    table.row(cells);
  };
  std::vector<Weakness> kinds;
  for (const RejudgedRow& p : in_paper) {
    if (p.result.verdict == Verdict::Consistent) continue;
    for (Weakness k : weaknesses(p.result))
      if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    const std::string now = mean_pm_sd(p.result.spread.mean, p.result.spread.sd) + ", holds in " + std::to_string(p.result.holds) +
                            " of " + std::to_string(p.result.valued) + " " + verdict_mark(p.result.verdict, !weaknesses(p.result).empty());
    const auto [part, row] = judged_in(posterior.parts, p.row.name);
    if (!part) {
      row_of({cell(p.row.name), now, "—", "not judged by any part of the calibration at the paper's size"}, "—");
      continue;
    }
    row_of({cell(p.row.name), now, std::to_string(row->consistent_sets) + " of " + std::to_string(row->judged_sets), answer(*part, *row)},
           reach_cell(*part, p.row.name));
  }
  std::sort(kinds.begin(), kinds.end());
  if (table.rows() == 0) return out + "\n\nThe paper study misses no row.\n";
  return out + "\n\n" + table.text() + (kinds.empty() ? std::string() : "\n" + weak_legend(kinds) + ".\n");
}

}  // namespace validation
