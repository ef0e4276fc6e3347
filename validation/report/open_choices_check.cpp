#include "report/open_choices_check.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "judge/verdicts.hpp"
#include "judge/weak_verdicts.hpp"
#include "report/other_sections.hpp"
#include "study/format.hpp"
#include "study/json_file.hpp"
#include "study/markdown_table.hpp"
#include "study/posterior_summary.hpp"
#include "study/settings.hpp"
#include "study/stamp.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

const char* const check_dir = "calibration/paper_open_choices/best";

// Row name -> verdict, from a validation.json.
std::map<std::string, Verdict> verdicts_of(const nlohmann::json& validation) {
  std::map<std::string, Verdict> out;
  for (const auto& r : validation.at("rows")) out[r.at("name").get<std::string>()] = verdict_from_string(r.at("verdict").get<std::string>());
  return out;
}

// The rows of a validation.json whose verdict carries a warning, each with its kinds (weak_verdicts.hpp).
std::map<std::string, std::vector<Weakness>> weak_rows(const nlohmann::json& validation) {
  std::map<std::string, std::vector<Weakness>> out;
  for (const auto& r : validation.at("rows"))
    if (r.contains("warnings"))
      for (const auto& w : r.at("warnings")) out[r.at("name").get<std::string>()].push_back(weakness_of(w.get<std::string>()));
  return out;
}

// A row's verdict in `verdicts`; not there: not judged.
Verdict verdict_in(const std::map<std::string, Verdict>& verdicts, const std::string& row) {
  const auto it = verdicts.find(row);
  return it == verdicts.end() ? Verdict::NotJudged : it->second;
}

}  // namespace

std::string open_choices_check_text(const fs::path& report) {
  const fs::path check_file = report / check_dir / "validation.json";
  const fs::path posterior_file = report / "calibration" / "paper_open_choices" / "posterior.json";
  std::error_code ec;
  if (!fs::exists(check_file, ec) || !fs::exists(posterior_file, ec)) return "";
  const nlohmann::json check = read_json_file(check_file.string());
  const PosteriorSummary posterior = read_posterior_summary(posterior_file.string());
  const std::string& best = posterior.best_set;

  // The set the check judged: its record names it (validate records a study's variants).
  std::set<std::string> judged_sets;
  if (check.contains("judged_from") && check.at("judged_from").contains("variants"))
    for (const auto& v : check.at("judged_from").at("variants")) judged_sets.insert(v.get<std::string>());
  if (judged_sets != std::set<std::string>{best})
    return "⚠ The check in `" + std::string(check_dir) + "/` judged " +
           (judged_sets.empty() ? std::string("a study that does not name its set") : "the set(s) " + joined(std::vector<std::string>(judged_sets.begin(), judged_sets.end()), ", ")) +
           ", not the calibration's best set `" + best + "`, so it is not set beside the calibration here: `make open-choices-check` runs the best set.\n";

  const Stamp check_stamp = stamp_from_json(check.at("stamp"));
  const Stamp& calibration_stamp = posterior.stamp;
  const Stamp paper_stamp = read_paper_stamp(report);
  std::map<std::string, Verdict> at_calibration;
  for (const PosteriorSummary::Row& r : posterior.rows)
    at_calibration[r.name] = !r.consistent_at_best_set ? Verdict::NotJudged : *r.consistent_at_best_set ? Verdict::Consistent : Verdict::Inconsistent;
  std::map<std::string, Verdict> at_paper;
  std::map<std::string, std::vector<Weakness>> weak_at_paper;
  if (fs::exists(report / "validation.json", ec)) {
    const nlohmann::json paper_record = read_json_file((report / "validation.json").string());
    at_paper = verdicts_of(paper_record), weak_at_paper = weak_rows(paper_record);
  }
  const std::map<std::string, std::vector<Weakness>> weak_checked = weak_rows(check);

  std::string out = "`make open-choices-check` ran the calibration's best set, `" + best +
                    "`, as the paper study is run, and `validate` judged it against the same rows (every row with its values: `" +
                    check_dir + "/verdicts.md`). " + stamp_sentence(check_stamp) + ".";
  if (check_stamp.engine_source != calibration_stamp.engine_source)
    out += " ⚠ Another engine than the calibration's (`" + calibration_stamp.engine_source + "`).";
  out += "\n\nAt " + size_of(check_stamp) + " per density, **" + std::to_string(check.at("consistent").get<int>()) + " of " +
         std::to_string(check.at("total").get<int>()) + "** rows are consistent (" + std::to_string(check.at("inconsistent").get<int>()) +
         " inconsistent, " + std::to_string(check.at("not_judged").get<int>()) + " not judged); " +
         (posterior.best_consistent && posterior.best_judged
              ? "at the calibration's " + size_of(calibration_stamp) + ", the same set made " + std::to_string(*posterior.best_consistent) +
                    " of " + std::to_string(*posterior.best_judged) + " consistent."
              : "its count at the calibration's " + size_of(calibration_stamp) + " is not recorded in the calibration's posterior.json.");
  if (!check.at("complete").get<bool>())
    out += " **Incomplete:** " + std::to_string(check.at("missing_results").size()) +
           " result file(s) missing; the rows are judged on what is there.";
  out += "\n\n";

  // The rows not consistent everywhere, in the reference file's order.
  std::vector<std::string> headings = {"row"};
  if (!at_paper.empty()) headings.push_back("the paper study (" + size_of(paper_stamp) + ")");
  headings.push_back("best set, calibration (" + size_of(calibration_stamp) + ")");
  headings.push_back("best set, check (" + size_of(check_stamp) + ")");
  MarkdownTable table(headings);
  std::vector<Weakness> kinds;  // of the ⚠ the table shows
  for (const auto& r : check.at("rows")) {
    const std::string name = r.at("name").get<std::string>();
    const Verdict checked = verdict_from_string(r.at("verdict").get<std::string>());
    const Verdict calibrated = verdict_in(at_calibration, name), paper = verdict_in(at_paper, name);
    if (checked == Verdict::Consistent && calibrated == Verdict::Consistent && (at_paper.empty() || paper == Verdict::Consistent)) continue;
    std::vector<std::string> cells = {cell(name)};
    // ⚠ on a weak verdict, as everywhere (the calibration's posterior.json records no warnings).
    if (!at_paper.empty()) cells.push_back(verdict_words(paper, weak_at_paper.count(name) > 0));
    cells.push_back(verdict_words(calibrated));
    cells.push_back(verdict_words(checked, weak_checked.count(name) > 0));
    using Weak = const std::map<std::string, std::vector<Weakness>>;
    for (Weak* weak : {static_cast<Weak*>(&weak_at_paper), &weak_checked})
      if (const auto it = weak->find(name); it != weak->end())
        for (Weakness k : it->second)
          if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    table.row(cells);
  }
  std::sort(kinds.begin(), kinds.end());
  if (table.rows() == 0) return out + "Every row is consistent in each.\n";
  return out + "The rows not consistent in each (the others are):\n\n" + table.text() +
         (kinds.empty() ? std::string() : "\n" + weak_legend(kinds) + " (each row's warning: its study's `verdicts.md`).\n");
}

}  // namespace validation
