// report: writes the study report (REPORT_DIR/index.md) from a study's results, the validation
// output, the figures, the other studies' tables, the resolved scenes and reference_data/. The text
// is reports/templates/index.md with its {{keys}} filled; every number is computed here
// (validation/report/report.hpp) or by the tool that wrote the table included (validate, figure-data,
// compare-runs). The figure notes are reports/templates/figure_notes.tsv, filled from the data the
// figures plot and the verdicts of the validation rows about them.
//   report --results DIR --references FILE --out REPORT_DIR [--profile NAME] [--sample NAME]
//          [--templates DIR] [--baseline FILE] [--decisions DIR] [--stability DIR]
//          [--source TEXT] [--note TEXT] [--allow-other-baseline]
// --source defaults to the commit the tools were built from, "(with uncommitted changes)" when the
// tree differed from it (engine/cmake/version.cmake: the one definition of a modified tree).
// REPORT_DIR holds what the other tools wrote (validation.md, verdicts.md, figures/, samples.md,
// decisions/, convergence/, stability/, critical_state/, liquefaction/, bench.md); a part that is
// missing is said so in its section. --baseline: an earlier baseline's validation.json, compared
// row by row. What the text takes from the paper study's results is written to
// REPORT_DIR/study_values.json whenever they are here, and read from it when they are not
// (report/study_values.hpp), so the report is written again anywhere from committed files. Under the heading of each section another study made (report/other_sections.hpp) a
// line says the engine, baseline, size and date of its numbers; a section whose baseline or
// engine source differs from the paper study's (REPORT_DIR/validation.json's stamp) is refused
// (exit 1, naming it) unless --allow-other-baseline, which heads it "⚠ from another baseline" (or
// engine); so is a study_values.json from another baseline or engine, and a validation.json that
// judged other results than --results (another engine, baseline, size or samples). Exit status: 0; 1 if the report cannot be written, a
// template names an unknown key or a result file is there but cannot be read; 2 for bad arguments
// or a --results that is not a folder (one that does not exist is accepted when REPORT_DIR has a
// study_values.json).
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/atomic_file.hpp"
#include "figures/figure_bounds.hpp"
#include "io/failure.hpp"
#include "report/other_sections.hpp"
#include "study/json_file.hpp"
#include "report/baseline_check.hpp"
#include "report/prose_numbers.hpp"
#include "report/report.hpp"
#include "report/report_values.hpp"
#include "report/study_values.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/paths.hpp"
#include "study/settings.hpp"
#include "version.hpp"

namespace fs = std::filesystem;

namespace {

// What a file from other results (`differs`: what differs, "" when nothing does) does to the
// report: refused (false, `why` said on stderr), or with --allow-other-baseline kept and named in
// the header (`elsewhere`).
bool kept_or_refused(const std::string& differs, bool allow, std::vector<std::string>& elsewhere, const std::string& what,
                     const std::string& why) {
  if (differs.empty()) return true;
  if (!allow) {
    std::fprintf(stderr, "report: %s, or keep it with --allow-other-baseline\n", why.c_str());
    return false;
  }
  elsewhere.push_back(what + " (another " + differs + ")");
  return true;
}

// What the report was made from when --source does not say: the commit the tools were built from,
// and whether the tree differed from it, as engine/cmake/version.cmake decides (the one definition
// of a modified tree; dem::software_version is "VERSION+COMMIT" or "VERSION+COMMIT-modified").
std::string built_from() {
  const std::string version = dem::software_version, modified = "-modified";
  std::string commit = version.substr(version.find('+') + 1);
  const bool changed = commit.size() > modified.size() && commit.compare(commit.size() - modified.size(), modified.size(), modified) == 0;
  if (changed) commit.resize(commit.size() - modified.size());
  return "commit " + commit + (changed ? " (with uncommitted changes)" : "");
}

}  // namespace


// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
namespace {

// Nothing to report on is an error: --results must be a folder; one that does not exist only
// when the report's folder keeps what an earlier report took from the results (study_values.json).
// --out must be a folder or not exist yet. False (the error printed) when they are not.
bool folders_usable(const std::string& results, const std::string& out) {
  std::error_code ec;
  if (const std::string bad = validation::folder_problem(results);
      !bad.empty() && !(bad == "does not exist" && fs::exists(fs::path(out) / validation::study_values_file, ec))) {
    std::fprintf(stderr, "report: --results '%s' %s (a study's results folder: seed<N>/ folders or one sample's results%s)\n",
                 results.c_str(), bad.c_str(),
                 bad == "does not exist" ? "; without it, REPORT_DIR/study_values.json, which a report written with the results leaves" : "");
    return false;
  }
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    std::fprintf(stderr, "report: --out '%s' is not a folder\n", out.c_str());
    return false;
  }
  return true;
}

// The notes' verdicts and the earlier baseline's table (--baseline: `baseline`) as validation.json's
// rows give them (the verdict table's), weak ones marked; a table kept as text by an older
// study_values.json is not shown.
void add_judged_values(validation::Values& v, const fs::path& report, const std::vector<validation::Row>& rows, const std::string& baseline) {
  v.erase("baseline.table");
  try {
    const validation::PaperEnsemble judged = validation::read_paper_ensemble(report, rows);
    validation::add_note_verdicts(v, judged);
    if (!baseline.empty() && !judged.rows.empty()) {
      v["baseline.file"] = baseline;
      v["baseline.table"] = validation::baseline_table(validation::read_json_file(baseline), judged.rows);
    }
  } catch (const std::exception& e) {  // the notes keep the verdicts computed with the results
    std::fprintf(stderr, "report: %s; the figure notes' verdicts and the earlier baseline's table are not taken from it\n", e.what());
  }
}

// Each sentence of the report that states one number in two roundings, said (report/prose_numbers.hpp):
// the report is written, and the sentence's section is what to correct.
void warn_restated(const std::string& text) {
  for (const validation::RestatedNumber& r : validation::numbers_restated(text))
    std::fprintf(stderr, "report: warning: one number in two roundings, %s and %s, in one sentence: \"%s\"\n", r.longer.c_str(),
                 r.shorter.c_str(), r.sentence.c_str());
}

}  // namespace

int tool_main(int argc, char** argv) {
  std::map<std::string, std::string> opt = {{"--profile", "paper"}, {"--templates", "reports/templates"}};
  CLI::App app{"report: writes the study report REPORT_DIR/index.md from a study's results, the validation output, the figures, "
               "the other studies' tables, the resolved scenes and reference_data/ (the text: TEMPLATES/index.md, every number "
               "computed)"};
  app.name("report");
  const auto option = [&](const std::string& name, const std::string& what) { return app.add_option(name, opt[name], what); };
  option("--results", "the study's results folder (its runs.tsv)")->required();
  option("--references", "the reference file (reference_data/paper.yaml)")->required();
  option("--out", "REPORT_DIR: holds what the other tools wrote (validation.md, figures/, ...); index.md goes there")->required();
  option("--profile", "the reference file's profile of the rows")->capture_default_str();
  option("--sample", "the sample whose runs the single-run figures show (e.g. seed1)");
  option("--templates", "the folder of index.md and figure_notes.tsv")->capture_default_str();
  option("--baseline", "an earlier baseline's validation.json, compared row by row");
  option("--decisions", "the decisions study's results folder (its settings for the text)");
  option("--stability", "the stability study's results folder (its settings for the text)");
  option("--source", "what the report was made from (default: the commit the tools were built from, and whether the tree "
                     "differed from it outside reports/)");
  option("--note", "a note printed at the top of the report");
  bool allow_other_baseline = false;
  app.add_flag("--allow-other-baseline", allow_other_baseline,
               "keep a section another study made on another baseline or engine source than the paper study's (its stamp "
               "says which), headed \"⚠ from another baseline\" (or engine); without it such a section is refused (exit 1)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
  }
  for (const char* k : {"--results", "--references", "--out"})
    if (opt[k].empty()) {
      std::fprintf(stderr, "report: %s must not be empty\n", k);
      return 2;
    }
  const std::string results = opt["--results"], out = opt["--out"];
  std::error_code ec;
  if (!folders_usable(results, out)) return 2;
  try {
    fs::create_directories(out);
    const fs::path report = out;
    const validation::ReportSources src{results, out, opt["--templates"], opt["--baseline"],
                                        opt["--decisions"], opt["--stability"],
                                        opt["--source"].empty() ? built_from() : opt["--source"], opt["--note"]};
    validation::ReportInputs in;
    in.paper = validation::load_references(opt["--references"], "paper");
    in.rows = validation::load_references(opt["--references"], opt["--profile"]);
    std::vector<std::string> missing;
    const bool have_results = fs::is_directory(results, ec);
    const std::vector<std::string> densities = have_results ? validation::study_densities(results) : validation::paper_densities();
    if (have_results) in.samples = validation::load_samples(results, densities, missing);
    if (validation::report_unreadable("report", missing)) return 1;  // lost, not merely not run
    in.sample = opt["--sample"];
    // The values the results give: computed and kept beside the report, or read back from there.
    const bool fresh = have_results && !in.samples.empty();
    const bool stability_here = !opt["--stability"].empty() && fs::exists(fs::path(opt["--stability"]) / "runs.tsv", ec);
    std::optional<validation::StudyValues> from_results;
    if (fresh) {
      from_results = validation::StudyValues{validation::stamp_of_results(results), validation::shown_path(results),
                                             validation::values_from_results(in, results, opt["--baseline"], densities)};
      // The stability study's settings, which its section quotes, kept with them when its results are here.
      if (stability_here) validation::add_study_settings(from_results->values, opt["--stability"]);
      // Rendered below from typed values (validation.json's rows, the earlier baseline's file), not kept as text.
      from_results->values.erase("baseline.table");
      validation::write_study_values(report, *from_results);
    } else {
      from_results = validation::read_study_values(report);
    }
    validation::Values v = fresh ? validation::Values{} : validation::figure_values(in);  // no samples: the constants the text quotes
    if (from_results) {
      for (const auto& [k, val] : from_results->values) v[k] = val;
    } else {
      v["sample"] = in.sample.empty() ? "—" : in.sample, v["samples_n"] = "0";  // no results: the sample named
      validation::add_settings(v, results, false);
    }
    const bool read_back = from_results && !fresh;
    const std::string values_file = (report / validation::study_values_file).string();
    validation::add_provenance(v, src, from_results.has_value(), missing.size());
    if (read_back) {
      v["results"] = from_results->results;
      v["values.file"] = values_file;
      v["values.stamp"] = validation::stamp_text(from_results->stamp);
      // The bounds the notes state, worded again from the unrounded data of the figures they
      // describe (a file kept from before they were rounded outwards holds them rounded to nearest).
      const auto last = v.find("cycles.last");
      validation::add_figure_bounds(v, report / "figures",
                                    last == v.end() ? std::nullopt : std::optional<int>(std::stoi(last->second)));
    }
    validation::add_tables(v, report, in.paper, opt["--decisions"]);
    const validation::Stamp paper_stamp = validation::read_paper_stamp(report);
    v["stamp.paper"] = paper_stamp.recorded() ? validation::stamp_text(paper_stamp)
                                              : "made before stamps (their engine and baseline are not recorded, so no section is compared with them)";
    // What is kept from another baseline or engine (with --allow-other-baseline), named in the
    // header: the verdicts and values here, the sections once every table is in (below).
    std::vector<std::string> kept;
    // The verdicts shown are validation.json's: it must have judged these results (the same
    // engine, baseline, spheres and samples), or the report would present another study's verdicts
    // as this one's.
    if (const std::string differs = fresh ? validation::judged_difference(from_results->stamp, paper_stamp) : "";
        !kept_or_refused(differs, allow_other_baseline, kept, "the verdicts of `" + (report / "validation.json").string() + "`",
                         (report / "validation.json").string() + " judged other results than --results " + validation::shown_path(results) +
                             ": its " + differs + " differ; run validate on these results first"))
      return 1;
    // The values read back must come from the results validation.json judged: another baseline is
    // refused as a section would be.
    if (const std::string differs = read_back ? validation::stamp_difference(from_results->stamp, paper_stamp) : "";
        !kept_or_refused(differs, allow_other_baseline, kept, "the values of `" + values_file + "`",
                         values_file + " was written from results on another " + differs + " than reports/validation.json's (" +
                             from_results->stamp.baseline + " against " + paper_stamp.baseline + "); write the report with the results here"))
      return 1;
    validation::add_setup(v, report, !from_results ? "" : read_back ? "`" + values_file + "`" : "the resolved scenes of the results");
    // The stability study's settings: read once from its results (above, with fresh values), else as
    // the values file kept them, else none.
    if ((stability_here && !fresh) || !v.count("have_stability")) validation::add_study_settings(v, stability_here ? opt["--stability"] : "");
    add_judged_values(v, report, in.rows, opt["--baseline"]);
    // The sections from elsewhere, after the last table is filled (the earlier baseline's is
    // added just above): the header names every section stamp_sections heads with ⚠.
    std::vector<std::string> elsewhere;
    for (const auto& [section, differs] : validation::sections_from_elsewhere(report, v, paper_stamp))
      elsewhere.push_back("\"" + validation::section_shown(section) + "\" (another " + differs + ")");
    elsewhere.insert(elsewhere.end(), kept.begin(), kept.end());
    v["stamp.elsewhere"] = allow_other_baseline ? validation::joined(elsewhere, ", ") : "";
    const std::string notes = validation::read_text(fs::path(opt["--templates"]) / "figure_notes.tsv");
    if (notes.empty()) throw std::runtime_error(opt["--templates"] + "/figure_notes.tsv is missing or empty");
    validation::add_figures(v, report, notes);

    const std::string tmpl = validation::read_text(fs::path(opt["--templates"]) / "index.md");
    if (tmpl.empty()) throw std::runtime_error(opt["--templates"] + "/index.md is missing or empty");
    std::string text = validation::fill(tmpl, v);
    // Each section another study made, with its stamp; one from another baseline is refused unless allowed.
    const validation::StampedReport stamped = validation::stamp_sections(text, report, v, paper_stamp, allow_other_baseline);
    if (!stamped.refused.empty()) {
      for (const std::string& r : stamped.refused) std::fprintf(stderr, "report: %s\n", r.c_str());
      std::fprintf(stderr, "report: %s not written\n", (report / "index.md").c_str());
      return 1;
    }
    for (const std::string& h : stamped.other) std::fprintf(stderr, "report: warning: '%s' kept from another baseline or engine (headed ⚠)\n", h.c_str());
    text = stamped.text;
    dem::write_file_atomically((report / "index.md").string(), text);
    warn_restated(text);
    std::fprintf(stderr, "report written to %s (%zu sample(s) of %s%s)\n", (report / "index.md").c_str(), in.samples.size(),
                 validation::shown_path(results).c_str(), missing.empty() ? "" : (", " + std::to_string(missing.size()) + " result files missing").c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) { return dem::guarded_main("report", [&] { return tool_main(argc, argv); }); }
