#pragma once
// The tables validate writes of its judged rows: validation.json (every row with its per-sample
// values, which `validate --from-json` judges again), validation.md (every row in full), verdicts.md
// (the counts, the rule and the compact verdict table: one line per row, its cause in one line with
// a link to its entry in causes.md) and causes.md (each row that is not consistent with the cause
// the decisions studies found, in full). Pure functions of the judged rows, so that a validation
// judged from the results and one judged again from its validation.json write the same tables.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "judge/decisions_file.hpp"
#include "judge/row_runs.hpp"
#include "judge/rows.hpp"

namespace validation {

// A row, judged: which runs it read (their density, for validation.json) and what they gave.
struct Judged {
  Row row;
  RowRuns runs;
  RowResult result;
};

struct VerdictCounts {
  std::map<Verdict, int> verdicts;
  int must_pass_failed = 0;
  int of(Verdict v) const { return verdicts.count(v) ? verdicts.at(v) : 0; }
};
VerdictCounts count_verdicts(const std::vector<Judged>& judged);

// The groups of samples whose values are the same to the last bit in every row (each group two or
// more samples, in the rows' sample order): one sample counted as several, which the interval and
// majority rules would take for independent samples that agree (a seed set by hand in an ensemble,
// a copied folder). Rows of the rule "every" (no scatter meant) are left out, and so are samples
// that agree only on whole numbers (a count, an ordering): a group needs a value with a fraction.
std::vector<std::vector<std::string>> identical_samples(const std::vector<Judged>& judged);

// The reference's statement as a region: "0.73 ± 0.02", "≥ 0.05", "≤ 0".
std::string statement(const Row& r);

// A verdict as the tables mark it: "✅ consistent", "❌ inconsistent", "— not judged".
const char* mark(Verdict v);

// A row of validation.json: the row's definition, every sample's value (with its note, and its
// misfit when it has one) and the verdict.
nlohmann::ordered_json json_row(const Judged& j);

// validation.md's table.
std::string validation_table(const std::vector<Judged>& judged, const std::string& label);

// What the tables need besides the rows.
struct VerdictsContext {
  std::string label;                  // "paper", or the reference file's own label
  std::string provenance;             // the first line of validation.md and verdicts.md: what was judged
  std::size_t samples = 0;            // samples per density
  std::size_t missing = 0;            // result files missing or not complete
  std::size_t missing_samples = 0;    // samples runs.tsv lists without a folder
  bool with_causes = false;           // --decisions given: the compact table has a cause column
  // The document the cause cells link to: causes.md beside verdicts.md; "" for the same document
  // (reports/index.md, which holds the causes in its own appendix).
  std::string causes_document = "causes.md";
  std::vector<DecisionsFile> findings;
};

// A row's name for the compact table: without its last parenthesis when it ends in one ("medium:
// εv grows with cycles (cycles 1..5, %)" -> "medium: εv grows with cycles").
std::string short_row_name(const std::string& name);

// The anchor of a row's entry in causes.md (and in the report's appendix): "cause-N", N the row's
// place (from 1) among the judged rows; the heading "Cause N" gets that id on GitHub and in
// reports/render_html.sh.
std::string cause_anchor(std::size_t index);

// The longest a cell of the compact table may be, in characters (code points) of its Markdown.
constexpr std::size_t compact_cell_limit = 80;

// verdicts.md: the provenance line, the counts and the rule, the compact table (row, the reference's
// statement, ours as mean ± sd, the samples inside the reference's region, the verdict and, with
// causes, the cause in one line linking to <causes_document>#cause-N), what is missing, and the verdicts
// that cannot mean much.
std::string verdicts_text(const std::vector<Judged>& judged, const VerdictsContext& c);

// What validate writes besides verdicts.md when it has causes: the same text with causes_document
// "", which the report includes as it is (no link of another tool's Markdown is rewritten).
inline constexpr const char* verdicts_in_report_file = "verdicts_in_report.md";

// causes.md: how the causes are chosen, then for each row that is not consistent a "### Cause N"
// entry with the row, its verdict and interval and the cause in full. "" when there are no causes
// (no --decisions, or every row consistent).
std::string causes_text(const std::vector<Judged>& judged, const VerdictsContext& c);

// The number of characters (UTF-8 code points) of `s`: what the cell limit counts.
std::size_t code_points(const std::string& s);

}  // namespace validation
