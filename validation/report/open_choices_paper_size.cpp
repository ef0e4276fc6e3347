#include "report/open_choices_paper_size.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "judge/validation_file.hpp"
#include "judge/verdicts.hpp"
#include "judge/weak_verdicts.hpp"
#include "report/other_sections.hpp"
#include "study/format.hpp"
#include "study/json_file.hpp"
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

std::string size_of(const Stamp& s) {
  if (s.spheres <= 0 || s.samples <= 0) return "size not recorded";
  return thousands(s.spheres) + " spheres, " + std::to_string(s.samples) + " sample" + (s.samples == 1 ? "" : "s");
}

}  // namespace

std::string open_choices_paper_size_text(const fs::path& report, const std::vector<Row>& rows) {
  const fs::path set_file = report / set_dir / "validation.json", paper_file = report / "validation.json";
  std::error_code ec;
  if (!fs::exists(set_file, ec) || !fs::exists(paper_file, ec)) return "";
  const std::vector<RejudgedRow> in_paper = rejudged(paper_file, rows);
  std::map<std::string, RejudgedRow> in_set;
  for (RejudgedRow& r : rejudged(set_file, rows)) in_set.emplace(r.row.name, std::move(r));
  const nlohmann::json set_record = read_json_file(set_file.string());
  const Stamp set_stamp = stamp_from_json(set_record.at("stamp"));
  // The set: the study variant(s) validate judged (its record names them).
  std::vector<std::string> variants;
  if (set_record.contains("judged_from") && set_record.at("judged_from").contains("variants"))
    for (const auto& v : set_record.at("judged_from").at("variants")) variants.push_back("`" + v.get<std::string>() + "`");
  const std::string set_name = variants.empty() ? "The baseline" : "The set " + joined(variants, ", ");
  const Stamp paper_stamp = read_paper_stamp(report);

  // The rows consistent in the paper study that the set does not keep so, and those it misses.
  std::vector<std::string> lost, missed;
  int kept = 0, consistent_now = 0, consistent_in_set = 0;
  for (const RejudgedRow& p : in_paper) {
    const std::string& name = p.row.name;
    const auto s = in_set.find(name);
    const Verdict there = s == in_set.end() ? Verdict::NotJudged : s->second.result.verdict;
    consistent_in_set += there == Verdict::Consistent;
    if (p.result.verdict == Verdict::Consistent) {
      ++consistent_now;
      if (there == Verdict::Consistent) ++kept;
      else lost.push_back(name);
    } else {
      missed.push_back(name);
    }
  }
  std::string out = set_name + " of `pipeline/studies/open_choices_paper_size.yaml` (`make open-choices-paper-size`; "
                    "every row with its values: `" + std::string(set_dir) + "/verdicts.md`). " + stamp_sentence(set_stamp) + ".";
  if (set_stamp.engine_source != paper_stamp.engine_source)
    out += " ⚠ Another engine than the paper study's (`" + paper_stamp.engine_source + "`).";
  if (set_stamp.baseline != paper_stamp.baseline) out += " Its baseline is not the paper study's (`" + paper_stamp.baseline + "`).";
  out += "\n\nAt " + size_of(set_stamp) + " per density, **" + std::to_string(consistent_in_set) + " of " + std::to_string(in_paper.size()) +
         "** rows are consistent; in the paper study (" + size_of(paper_stamp) + "), " + std::to_string(consistent_now) + ". Of the " +
         std::to_string(consistent_now) + " rows consistent there, " + std::to_string(kept) + " are consistent in the set" +
         (lost.empty() ? "." : "; not: " + joined(lost, "; ") + ".") + "\n\n";

  MarkdownTable table({"row inconsistent in the paper study, or in the set", "the paper study", "the set", "answer at the paper's size"});
  std::vector<Weakness> kinds;
  for (const RejudgedRow& p : in_paper) {
    const std::string& name = p.row.name;
    const auto s = in_set.find(name);
    if (s == in_set.end()) continue;
    const RowResult &now = p.result, &set = s->second.result;
    if (now.verdict == Verdict::Consistent && set.verdict == Verdict::Consistent) continue;
    for (const RowResult* r : {&now, &set})
      for (Weakness k : weaknesses(*r))
        if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    std::string answer;
    if (now.verdict == Verdict::Consistent) answer = "turned inconsistent by the set";
    else if (set.verdict != Verdict::Consistent) answer = "not answered by the set: it holds in " + std::to_string(set.holds) + " of " + std::to_string(set.valued);
    else if (lost.empty()) answer = "consistent together with every row consistent now";
    else answer = "consistent, but not together with " + std::to_string(lost.size()) + " row" + (lost.size() == 1 ? "" : "s") + " consistent now";
    table.row({cell(name), row_cell(now), row_cell(set), answer});
  }
  std::sort(kinds.begin(), kinds.end());
  return out + table.text() + (kinds.empty() ? std::string() : "\n" + weak_legend(kinds) + ".\n");
}

}  // namespace validation
