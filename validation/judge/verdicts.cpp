#include "judge/verdicts.hpp"
#include "judge/weak_verdicts.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

#include "study/format.hpp"
#include "study/markdown_table.hpp"

namespace validation {

namespace {

std::string number_or_dash(const std::optional<double>& x) { return x ? number(*x) : "—"; }

nlohmann::json json_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); }

// "mean ± sd", the digits from the scatter (format.hpp); one sample: its value.
std::string mean_sd(const RowResult& e) {
  if (!e.valued) return "—";
  return e.valued > 1 ? mean_pm_sd(e.spread.mean, e.spread.sd) : number(e.spread.mean);
}

// The prediction interval to the digits of the scatter.
std::string interval(const RowResult& e) {
  if (!e.spread.low) return "—";
  return "[" + to_scatter(*e.spread.low, e.spread.sd) + ", " + to_scatter(*e.spread.high, e.spread.sd) + "]";
}

// "3 of 5": the samples in which the row holds, of those with a value.
std::string holds_in(const RowResult& e) { return std::to_string(e.holds) + " of " + std::to_string(e.valued); }

// The verdict with the row's warnings after it: "✅ consistent ⚠ samples too few to judge: ...".
std::string verdict_cell(const RowResult& e) {
  std::string cell = mark(e.verdict);
  for (const std::string& w : e.warnings) cell += " ⚠ " + w;
  return cell;
}

// The row's cells in validation.md.
std::vector<std::string> markdown_cells(const Judged& j) {
  const Row& r = j.row;
  const RowResult& e = j.result;
  std::string values;
  for (std::size_t k = 0; k < e.samples.size(); ++k) {
    const auto& v = e.samples[k].measured.value;
    values += (k ? ", " : "") + (e.valued > 1 && v ? to_scatter(*v, e.spread.sd) : number_or_dash(v));
  }
  return {r.name, statement(r), values, e.valued ? mean_sd(e) + " (" + std::to_string(e.valued) + ")" : "—", interval(e), holds_in(e),
          r.rule == "majority" ? "holds in > half" : r.rule == "every" ? "holds in every" : "interval", verdict_cell(e),
          r.must_pass ? "yes" : "no", r.source, r.reason};
}

// What a reading that explains a row does to the rows consistent here (decisions_file.hpp).
TurnsInconsistent side_effects_of(const std::vector<Judged>& judged) {
  return [&judged](const DecisionsFile& f, const std::string& reading) {
    std::vector<std::string> broken;
    for (const Judged& j : judged)
      if (auto b = turned_inconsistent(f, reading, j.row, j.result)) broken.push_back(std::move(*b));
    return broken;
  };
}

}  // namespace

std::vector<std::vector<std::string>> identical_samples(const std::vector<Judged>& judged) {
  std::vector<const Judged*> rows;
  for (const Judged& j : judged)
    if (j.row.rule != "every") rows.push_back(&j);
  if (rows.empty()) return {};
  // The values of sample k in every row, as bits (a NaN equals itself; 0.0 and -0.0 differ).
  const auto bits = [](const Measured& m) { return m.value ? std::optional<std::uint64_t>(std::bit_cast<std::uint64_t>(*m.value)) : std::nullopt; };
  const std::vector<RowResult::PerSample>& first = rows.front()->result.samples;
  const auto same = [&](std::size_t a, std::size_t b) {
    bool fraction = false;
    for (const Judged* j : rows) {
      const auto& s = j->result.samples;
      if (a >= s.size() || b >= s.size() || s[a].sample != first[a].sample || s[b].sample != first[b].sample ||
          bits(s[a].measured) != bits(s[b].measured))
        return false;
      if (s[a].measured.value && *s[a].measured.value != std::floor(*s[a].measured.value)) fraction = true;
    }
    return fraction;
  };
  std::vector<std::vector<std::string>> groups;
  std::vector<bool> grouped(first.size(), false);
  for (std::size_t a = 0; a < first.size(); ++a) {
    if (grouped[a]) continue;
    std::vector<std::string> group{first[a].sample};
    for (std::size_t b = a + 1; b < first.size(); ++b)
      if (!grouped[b] && same(a, b)) group.push_back(first[b].sample), grouped[b] = true;
    if (group.size() > 1) groups.push_back(group);
  }
  return groups;
}

const char* mark(Verdict v) {
  return v == Verdict::Consistent ? "✅ consistent" : v == Verdict::Inconsistent ? "❌ inconsistent" : "— not judged";
}

VerdictCounts count_verdicts(const std::vector<Judged>& judged) {
  VerdictCounts c;
  for (const Judged& j : judged) {
    ++c.verdicts[j.result.verdict];
    if (j.result.verdict == Verdict::Inconsistent && j.row.must_pass) ++c.must_pass_failed;
  }
  return c;
}

std::string statement(const Row& r) {
  if (r.check == "within") return number(r.reference) + (r.tolerance > 0 ? " ± " + number(r.tolerance) : "");
  return (r.check == "at_least" ? "≥ " : "≤ ") + number(r.reference);
}

nlohmann::ordered_json json_row(const Judged& j) {
  const Row& r = j.row;
  const RowResult& e = j.result;
  nlohmann::ordered_json row = {{"name", r.name}, {"group", r.group}, {"quantity", r.quantity}, {"density", j.runs.density},
                                {"reference", r.reference}, {"check", r.check}, {"tolerance", r.tolerance},
                                {"resolution", r.resolution}};
  row["per_sample"] = nlohmann::json::array();
  for (const auto& ps : e.samples) {
    nlohmann::ordered_json s = {{"sample", ps.sample}, {"value", json_number(ps.measured.value)}, {"note", ps.measured.note}};
    if (!ps.measured.misfit.empty()) s["misfit"] = ps.measured.misfit;  // judged again into the row's warnings
    row["per_sample"].push_back(s);
  }
  row["n"] = e.valued;
  row["mean"] = e.valued ? nlohmann::json(e.spread.mean) : nlohmann::json(nullptr);
  row["sd"] = e.valued > 1 ? nlohmann::json(e.spread.sd) : nlohmann::json(nullptr);
  row["prediction_interval"] = {json_number(e.spread.low), json_number(e.spread.high)};
  row["holds_in"] = e.holds;
  row["rule"] = r.rule;
  row["verdict"] = to_string(e.verdict);
  row["must_pass"] = r.must_pass;
  row["source"] = r.source;
  row["reason"] = r.reason;
  if (!e.warnings.empty()) row["warnings"] = e.warnings;  // rows.hpp: a verdict that cannot mean much
  return row;
}

std::string validation_table(const std::vector<Judged>& judged, const std::string& label) {
  MarkdownTable md({"check", label, "per sample", "mean ± sd (n)", number(100 * prediction_level) + " % interval of one sample", "holds in",
                    "rule", "verdict", "must pass", "source", "reason"});
  for (const Judged& j : judged) md.row(markdown_cells(j));
  return md.text();
}

std::string short_row_name(const std::string& name) {
  if (name.empty() || name.back() != ')') return name;
  int depth = 0;
  for (std::size_t i = name.size(); i-- > 0;) {
    if (name[i] == ')') ++depth;
    else if (name[i] == '(' && --depth == 0) {
      const std::size_t end = name.find_last_not_of(' ', i == 0 ? 0 : i - 1);
      return i == 0 || end == std::string::npos ? name : name.substr(0, end + 1);
    }
  }
  return name;
}

std::string cause_anchor(std::size_t index) { return "cause-" + std::to_string(index); }

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

std::string verdicts_text(const std::vector<Judged>& judged, const VerdictsContext& c) {
  const VerdictCounts n = count_verdicts(judged);
  std::vector<std::string> headings = {"row", c.label, "ours: mean ± sd", "samples in the " + c.label + "'s range", "verdict"};
  if (c.with_causes) headings.push_back("cause (in full: the link)");
  MarkdownTable compact(headings);
  MarkdownTable warned({"row", "verdict", "warning"});
  const TurnsInconsistent side_effects = side_effects_of(judged);
  std::size_t readings = 0;  // rows whose bound is this project's reading
  for (std::size_t i = 0; i < judged.size(); ++i) {
    const Judged& j = judged[i];
    for (const std::string& w : j.result.warnings) warned.row({j.row.name, mark(j.result.verdict), w});
    const bool reading = bound_is_reading(j.row);  // †
    readings += reading;
    std::vector<std::string> cells = {short_row_name(j.row.name), statement(j.row) + (reading ? " †" : ""), mean_sd(j.result),
                                      holds_in(j.result), verdict_words(j.result.verdict, !j.result.warnings.empty())};
    if (c.with_causes) {
      if (j.result.verdict == Verdict::Consistent) {
        cells.push_back("—");
      } else {
        const std::string link = "](" + c.causes_document + "#" + cause_anchor(i + 1) + ")";
        const std::size_t room = compact_cell_limit - code_points("[" + link);
        cells.push_back("[" + cause_line(c.findings, j.row.name, side_effects, room) + link);
      }
    }
    compact.row(cells);
  }
  std::ostringstream out;
  if (!c.provenance.empty()) out << c.provenance << "\n\n";
  out << "Of " << judged.size() << " rows, **" << n.of(Verdict::Consistent) << " consistent**, **" << n.of(Verdict::Inconsistent)
      << " inconsistent**, " << n.of(Verdict::NotJudged) << " not judged, over " << c.samples << " sample" << (c.samples == 1 ? "" : "s")
      << " per density. A value read from the " << c.label << " (rule *interval*) is consistent "
      << "when it, widened by the row's reading tolerance, overlaps the " << number(100 * prediction_level)
      << " % prediction interval of one sample of ours (mean ± t(" << number(0.5 + prediction_level / 2)
      << ", n−1) · sd · √(1 + 1/n)); a trend or an ordering (rule *holds in > half*) is consistent when it holds in "
         "more than half of our samples; a case without scatter (rule *holds in every*) when it holds in every sample. "
         "Otherwise, with fewer than two samples a row is not judged.\n";
  if (c.missing || c.missing_samples)
    out << "\n**Incomplete:** " << c.missing << " result file(s) missing or not complete"
        << (c.missing_samples ? ", and " + std::to_string(c.missing_samples) + " sample(s) that `runs.tsv` lists have no folder" : std::string())
        << "; the rows are judged on what is there.\n";
  out << "\n" << compact.text();
  if (readings)
    out << "\n†: a bound this project reads into the " << c.label << "'s words (\"grows\", \"independent of cycles\": a trend or an "
        << "ordering, for which the " << c.label << " gives no number); every other value is the " << c.label
        << "'s, ± the tolerance this project reads into it (each row's reason: its source and why that tolerance).\n";
  if (warned.rows()) {
    std::vector<Weakness> kinds;  // the kinds the table shows, each once, in the order of the enum
    for (const Judged& j : judged)
      for (Weakness k : weaknesses(j.result))
        if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
    std::sort(kinds.begin(), kinds.end());
    out << "\n" << weak_legend(kinds) << ":\n\n" << warned.text();
  }
  return out.str();
}

std::string causes_text(const std::vector<Judged>& judged, const VerdictsContext& c) {
  if (!c.with_causes) return "";
  const TurnsInconsistent side_effects = side_effects_of(judged);
  std::ostringstream entries;
  for (std::size_t i = 0; i < judged.size(); ++i) {
    const Judged& j = judged[i];
    if (j.result.verdict == Verdict::Consistent) continue;
    entries << "\n### Cause " << (i + 1) << "\n\n**" << j.row.name << "**: " << mark(j.result.verdict) << "; " << c.label << " "
            << statement(j.row) << ", interval of one sample " << interval(j.result) << ", holds in " << holds_in(j.result)
            << " samples. " << cause_text(c.findings, j.row.name, side_effects) << "\n";  // decisions_file.hpp
  }
  if (entries.str().empty()) return "";
  std::ostringstream out;
  if (c.findings.size() > 1)
    out << "What the decisions studies found for each row that is not consistent (each its own ensemble: "
           "`make decisions`, `make readings-report`): the findings of the largest size that judged the row, that size first "
           "(from the file's own record; \"size not recorded\": a file written before it recorded its size), each study named "
           "when two or more of that size judged the row, a finding that explains it first. After a reading that explains a "
           "row: the rows consistent here that its shift of their means, from the same study and applied to this ensemble's "
           "samples, turns inconsistent.\n";
  else
    out << "What the decisions study found for each row that is not consistent (its own ensemble, `make decisions`; after a "
           "reading that explains a row, the rows consistent here that its shift of their means, applied to this ensemble's "
           "samples, turns inconsistent).\n";
  out << entries.str();
  return out.str();
}

}  // namespace validation
