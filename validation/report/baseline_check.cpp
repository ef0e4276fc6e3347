#include "report/baseline_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "judge/weak_verdicts.hpp"
#include "report/other_sections.hpp"
#include "study/ensemble.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "study/settings.hpp"

namespace validation {

namespace {

std::string samples_text(std::size_t n) { return std::to_string(n) + " sample" + (n == 1 ? "" : "s"); }

// One line of the check: the values it shows, compared as values (two studies whose baselines are
// the same samples give the same line).
struct CheckLine {
  const RejudgedRow* paper;
  std::optional<double> mean, sd;
  Verdict verdict;
  bool operator==(const CheckLine& o) const { return paper == o.paper && mean == o.mean && sd == o.sd && verdict == o.verdict; }
};

std::string mean_sd(const std::optional<double>& mean, const std::optional<double>& sd) {
  return !mean ? "—" : sd ? mean_pm_sd(*mean, *sd) : number(*mean);
}

// A baseline that is the paper study's own first `n` samples (a readings study's: same size, its
// samples another study's), judged again on their recorded values by judge_values, the function
// that judged the paper study, so that its verdict carries the same warnings (consistent by width
// only, samples too few). None unless the samples' mean, sd and verdict are the ones the file
// records (to the six significant digits it writes): then the baseline is not those samples.
std::optional<RowResult> judged_on_paper_samples(const CheckLine& line, std::size_t n) {
  const RowResult& paper = line.paper->result;
  if (n == 0 || n > paper.samples.size() || !line.mean) return std::nullopt;
  const std::vector<RowResult::PerSample> first(paper.samples.begin(), paper.samples.begin() + static_cast<std::ptrdiff_t>(n));
  RowResult r = judge_values(line.paper->row, first);
  const bool same = r.valued > 0 && number(r.spread.mean) == number(*line.mean) &&
                    (line.sd ? r.valued > 1 && number(r.spread.sd) == number(*line.sd) : r.valued == 1) && r.verdict == line.verdict;
  if (!same) return std::nullopt;
  return r;
}

}  // namespace

PaperEnsemble read_paper_ensemble(const std::filesystem::path& report, const std::vector<Row>& rows) {
  PaperEnsemble e;
  const std::filesystem::path file = report / "validation.json";
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return e;
  const RecordedValidation record = read_validation_file(file.string());  // errors name the file
  std::vector<Row> recorded;  // the rows the record has, in the reference file's order
  for (const Row& r : rows)
    if (std::any_of(record.rows.begin(), record.rows.end(), [&](const auto& rr) { return rr.name == r.name; })) recorded.push_back(r);
  e.rows = judge_recorded(record, recorded, file.string(), "the reference file");
  e.samples = record.samples.size();
  e.spheres = read_paper_stamp(report).spheres;
  return e;
}

std::string baseline_check_name(const std::optional<long>& particles, const PaperEnsemble& paper) {
  return particles && paper.spheres > 0 && *particles == paper.spheres ? "sample-count check" : "size check";
}

std::string baseline_check_section(const std::vector<const DecisionsFile*>& files, const PaperEnsemble& paper, int level) {
  if (files.empty()) return "";
  std::vector<std::pair<CheckLine, std::vector<std::string>>> lines;  // a line, the studies that give it
  for (const RejudgedRow& row : paper.rows)
    for (const DecisionsFile* f : files) {
      const auto it = f->rows.find(row.row.name);
      if (it == f->rows.end()) continue;
      const CheckLine line{&row, it->second.baseline_mean, it->second.baseline_sd, it->second.baseline_verdict};
      const auto same = std::find_if(lines.begin(), lines.end(), [&](const auto& l) { return l.first == line; });
      if (same == lines.end()) lines.push_back({line, {study_label(*f)}});
      else same->second.push_back(study_label(*f));
    }
  if (lines.empty()) return "";
  const DecisionsFile& first = *files.front();
  const std::string name = baseline_check_name(first.particles, paper);
  const bool by_study = files.size() > 1;
  std::vector<std::string> headings = {"row", "paper study: mean ± sd", "this study's baseline: mean ± sd",
                                       "difference / max(sd, resolution)", "verdicts (paper study / baseline)"};
  if (by_study) headings.push_back("studies");
  MarkdownTable table(headings);
  const std::size_t first_samples = first.samples.value_or(0);
  std::vector<Weakness> kinds;  // the kinds of ⚠ the table shows
  const auto note = [&](const std::vector<Weakness>& ks) {
    for (Weakness k : ks)
      if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
  };
  // A baseline of the paper study's own samples (same size, `baseline_results`): each line judged
  // on those samples' values where the file's numbers are theirs.
  const bool own_samples = name == "sample-count check" && !first.baseline_results.empty();
  std::size_t on_samples = 0;  // lines judged on the paper study's samples
  for (const auto& [line, studies] : lines) {
    const RowResult& big = line.paper->result;
    std::string diff = "—";
    if (big.valued > 1 && std::max(big.spread.sd, line.paper->row.resolution) > 0 && line.mean)
      diff = shift_text(shift_in_sd(*line.mean - big.spread.mean, big.spread.sd, line.paper->row.resolution));
    // The baseline's verdict is weak when its interval of one sample, from the mean, sd and samples
    // the file records, is too wide for the row's tolerance (too_few_warning).
    // Judged on its samples' values when they are the paper study's (above): every kind of warning.
    // Otherwise from the mean, sd and samples the file records: the interval of one sample too wide
    // for the row's tolerance (too_few_warning); whether a sample lies in the region is not recorded.
    const std::optional<RowResult> own = own_samples ? judged_on_paper_samples(line, first_samples) : std::nullopt;
    on_samples += own.has_value();
    const bool weak = own ? !own->warnings.empty()
                          : line.mean && line.sd &&
                                too_few_warning(line.paper->row, summary_spread(*line.mean, *line.sd, static_cast<int>(first_samples)));
    std::vector<std::string> cells = {line.paper->row.name, big.valued > 1 ? mean_pm_sd(big.spread.mean, big.spread.sd) : "—",
                                      mean_sd(line.mean, line.sd), diff, verdict_mark(big) + " / " + verdict_mark(line.verdict, weak)};
    if (by_study) cells.push_back(joined(studies, ", "));
    table.row(cells);
    note(weaknesses(big));
    if (own) note(weaknesses(*own));
    else if (weak) note({Weakness::TooFewSamples});
  }
  std::sort(kinds.begin(), kinds.end());
  // What the two ensembles are, from the records: their spheres and samples.
  const std::size_t n = first.samples.value_or(0), m = paper.samples;
  const std::string spheres = first.particles ? thousands(*first.particles) + " spheres" : "spheres not recorded";
  std::string heading = std::string(static_cast<std::size_t>(level), '#') + " " + static_cast<char>(std::toupper(name[0])) + name.substr(1) +
                        ": this study's baseline (";
  std::string text;
  if (name == "size check") {
    heading += spheres + ", " + samples_text(n) + ") against the paper study's ensemble (" + thousands(paper.spheres) + " spheres, " +
               samples_text(m) + ")";
    text = "The same rows on the paper study's samples and on this study's baseline, which differ in size";
    text += ". A reading's shift is trusted at this study's size where the two verdicts agree.";
  } else {
    heading += samples_text(n) + ") against the paper study's ensemble (" + samples_text(m) + "), both of " + spheres;
    text = "The same rows on the paper study's samples and on this study's baseline, of the same size";
    if (!first.baseline_results.empty()) text += " (the baseline is " + samples_text(n) + " of the paper study's own, `" + first.baseline_results + "`)";
    text += ": no size is compared. A verdict that differs comes from the number of samples: the interval of one sample is mean ± "
            "t(0.975, n − 1) · sd · √(1 + 1/n)";
    if (n >= 2 && m >= 2)
      text += ", with t = " + fixed(t_quantile(0.975, static_cast<int>(n) - 1), 2) + " for " + std::to_string(n) + " samples and " +
              fixed(t_quantile(0.975, static_cast<int>(m) - 1), 2) + " for " + std::to_string(m);
    text += ".";
    if (on_samples > 0 && !paper.rows.empty() && n <= paper.rows.front().result.samples.size()) {
      std::vector<std::string> names;
      for (std::size_t k = 0; k < n; ++k) names.push_back(paper.rows.front().result.samples[k].sample);
      text += " Its means and sds are those of the paper study's " + joined(names, ", ") + " in " + std::to_string(on_samples) + " of " +
              std::to_string(lines.size()) + " rows, and there its verdict is judged on their values as the paper study's is, "
              "warnings included.";
    }
  }
  text += " The difference of the means is in units of the paper ensemble's standard deviation, or of the row's resolution where "
          "that is larger (a scatter below it says nothing).";
  if (by_study) text += " Each row once, with the readings studies whose baseline has it.";
  if (!kinds.empty()) text += " " + weak_legend(kinds) + ".";
  return heading + "\n\n" + text + "\n\n" + table.text();
}

}  // namespace validation
