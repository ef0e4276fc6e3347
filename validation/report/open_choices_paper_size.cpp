#include "report/open_choices_paper_size.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "judge/decisions_file.hpp"
#include "judge/validation_file.hpp"
#include "judge/verdicts.hpp"
#include "judge/weak_verdicts.hpp"
#include "report/other_sections.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "study/settings.hpp"
#include "study/stamp.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

const char* const set_dir = "calibration/paper_open_choices/paper_size";

// A validation.json's rows judged again by the reference file's rows, in its order.
std::vector<RejudgedRow> rejudged(const fs::path& file, const std::vector<Row>& rows) {
  return judge_recorded(read_validation_file(file.string()), rows, file.string(), "the paper's reference file");
}

// "1.42 ± 0.040, in 0 of 5 ❌" : the samples' mean ± sd, how many hold it, the verdict with its ⚠.
std::string row_cell(const RowResult& r) {
  return mean_pm_sd(r.spread.mean, r.spread.sd) + ", holds in " + std::to_string(r.holds) + " of " + std::to_string(r.valued) + " " +
         verdict_mark(r.verdict, !weaknesses(r).empty());
}

// A row's verdict in the set, its cell, its warnings and how many samples hold it ("it holds in 0
// of 3"), from the set's own runs or from the study it borrows a density from.
struct SetVerdict {
  Verdict verdict = Verdict::NotJudged;
  std::string cell;
  std::vector<Weakness> weak;
  std::string holds;
};

SetVerdict set_verdict(const RowResult& r) {
  return {r.verdict, row_cell(r), weaknesses(r), "it holds in " + std::to_string(r.holds) + " of " + std::to_string(r.valued)};
}

// Adds to `in_set` the rows of each density the set's record borrows (judged_from.borrowed: a
// density whose runs under the set are another study's reading) that the set did not judge, from
// that study's decisions.json; returns the sentence that says so, with that study's stamp ("" when
// nothing is borrowed, or the file is not there: its rows are then not run).
std::string add_borrowed(const RecordedValidation& set, const std::vector<RejudgedRow>& paper, std::map<std::string, SetVerdict>& in_set) {
  std::string out;
  for (const RecordedValidation::Borrowed& b : set.borrowed) {
    std::error_code ec;
    if (!fs::exists(b.decisions, ec)) continue;
    const DecisionsFile f = read_decisions_file(b.decisions);
    const std::string study = fs::path(b.decisions).parent_path().string();
    int taken = 0;
    for (const RejudgedRow& p : paper) {
      if (p.density != b.density || in_set.count(p.row.name) || !f.rows.count(p.row.name)) continue;
      const DecisionsFile::Reading* r = f.rows.at(p.row.name).reading(b.reading);
      if (!r || r->verdict == Verdict::NotJudged || !r->mean) continue;
      in_set.emplace(p.row.name, SetVerdict{r->verdict,
                                            "mean " + number(*r->mean) + " (`" + study + "`) " + verdict_mark(r->verdict, false),
                                            {},
                                            "it is " + std::string(to_string(r->verdict)) + " on the " + std::to_string(f.samples.value_or(0)) +
                                                " samples of `" + study + "`"});
      ++taken;
    }
    if (taken == 0) continue;
    out += " Its " + b.density + " rows (" + std::to_string(taken) + ") are those of `" + study + "` under `" + b.reading +
           "`, judged on that study's own samples (the set's record says the " + b.density + " sample's runs under the set are "
           "that reading's). " + stamp_sentence(f.stamp) + ".";
  }
  return out;
}

}  // namespace

std::string open_choices_paper_size_text(const fs::path& report, const std::vector<Row>& rows) {
  const fs::path set_file = report / set_dir / "validation.json", paper_file = report / "validation.json";
  std::error_code ec;
  if (!fs::exists(set_file, ec) || !fs::exists(paper_file, ec)) return "";
  const std::vector<RejudgedRow> in_paper = rejudged(paper_file, rows);
  const RecordedValidation set_record = read_validation_file(set_file.string());
  std::vector<Row> set_rows = rows;  // the rows of the densities the set ran (its record names them)
  if (const std::string bad = keep_densities(set_rows, set_record.densities); !bad.empty()) throw std::runtime_error(set_file.string() + ": " + bad);
  std::map<std::string, SetVerdict> in_set;
  for (RejudgedRow& r : judge_recorded(set_record, set_rows, set_file.string(), "the paper's reference file"))
    in_set.emplace(r.row.name, set_verdict(r.result));
  const std::string borrowed_text = add_borrowed(set_record, in_paper, in_set);
  const Stamp& set_stamp = set_record.stamp;
  // The set: the study variant(s) validate judged (its record names them).
  std::vector<std::string> variants;
  for (const std::string& v : set_record.variants) variants.push_back("`" + v + "`");
  const std::string set_name = variants.empty() ? "The baseline" : "The set " + joined(variants, ", ");
  const Stamp paper_stamp = read_paper_stamp(report);

  // The rows consistent in the paper study that the set does not keep so, those it misses, and
  // those of a density neither the set nor a study it borrows from ran.
  std::vector<std::string> lost, not_run;
  int kept = 0, consistent_now = 0, consistent_in_set = 0;
  for (const RejudgedRow& p : in_paper) {
    const auto s = in_set.find(p.row.name);
    if (s == in_set.end()) {
      not_run.push_back(p.row.name);
      continue;
    }
    consistent_in_set += s->second.verdict == Verdict::Consistent;
    if (p.result.verdict != Verdict::Consistent) continue;
    ++consistent_now;
    if (s->second.verdict == Verdict::Consistent) ++kept;
    else lost.push_back(p.row.name);
  }
  std::string out = set_name + " of `pipeline/studies/open_choices_paper_size.yaml` (`make open-choices-paper-size`; "
                    "every row with its values: `" + std::string(set_dir) + "/verdicts.md`). " + stamp_sentence(set_stamp) + ".";
  if (set_stamp.engine_source != paper_stamp.engine_source)
    out += " ⚠ Another engine than the paper study's (`" + paper_stamp.engine_source + "`).";
  if (set_stamp.baseline != paper_stamp.baseline) out += " Its baseline is not the paper study's (`" + paper_stamp.baseline + "`).";
  if (!set_record.densities.empty()) out += " It runs the " + joined(set_record.densities, " and ") + " samples only.";
  out += borrowed_text;
  const std::size_t judged = in_paper.size() - not_run.size();
  out += "\n\nAt " + size_of(set_stamp) + " per density, **" + std::to_string(consistent_in_set) + " of " + std::to_string(judged) +
         "** rows are consistent" + (not_run.empty() ? "" : " (" + std::to_string(not_run.size()) + " not run)") +
         "; in the paper study (" + size_of(paper_stamp) + "), " + std::to_string(consistent_now) + " of the same " +
         std::to_string(judged) + ". Of those " + std::to_string(consistent_now) + ", " + std::to_string(kept) + " are consistent in the set" +
         (lost.empty() ? "." : "; not: " + joined(lost, "; ") + ".") + "\n\n";

  MarkdownTable table({"row inconsistent in the paper study, or in the set", "the paper study", "the set", "answer at the paper's size"});
  std::vector<Weakness> kinds;
  for (const RejudgedRow& p : in_paper) {
    const auto s = in_set.find(p.row.name);
    if (s == in_set.end()) continue;
    const RowResult& now = p.result;
    const Verdict set = s->second.verdict;
    if (now.verdict == Verdict::Consistent && set == Verdict::Consistent) continue;
    for (Weakness k : weaknesses(now))
      if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    for (Weakness k : s->second.weak)
      if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    std::string answer;
    if (now.verdict == Verdict::Consistent) answer = "turned inconsistent by the set";
    else if (set != Verdict::Consistent) answer = "not answered by the set: " + s->second.holds;
    else if (lost.empty()) answer = "consistent together with every row consistent now";
    else answer = "consistent, but not together with " + std::to_string(lost.size()) + " row" + (lost.size() == 1 ? "" : "s") + " consistent now";
    table.row({cell(p.row.name), row_cell(now), s->second.cell, answer});
  }
  std::sort(kinds.begin(), kinds.end());
  return out + table.text() + (kinds.empty() ? std::string() : "\n" + weak_legend(kinds) + ".\n");
}

}  // namespace validation
