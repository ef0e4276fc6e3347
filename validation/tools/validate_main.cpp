// validate: judges a study's results against a reference file (reference_data/paper.yaml, or a
// user's own: validation/README.md), writes validation.json, validation.md and verdicts.md.
//   validate --results DIR --references FILE --out DIR [--profile NAME] [--decisions decisions.json]...
// DIR is a study's results folder, with the manifest the pipeline writes (DIR/runs.tsv): an
// ensemble (DIR/seed<N>/, one folder per sample) or one sample. Each row names the runs it reads by
// the study's names (variant, density, test; row_runs.hpp), and only those runs are read.
// Exit status: 0 only when everything asked for was done and judged: every result the rows need
// read (of every sample runs.tsv lists), every row judged, no must-pass row inconsistent; 1
// otherwise (the tables are still written, and stderr says why); 2 for bad arguments, a reference
// file that cannot be read or has a bad row (an unknown key or quantity, a selector naming what the
// study does not have), a results folder that does not exist or has no runs.tsv, or an --out that
// is not a folder.
// --decisions may be given several times (the decisions study, the readings at the paper's size):
// each row's cause is what the files of the largest size that judged it found, said with that size,
// and what a reading that explains it does to the rows consistent here (decisions_file.hpp).
// Every row is computed per sample; its verdict compares the reference's value, widened by the
// row's tolerance, with the 95 % prediction interval of a single sample of the ensemble (rows.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "judge/decisions_file.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/markdown_table.hpp"
#include "judge/row_runs.hpp"
#include "judge/rows.hpp"
#include "judge/study_results.hpp"
#include "io/failure.hpp"

namespace fs = std::filesystem;

namespace {

using validation::number;
using validation::Verdict;

struct Options {
  std::string results, references, out, profile = "paper";
  std::vector<std::string> decisions;  // decisions.json files, in the order given
};

// The options, or nothing when they are wrong or --help was asked (`code`: the exit status, 0 for
// --help, 2 for bad arguments; CLI11 has printed the help, or the error naming the option).
std::optional<Options> parse_options(int argc, char** argv, int& code) {
  Options o;
  CLI::App app{"validate: judges a study's results against a reference file (the paper's, reference_data/paper.yaml, or "
               "your own: validation/README.md); writes validation.json, validation.md and verdicts.md into --out"};
  app.name("validate");
  app.add_option("--results", o.results, "the study's results folder (its runs.tsv, written by build/bin/pipeline)")->required();
  app.add_option("--references", o.references, "the reference file: the rows to judge")->required();
  app.add_option("--out", o.out, "the folder the tables go to (made if missing)")->required();
  app.add_option("--profile", o.profile, "the reference file's profile (its rows' `profiles` entries)")->capture_default_str();
  app.add_option("--decisions", o.decisions,
                 "a decisions study's decisions.json (compare-runs decisions); may be given several times, each row's cause "
                 "is what the files of the largest size that judged it found")
      ->allow_extra_args(false);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    code = rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
    return std::nullopt;
  }
  if (o.profile.empty()) {
    std::fprintf(stderr, "validate: --profile: must not be empty\n");
    code = 2;
    return std::nullopt;
  }
  return o;
}

// The decisions studies' findings (compare-runs decisions), of the files that are there (a study
// not run yet has none).
std::vector<validation::DecisionsFile> read_findings(const std::vector<std::string>& files, const std::vector<validation::Row>& rows) {
  std::vector<validation::DecisionsFile> out;
  for (const std::string& file : files) {
    if (!fs::exists(file)) continue;
    try {
      out.push_back(validation::read_decisions_file(file, rows));
    } catch (const std::exception& e) {
      throw std::runtime_error(file + ": " + e.what());
    }
  }
  return out;
}

// An error message about --results or --out, or "" when both can be used.
std::string check_folders(const Options& o) {
  std::error_code ec;
  if (!fs::is_directory(o.results, ec))
    return "--results '" + o.results + "' " + (fs::exists(o.results, ec) ? "is not a folder" : "does not exist") +
           " (a study's results folder: seed<N>/ folders or one sample's results)";
  if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
    return "--out '" + o.out + "' is not a folder (validate writes validation.json, validation.md and verdicts.md into it)";
  return "";
}

// The reference's statement as a region: "0.73 ± 0.02", "≥ 0.05", "≤ 0".
std::string statement(const validation::Row& r) {
  if (r.check == "within") return number(r.reference) + (r.tolerance > 0 ? " ± " + number(r.tolerance) : "");
  return (r.check == "at_least" ? "≥ " : "≤ ") + number(r.reference);
}

std::string number_or_dash(const std::optional<double>& x) { return x ? number(*x) : "—"; }

nlohmann::json json_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); }

// "mean ± sd (n)", the digits from the scatter (format.hpp).
std::string mean_sd_n(const validation::RowResult& e) {
  if (!e.valued) return "—";
  return (e.valued > 1 ? validation::mean_pm_sd(e.spread.mean, e.spread.sd) : number(e.spread.mean)) + " (" + std::to_string(e.valued) + ")";
}

// The prediction interval to the digits of the scatter.
std::string interval(const validation::RowResult& e) {
  if (!e.spread.low) return "—";
  return "[" + validation::to_scatter(*e.spread.low, e.spread.sd) + ", " + validation::to_scatter(*e.spread.high, e.spread.sd) + "]";
}

// "3 of 5": the samples in which the row holds, of those with a value.
std::string holds_in(const validation::RowResult& e) { return std::to_string(e.holds) + " of " + std::to_string(e.valued); }

const char* mark(Verdict v) {
  return v == Verdict::Consistent ? "✅ consistent" : v == Verdict::Inconsistent ? "❌ inconsistent" : "— not judged";
}

// The verdict with the row's warnings after it: "✅ consistent ⚠ samples too few to judge: ...".
std::string verdict_cell(const validation::RowResult& e) {
  std::string cell = mark(e.verdict);
  for (const std::string& w : e.warnings) cell += " ⚠ " + w;
  return cell;
}

// A row, judged: which runs it read and what they gave.
struct Judged {
  validation::Row row;
  validation::RowRuns runs;
  validation::RowResult result;
};

nlohmann::ordered_json json_row(const Judged& j) {
  const validation::Row& r = j.row;
  const validation::RowResult& e = j.result;
  nlohmann::ordered_json row = {{"name", r.name}, {"group", r.group}, {"quantity", r.quantity}, {"density", j.runs.density},
                                {"reference", r.reference}, {"check", r.check}, {"tolerance", r.tolerance},
                                {"resolution", r.resolution}};
  row["per_sample"] = nlohmann::json::array();
  for (const auto& ps : e.samples)
    row["per_sample"].push_back({{"sample", ps.sample}, {"value", json_number(ps.measured.value)}, {"note", ps.measured.note}});
  row["n"] = e.valued;
  row["mean"] = e.valued ? nlohmann::json(e.spread.mean) : nlohmann::json(nullptr);
  row["sd"] = e.valued > 1 ? nlohmann::json(e.spread.sd) : nlohmann::json(nullptr);
  row["prediction_interval"] = {json_number(e.spread.low), json_number(e.spread.high)};
  row["holds_in"] = e.holds;
  row["rule"] = r.rule;
  row["verdict"] = validation::to_string(e.verdict);
  row["must_pass"] = r.must_pass;
  row["source"] = r.source;
  row["reason"] = r.reason;
  if (!e.warnings.empty()) row["warnings"] = e.warnings;  // rows.hpp: a verdict that cannot mean much
  return row;
}

// The row's cells in validation.md, in the order of validation_headings().
std::vector<std::string> markdown_cells(const Judged& j) {
  const validation::Row& r = j.row;
  const validation::RowResult& e = j.result;
  std::string values;
  for (std::size_t k = 0; k < e.samples.size(); ++k) {
    const auto& v = e.samples[k].measured.value;
    values += (k ? ", " : "") + (e.valued > 1 && v ? validation::to_scatter(*v, e.spread.sd) : number_or_dash(v));
  }
  return {r.name, statement(r), values, mean_sd_n(e), interval(e), holds_in(e), r.rule == "majority" ? "holds in > half" : r.rule == "every" ? "holds in every" : "interval",
          verdict_cell(e), r.must_pass ? "yes" : "no", r.source, r.reason};
}

std::vector<std::string> validation_headings(const std::string& label) {
  return {"check", label, "per sample", "mean ± sd (n)", validation::number(100 * validation::prediction_level) + " % interval of one sample", "holds in", "rule", "verdict", "must pass",
          "source", "reason"};
}

struct Counts {
  std::map<Verdict, int> verdicts;
  int must_pass_failed = 0;
};

// verdicts.md: the counts, the rule, what is missing, and the rows not consistent with their causes.
std::string verdicts_text(const std::vector<Judged>& judged, const Counts& c, std::size_t samples, std::size_t missing,
                          std::size_t missing_samples, const std::string& label, bool with_causes,
                          const std::vector<validation::DecisionsFile>& findings) {
  // Each row not consistent, with the decisions study's cause when --decisions gave its findings.
  std::vector<std::string> headings = {"row", "verdict", label, "interval of one sample", "holds in"};
  if (with_causes) headings.push_back("cause");
  // What a reading that explains a row does to the rows consistent here (decisions_file.hpp).
  const validation::TurnsInconsistent side_effects = [&](const validation::DecisionsFile& f, const std::string& reading) {
    std::vector<std::string> broken;
    for (const Judged& j : judged)
      if (auto b = validation::turned_inconsistent(f, reading, j.row, j.result)) broken.push_back(std::move(*b));
    return broken;
  };
  validation::MarkdownTable misses(headings);
  validation::MarkdownTable warned({"row", "verdict", "warning"});
  for (const Judged& j : judged)
    for (const std::string& w : j.result.warnings) warned.row({j.row.name, mark(j.result.verdict), w});
  for (const Judged& j : judged) {
    if (j.result.verdict == Verdict::Consistent) continue;
    std::vector<std::string> cells = {j.row.name, mark(j.result.verdict), statement(j.row), interval(j.result), holds_in(j.result)};
    if (with_causes) cells.push_back(validation::cause_text(findings, j.row.name, side_effects));  // decisions_file.hpp
    misses.row(cells);
  }
  auto n = [&](Verdict v) { return c.verdicts.count(v) ? c.verdicts.at(v) : 0; };
  std::ostringstream out;
  out << "Of " << judged.size() << " rows, **" << n(Verdict::Consistent) << " consistent**, **" << n(Verdict::Inconsistent)
      << " inconsistent**, " << n(Verdict::NotJudged) << " not judged, over " << samples << " sample" << (samples == 1 ? "" : "s")
      << " per density. A value read from the " << label << " (rule *interval*) is consistent "
      << "when it, widened by the row's reading tolerance, overlaps the " << validation::number(100 * validation::prediction_level)
      << " % prediction interval of one sample of ours (mean ± t(" << validation::number(0.5 + validation::prediction_level / 2)
      << ", n−1) · sd · √(1 + 1/n)); a trend or an ordering (rule *holds in > half*) is consistent when it holds in "
         "more than half of our samples; a case without scatter (rule *holds in every*) when it holds in every sample. "
         "Otherwise, with fewer than two samples a row is not judged.\n";
  if (missing || missing_samples)
    out << "\n**Incomplete:** " << missing << " result file(s) missing or not complete"
        << (missing_samples ? ", and " + std::to_string(missing_samples) + " sample(s) that `runs.tsv` lists have no folder" : std::string())
        << "; the rows are judged on what is there.\n";
  if (misses.rows() && with_causes && findings.size() > 1)
    out << "\nThe rows that are not consistent, and what the decisions studies found for each (each its own ensemble: "
           "`make decisions`, `make readings-report`): the findings of the largest size that judged the row, that size first "
           "(from the file's own record; \"size not recorded\": a file written before it recorded its size), each study named "
           "when two or more of that size judged the row, a finding that explains it first. After a reading that explains a "
           "row: the rows consistent here that its shift of their means, from the same study and applied to this ensemble's "
           "samples, turns inconsistent:\n\n"
        << misses.text();
  else if (misses.rows() && with_causes)
    out << "\nThe rows that are not consistent, and what the decisions study found for each (its own ensemble, "
           "`make decisions`; after a reading that explains a row, the rows consistent here that its shift of their means, "
           "applied to this ensemble's samples, turns inconsistent):\n\n" << misses.text();
  else if (misses.rows())
    out << "\nThe rows that are not consistent:\n\n" << misses.text();
  if (warned.rows())
    out << "\nVerdicts that cannot mean much (a quantity that does not fit the runs it read, or an interval of one sample "
           "wider than " << validation::number(validation::too_few_width) << " times the row's tolerance):\n\n" << warned.text();
  return out.str();
}

// Each value of a row that is not a finite number (a NaN or an infinity in a result), named with its
// row, its sample and the runs it read.
std::vector<std::string> non_finite_values(const std::vector<Judged>& judged, const std::string& results) {
  std::vector<std::string> out;
  for (const Judged& j : judged)
    for (const auto& ps : j.result.samples)
      if (ps.measured.value && !std::isfinite(*ps.measured.value)) {
        std::string runs = j.runs.preparation ? j.runs.density + "_prepare" : "";
        for (const std::string& t : j.runs.tests) runs += (runs.empty() ? "" : ", ") + j.runs.density + "_" + t;
        out.push_back("row '" + j.row.name + "': " + (ps.sample.empty() ? "the sample" : "sample " + ps.sample) + " gives " +
                      number(*ps.measured.value) + ", from " + (fs::path(results) / ps.sample).string() + " (" + runs +
                      "): a non-finite number in its results");
      }
  return out;
}

// Pairs of samples whose runs a row read are the same to the last digit (every value of the last
// rows of the preparation): a copied sample folder would count one sample twice.
std::vector<std::string> copied_samples(const std::vector<Judged>& judged, const validation::StudyResults& results) {
  std::vector<std::string> out;
  std::set<std::string> said;
  const std::vector<std::string>& samples = results.samples();
  for (const Judged& j : judged)
    for (std::size_t a = 0; a < samples.size(); ++a)
      for (std::size_t b = a + 1; b < samples.size(); ++b) {
        const validation::DensityResults* x = results.of(j.runs, samples[a]);
        const validation::DensityResults* y = results.of(j.runs, samples[b]);
        if (!x || !y || !x->prepared || !y->prepared || x->sample.empty() || x->sample != y->sample) continue;
        const std::string what = samples[a] + " and " + samples[b] + " have the same " + j.runs.density + " preparation";
        if (said.insert(what).second)
          out.push_back(what + " (every value of its last row): a copied sample folder counts one sample twice");
      }
  return out;
}

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  int code = 2;
  const std::optional<Options> opt = parse_options(argc, argv, code);
  if (!opt) return code;
  const Options& o = *opt;
  validation::References refs;
  std::vector<validation::DecisionsFile> findings;
  std::vector<validation::ManifestLine> manifest;
  std::vector<Judged> judged;
  try {
    refs = validation::read_references(o.references, o.profile);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  try {
    findings = read_findings(o.decisions, refs.rows);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --decisions %s\n", e.what());
    return 2;
  }
  // A file that declares profiles knows them all: another name than those and paper (every row as
  // written) is a typo, which would judge every row as written.
  if (!refs.profiles.empty() && !refs.profiles.count(o.profile) && o.profile != "paper") {
    std::string known = "paper (every row as written)";
    for (const std::string& p : refs.profiles) known += ", " + p;
    std::fprintf(stderr, "error: --profile '%s': no row of %s has it; its profiles: %s\n", o.profile.c_str(), o.references.c_str(),
                 known.c_str());
    return 2;
  }
  if (const std::string bad = check_folders(o); !bad.empty()) {
    std::fprintf(stderr, "error: %s\n", bad.c_str());
    return 2;
  }
  try {
    fs::create_directories(o.out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --out '%s': cannot create the folder: %s\n", o.out.c_str(), e.what());
    return 2;
  }
  // The study's names, and the runs each row reads: a row that names what the study lacks is refused.
  try {
    manifest = validation::read_manifest(o.results);
    const std::string study = (fs::path(o.results) / "runs.tsv").string();
    for (const validation::Row& r : refs.rows) judged.push_back({r, validation::resolve_runs(r, manifest, study), {}});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::vector<validation::RowRuns> needed;
  for (const Judged& j : judged) needed.push_back(j.runs);
  const validation::StudyResults results(o.results, manifest, needed);
  Counts count;
  for (Judged& j : judged) {
    std::vector<std::pair<std::string, const validation::DensityResults*>> of_samples;
    for (const std::string& s : results.samples()) of_samples.emplace_back(s, results.of(j.runs, s));
    j.result = validation::evaluate(j.row, of_samples);
    ++count.verdicts[j.result.verdict];
    if (j.result.verdict == Verdict::Inconsistent && j.row.must_pass) ++count.must_pass_failed;
  }
  const int consistent = count.verdicts[Verdict::Consistent], inconsistent = count.verdicts[Verdict::Inconsistent],
            not_judged = count.verdicts[Verdict::NotJudged];
  const std::vector<std::string>& missing = results.missing();
  const std::vector<std::string>& missing_samples = results.missing_samples();

  nlohmann::ordered_json json;
  json["profile"] = o.profile;
  json["references"] = o.references;
  json["rules"] = {
      {"interval", "consistent: the " + refs.label + "'s value, widened by the row's tolerance, overlaps the " +
                       validation::number(100 * validation::prediction_level) + " % prediction interval of one sample (mean -/+ t(" +
                       validation::number(0.5 + validation::prediction_level / 2) + ", n-1) sd sqrt(1 + 1/n))"},
      {"majority", "consistent: the " + refs.label + "'s statement holds in more than half of the samples"},
      {"every", "consistent: the " + refs.label + "'s statement holds in every sample with a value, one or more (a case without scatter)"},
      {"both", "interval and majority: not judged with fewer than 2 samples with a value"}};
  json["samples"] = results.samples();
  json["missing_samples"] = missing_samples;
  json["missing_results"] = nlohmann::json::array();
  for (const std::string& m : missing) json["missing_results"].push_back(fs::path(m).lexically_relative(o.results).string());  // lexical: a link loop cannot throw
  json["rows"] = nlohmann::json::array();
  validation::MarkdownTable md(validation_headings(refs.label));
  for (const Judged& j : judged) {
    json["rows"].push_back(json_row(j));
    md.row(markdown_cells(j));
  }
  json["consistent"] = consistent;
  json["inconsistent"] = inconsistent;
  json["not_judged"] = not_judged;
  json["total"] = judged.size();
  json["must_pass_inconsistent"] = count.must_pass_failed;
  // Everything asked for done and judged (the exit status 0).
  json["complete"] = missing.empty() && missing_samples.empty() && not_judged == 0;
  try {
    dem::write_file_atomically((fs::path(o.out) / "verdicts.md").string(),
                               verdicts_text(judged, count, results.samples().size(), missing.size(), missing_samples.size(),
                                             refs.label, !o.decisions.empty(), findings));
    dem::write_file_atomically((fs::path(o.out) / "validation.json").string(), json.dump(2) + "\n");
    dem::write_file_atomically((fs::path(o.out) / "validation.md").string(), md.text());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  const std::size_t n_samples = results.samples().size();
  std::printf("validation of %zu sample%s: %d consistent, %d inconsistent, %d not judged of %zu rows; %d must-pass rows inconsistent; %zu result files missing, %zu samples missing -> %s\n",
              n_samples, n_samples == 1 ? "" : "s", consistent, inconsistent, not_judged, judged.size(), count.must_pass_failed,
              missing.size(), missing_samples.size(), (fs::path(o.out) / "validation.json").c_str());
  for (const Judged& j : judged)  // warnings change no exit status: the verdict stands, and says it
    for (const std::string& w : j.result.warnings) std::fprintf(stderr, "warning: %s: %s\n", j.row.name.c_str(), w.c_str());
  int status = 0;
  if (!missing_samples.empty()) {
    std::string names;
    for (const std::string& m : missing_samples) names += (names.empty() ? "" : ", ") + m;
    std::fprintf(stderr, "error: %s/runs.tsv lists %zu sample(s) whose folder is gone: %s\n", o.results.c_str(), missing_samples.size(), names.c_str());
    status = 1;
  }
  if (!missing.empty()) {
    std::fprintf(stderr, "error: %zu result file(s) missing or not complete (of the runs the rows read), e.g. %s\n", missing.size(), missing.front().c_str());
    status = 1;
  }
  if (not_judged > 0) {
    std::string names;
    for (const Judged& j : judged)
      if (j.result.verdict == Verdict::NotJudged) names += (names.empty() ? "" : "; ") + j.row.name;
    std::fprintf(stderr, "error: %d row(s) not judged (fewer than 2 samples with a value): %s\n", not_judged, names.c_str());
    status = 1;
  }
  if (const std::vector<std::string> bad = non_finite_values(judged, o.results); !bad.empty()) {
    for (const std::string& b : bad) std::fprintf(stderr, "error: %s\n", b.c_str());
    status = 1;
  }
  if (const std::vector<std::string> copies = copied_samples(judged, results); !copies.empty()) {
    for (const std::string& c : copies) std::fprintf(stderr, "error: %s\n", c.c_str());
    status = 1;
  }
  if (count.must_pass_failed > 0) {
    std::fprintf(stderr, "error: %d must-pass row(s) inconsistent with the %s\n", count.must_pass_failed, refs.label.c_str());
    status = 1;
  }
  return status;
}

int main(int argc, char** argv) { return dem::guarded_main("validate", [&] { return tool_main(argc, argv); }); }
