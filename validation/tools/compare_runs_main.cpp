// compare-runs: the tables of a study of variants, from the pipeline's manifest (DIR/runs.tsv).
//   compare-runs convergence RESULTS_DIR OUT_DIR [--reference NAME] [--threads N] [--validation FILE]
//   compare-runs convergence --summary SUMMARY_JSON OUT_DIR [--reference NAME] [--validation FILE]
//   compare-runs stability RESULTS_DIR OUT_DIR [--report-only]
//   compare-runs decisions RESULTS_DIR OUT_DIR [--reference NAME] [--references FILE] [--ensemble PAPER_RESULTS]
//                          [--baseline-results DIR]
//   compare-runs decisions --from-json DECISIONS_JSON OUT_DIR [--references FILE] [--ensemble-json VALIDATION_JSON]
//   compare-runs critical-state RESULTS_DIR OUT_DIR [--ensemble DIR] [--rates DIR]
//   compare-runs liquefaction OUT_DIR RESULTS_DIR...
// Every mode takes --draw GNUPLOT_DIR (reports/gnuplot): its section's figures drawn in OUT_DIR
// once its data are written (sections/draw.hpp declares them). convergence without results
// (RESULTS_DIR has no runs.tsv) but with OUT_DIR/summary.json re-draws from that summary, and says so.
// Every mode takes --without-results keep|redraw: a study that has not run here (RESULTS_DIR has no
// runs.tsv, or no finished run) is no error; `redraw` re-draws the section from OUT_DIR's committed
// summary where the mode keeps one (convergence: summary.json, decisions: decisions.json, whose
// stamps the section keeps), and otherwise, as `keep` always, OUT_DIR is left as it is. Either way
// the tool says which source it used and exits 0 (without the option: exit 1 or 2, as below).
// Each mode is a file of sections/ (what it writes: modes.hpp); this one parses the arguments
// (every sub-command answers --help) and calls it. stability, critical-state and liquefaction also
// write OUT_DIR/stamp.json, decisions a "stamp" in decisions.json (study/stamp.hpp).
// Exit status: 0; 1 if a stability case is not acceptable, the reference or baseline is missing,
// or an output cannot be written; 2 on bad arguments (the error names the option) or an unreadable
// manifest or references file.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "sections/draw.hpp"
#include "study/settings.hpp"
#include "sections/modes.hpp"
#include "study/stamp.hpp"
#include "io/failure.hpp"

namespace {

// The results folder and the output folder every mode but liquefaction takes.
struct Folders {
  std::string results, out;
};

// Every option of every mode, parsed into one place.
struct Options {
  Folders convergence, stability, decisions, critical;
  std::string reference = "reference", baseline = "baseline", references = "reference_data/paper.yaml";
  std::string ensemble, baseline_results, from_json, ensemble_json;     // decisions
  std::string convergence_summary, validation_json;                     // convergence
  int threads_per_run = 1;
  bool report_only = false;                                             // stability
  std::string stability_summary;                                        // stability, --without-results redraw
  std::string critical_ensemble, critical_rates, critical_references;  // critical-state
  std::string liquefaction_out;
  std::vector<std::string> liquefaction_folders;
  std::string draw_dir;         // every mode
  std::string without_results;  // every mode: "", "keep" or "redraw"
};

// The sub-commands, to ask which one was given.
struct Modes {
  CLI::App *convergence, *stability, *decisions, *critical, *liquefaction;
};

CLI::App* study_mode(CLI::App& app, const std::string& name, const std::string& what, Folders& f) {
  CLI::App* cmd = app.add_subcommand(name, what);
  cmd->add_option("RESULTS_DIR", f.results, "the study's results folder (its runs.tsv, written by build/bin/pipeline)")->required();
  cmd->add_option("OUT_DIR", f.out, "where the tables and the figures' data go (made if missing)")->required();
  return cmd;
}

// Not study_mode(): with --summary the one folder given is OUT_DIR (checked after parsing).
CLI::App* convergence_mode(CLI::App& app, Options& o) {
  CLI::App* cmd = app.add_subcommand(
      "convergence", "the error budget of the reference's settings in time step, rate and size, every setting's error against the "
                     "converged values with its cost: summary.json (from results), table.md, errors.dat, front.dat");
  cmd->add_option("RESULTS_DIR", o.convergence.results,
                  "the study's results folder (its runs.tsv, written by build/bin/pipeline); left out with --summary");
  cmd->add_option("OUT_DIR", o.convergence.out, "where the tables and the figure's data go (made if missing)");
  cmd->add_option("--reference", o.reference, "the variant at the paper's settings")->capture_default_str();
  cmd->add_option("--threads", o.threads_per_run, "threads each run used (core-seconds = wall time x threads)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--validation", o.validation_json, "the paper study's validation.json: each inconsistent row's miss against the budget")
      ->check(CLI::ExistingFile);
  cmd->add_option("--summary", o.convergence_summary,
                  "re-draw the section from this summary.json (written beside table.md from the results), without the results "
                  "(compare-runs convergence --summary FILE OUT_DIR)")
      ->check(CLI::ExistingFile);
  return cmd;
}

// Not study_mode(): with --from-json the one folder given is OUT_DIR (checked after parsing).
CLI::App* decisions_mode(CLI::App& app, Options& o) {
  CLI::App* cmd = app.add_subcommand("decisions",
                                     "every validation row on every reading's ensemble against the baseline's: table.md, decisions.json, "
                                     "tornado_<group>.dat, tornado_values.gp");
  cmd->add_option("RESULTS_DIR", o.decisions.results,
                  "the study's results folder (its runs.tsv, written by build/bin/pipeline); left out with --from-json");
  cmd->add_option("OUT_DIR", o.decisions.out, "where the tables and the figures' data go (made if missing)");
  CLI::Option* reference = cmd->add_option("--reference", o.baseline, "the baseline reading")->capture_default_str();
  cmd->add_option("--references", o.references, "the validation rows (the paper's values)")->capture_default_str();
  CLI::Option* ensemble =
      cmd->add_option("--ensemble", o.ensemble, "the paper study's results: verdicts and causes are judged on its full-size ensemble");
  CLI::Option* baseline_results =
      cmd->add_option("--baseline-results", o.baseline_results,
                      "for a study of readings only (no baseline of its own): the study whose samples of the same seeds are the "
                      "baseline (e.g. results/study/paper)");
  CLI::Option* from_json = cmd->add_option("--from-json", o.from_json,
                  "re-draw table.md, tornado_<group>.dat and tornado_values.gp from this decisions.json alone, without the study's "
                  "results (compare-runs decisions --from-json FILE OUT_DIR): shifts restated against the rows' resolutions")
      ->check(CLI::ExistingFile)
      ->excludes(reference)
      ->excludes(ensemble)
      ->excludes(baseline_results);
  cmd->add_option("--ensemble-json", o.ensemble_json,
                  "with --from-json (or --without-results redraw, when it re-draws): the paper study's validation.json "
                  "(reports/validation.json); the marks are then the verdicts of its full-size ensemble with each reading's shift of "
                  "the mean applied, as drawn from the results")
      ->check(CLI::ExistingFile);
  return cmd;
}

CLI::App* critical_mode(CLI::App& app, Options& o) {
  CLI::App* cmd = study_mode(app, "critical-state",
                             "peak and critical state of each constant-p shear, the peaks in the pi-plane: table.md, "
                             "critical_state.dat, pi_plane.dat, values.gp",
                             o.critical);
  cmd->add_option("--ensemble", o.critical_ensemble,
                  "an ensemble study's results (pipeline/studies/critical_state_ensemble.yaml): mean ± sd over its samples "
                  "of each loading and μ (ensemble.dat)");
  cmd->add_option("--rates", o.critical_rates,
                  "a rates study's results (pipeline/studies/critical_state_rates.yaml): critical q/p against sqrt(I) with "
                  "this study's runs of the same μ, taken to I -> 0 (rates.dat, rates_qs.dat)");
  cmd->add_option("--references", o.critical_references,
                  "validation rows (e.g. reference_data/literature.yaml): a critical_state_friction_angle row that reads a rate "
                  "series' run is compared with the series' quasi-static φ (with --rates)")
      ->check(CLI::ExistingFile);
  return cmd;
}

Modes declare_modes(CLI::App& app, Options& o) {
  Modes m{};
  m.convergence = convergence_mode(app, o);
  m.stability = study_mode(app, "stability", "what became of each case: table.md (exit 1 if a case is not acceptable)", o.stability);
  m.stability->add_flag("--report-only", o.report_only, "mark a case that is not acceptable in the table, and exit 0");
  m.decisions = decisions_mode(app, o);
  m.critical = critical_mode(app, o);
  m.liquefaction = app.add_subcommand("liquefaction",
                                      "CSR against N_L and r_u against cycles of the undrained cyclic tests of every folder: "
                                      "table.md, csr_nl.dat, ru.dat, values.gp");
  m.liquefaction->add_option("OUT_DIR", o.liquefaction_out, "where the tables and the figures' data go (made if missing)")->required();
  m.liquefaction->add_option("RESULTS_DIR", o.liquefaction_folders, "the studies' results folders")->required();
  for (CLI::App* mode : {m.convergence, m.stability, m.decisions, m.critical, m.liquefaction}) {
    mode->add_option("--draw", o.draw_dir, "draw the section's figures in OUT_DIR with the gnuplot scripts of this folder (reports/gnuplot)")
        ->check(CLI::ExistingDirectory);
    mode->add_option("--without-results", o.without_results,
                     "a study not run here (RESULTS_DIR without runs.tsv or a finished run) is no error: redraw = the section "
                     "re-drawn from OUT_DIR's committed summary (convergence, stability: summary.json; decisions: decisions.json), else "
                     "OUT_DIR kept; keep = OUT_DIR kept; says which, exit 0")
        ->check(CLI::IsMember({"keep", "redraw"}));
  }
  return m;
}

// decisions and convergence take RESULTS_DIR and OUT_DIR, or OUT_DIR alone (parsed into
// f.results) with a file to re-draw from (`alone`, given as `flag`); the error, or "".
std::string folders_error(const Folders& f, const std::string& alone, const std::string& flag, const std::string& mode) {
  const bool both = !f.out.empty(), none = f.results.empty();
  if (!alone.empty()) return both ? flag + " takes OUT_DIR alone (no RESULTS_DIR)" : none ? flag + " needs OUT_DIR" : "";
  return both ? "" : mode + " needs RESULTS_DIR and OUT_DIR (or " + flag + " FILE OUT_DIR)";
}

// OUT/stamp.json from the studies a section was made from (their engine, baseline, size, date:
// study/stamp.hpp), once its tables are written (`status` 0 or 1); the report says it under the
// section's heading.
int stamped(int status, const std::string& out, const std::vector<std::string>& studies,
            const std::vector<std::pair<std::string, std::string>>& parts = {}) {
  if (status != 0 && status != 1) return status;
  const auto stamp_of = [](const std::string& dir) -> std::optional<validation::Stamp> {
    try {
      return validation::stamp_of_results(dir);
    } catch (const std::exception& e) {  // a study not run: its section says so, and it has no stamp
      std::fprintf(stderr, "compare-runs: no stamp from %s: %s\n", dir.c_str(), e.what());
      return std::nullopt;
    }
  };
  std::vector<validation::Stamp> stamps;
  for (const std::string& dir : studies)
    if (!dir.empty())
      if (const auto s = stamp_of(dir)) stamps.push_back(*s);
  // Each part another study feeds, with its own stamp (the report says it under the part's heading).
  std::vector<std::pair<std::string, validation::Stamp>> part_stamps;
  for (const auto& [name, dir] : parts)
    if (!dir.empty())
      if (const auto s = stamp_of(dir)) part_stamps.emplace_back(name, *s);
  validation::write_stamp_file(out, validation::combined(stamps), part_stamps);
  return status;
}

// A study with nothing finished (planned, or started) draws no section: its committed tables stay.
int nothing_finished(const std::string& dir) {
  std::fprintf(stderr, "compare-runs: no finished run in %s (its runs.tsv lists runs, none has a result or a recorded stop: "
                       "a study planned or still running); nothing written\n", dir.c_str());
  return 1;
}

// 0 when the study in `dir` has a finished run; else the exit status: 1 (nothing finished), 2 (no
// manifest). `manifest` receives it.
int finished(const std::string& dir, sections::Manifest& manifest) {
  try {
    manifest = sections::read_manifest(dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return sections::any_outcome(manifest, dir) ? 0 : nothing_finished(dir);
}

// Whether `dir` holds results to draw from: a runs.tsv with a finished run (one that cannot be
// read counts as results, so that drawing from it reports why).
bool has_results(const std::string& dir) {
  if (!std::filesystem::exists(std::filesystem::path(dir) / "runs.tsv")) return false;
  try {
    return sections::any_outcome(sections::read_manifest(dir), dir);
  } catch (const std::exception&) {
    return true;
  }
}

// --without-results: where the results are not here, the committed summary the mode re-draws from
// (set into `o`), or 0 once it has said that OUT_DIR is kept; nothing when the mode runs as asked.
// A critical-state study's --ensemble or --rates, or a liquefaction folder, without results is
// left out, and said so.
std::optional<int> without_results(const std::string& mode, const Modes& m, Options& o) {
  const auto left_out = [&](std::string& dir, const char* what) {
    if (dir.empty() || has_results(dir)) return;
    std::fprintf(stderr, "compare-runs %s: no results in %s yet; %s left out\n", mode.c_str(), dir.c_str(), what);
    dir.clear();
  };
  std::string results, out;
  if (*m.liquefaction) {
    std::vector<std::string> run;
    for (std::string dir : o.liquefaction_folders) {
      left_out(dir, "that study");
      if (!dir.empty()) run.push_back(dir);
    }
    o.liquefaction_folders = run;
    if (!run.empty()) return std::nullopt;
    results = "any of its folders", out = o.liquefaction_out;
  } else {
    if (*m.critical) left_out(o.critical_ensemble, "its --ensemble"), left_out(o.critical_rates, "its --rates");
    Folders& f = *m.convergence ? o.convergence : *m.stability ? o.stability : *m.decisions ? o.decisions : o.critical;
    const bool redrawn_already = (*m.convergence && !o.convergence_summary.empty()) || (*m.decisions && !o.from_json.empty());
    if (redrawn_already || has_results(f.results)) return std::nullopt;
    results = f.results, out = f.out;
    const std::string summary = *m.convergence || *m.stability ? "summary.json" : *m.decisions ? "decisions.json" : "";
    const std::filesystem::path committed = std::filesystem::path(out) / summary;
    if (o.without_results == "redraw" && !summary.empty() && std::filesystem::is_regular_file(committed)) {
      std::fprintf(stderr, "compare-runs %s: no results in %s; the section re-drawn from the committed %s (its stamp kept)\n",
                   mode.c_str(), results.c_str(), committed.c_str());
      (*m.convergence ? o.convergence_summary : *m.stability ? o.stability_summary : o.from_json) = committed.string();
      f.results = out, f.out.clear();  // as `--summary FILE OUT_DIR` / `--from-json FILE OUT_DIR` take them
      return std::nullopt;
    }
  }
  std::fprintf(stderr, "compare-runs %s: no results in %s yet (its study has not run here); %s left as it is\n", mode.c_str(),
               results.c_str(), out.c_str());
  return 0;
}

// The mode given, run; a mode's status with its figures drawn when its data are written (0, or 1: a
// stability case not acceptable); a figure that cannot be drawn makes a 0 a 1.
int run_mode(const std::string& mode, const Modes& m, const Options& o) {
  const auto drawn = [&](int status, const std::string& out) {
    if (o.draw_dir.empty() || (status != 0 && status != 1)) return status;
    const int d = sections::draw_section(mode, out, o.draw_dir);
    return status == 0 ? d : status;
  };
  if (*m.convergence && !o.convergence_summary.empty()) {
    std::filesystem::create_directories(o.convergence.results);
    return drawn(sections::convergence_from_summary(o.convergence_summary, o.convergence.results, o.reference, o.validation_json),
                 o.convergence.results);
  }
  if (*m.liquefaction) {
    bool any = false;
    for (const std::string& dir : o.liquefaction_folders) any = any || sections::any_outcome(sections::read_manifest(dir), dir);
    if (!any) return nothing_finished(validation::joined(o.liquefaction_folders, ", "));
    return drawn(stamped(sections::liquefaction(o.liquefaction_out, o.liquefaction_folders), o.liquefaction_out, o.liquefaction_folders),
                 o.liquefaction_out);
  }
  if (*m.stability && !o.stability_summary.empty()) return sections::stability_from_summary(o.stability_summary, o.stability.results);
  if (*m.decisions && !o.from_json.empty())
    return drawn(sections::decisions_from_json(o.from_json, o.decisions.results, o.references, o.ensemble_json), o.decisions.results);
  const Folders& f = *m.convergence ? o.convergence : *m.stability ? o.stability : *m.decisions ? o.decisions : o.critical;
  sections::Manifest manifest;
  if (const int rc = finished(f.results, manifest)) return rc;
  std::filesystem::create_directories(f.out);
  if (*m.convergence) return drawn(sections::convergence(manifest, f.results, f.out, o.reference, o.threads_per_run, o.validation_json), f.out);
  if (*m.stability) return stamped(sections::stability(manifest, f.results, f.out, o.report_only), f.out, {f.results});
  if (*m.decisions) return drawn(sections::decisions(manifest, f.results, f.out, o.references, o.baseline, o.ensemble, o.baseline_results), f.out);
  for (const std::string& dir : {o.critical_ensemble, o.critical_rates}) {
    sections::Manifest other;
    if (!dir.empty())
      if (const int rc = finished(dir, other)) return rc;
  }
  return drawn(stamped(sections::critical_state(manifest, f.results, f.out, o.critical_ensemble, o.critical_rates, o.critical_references),
                       f.out, {f.results, o.critical_ensemble, o.critical_rates},
                       {{"ensemble", o.critical_ensemble}, {"rates", o.critical_rates}}),
               f.out);
}

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  CLI::App app{"compare-runs: the tables of a study of variants (convergence, stability, decisions, critical state, liquefaction), "
               "from the pipeline's manifest RESULTS_DIR/runs.tsv"};
  app.name("compare-runs");
  app.require_subcommand(1);
  Options o;
  const Modes m = declare_modes(app, o);

  if (argc < 2) {  // what there is
    std::fputs(app.help().c_str(), stderr);
    return 2;
  }
  const auto named = [&](const CLI::App* c) { return c->get_name() == argv[1]; };
  if (argv[1][0] != '-' && std::as_const(app).get_subcommands(named).empty()) {
    std::fprintf(stderr, "compare-runs: unknown mode '%s' (convergence, stability, decisions, critical-state or liquefaction)\n", argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
  }
  const std::string error = *m.decisions     ? folders_error(o.decisions, o.from_json, "--from-json", "decisions")
                            : *m.convergence ? folders_error(o.convergence, o.convergence_summary, "--summary", "convergence")
                                             : "";
  if (!error.empty()) {
    std::fprintf(stderr, "compare-runs: %s\nRun with --help for more information.\n", error.c_str());
    return 2;
  }
  // Without its results, the convergence section is re-drawn from the summary its results left.
  if (*m.convergence && o.convergence_summary.empty() && !std::filesystem::exists(std::filesystem::path(o.convergence.results) / "runs.tsv") &&
      std::filesystem::exists(std::filesystem::path(o.convergence.out) / "summary.json")) {
    o.convergence_summary = (std::filesystem::path(o.convergence.out) / "summary.json").string();
    std::fprintf(stderr, "compare-runs: no results in %s; the convergence section re-drawn from %s\n", o.convergence.results.c_str(),
                 o.convergence_summary.c_str());
    o.convergence.results = o.convergence.out;
  }
  if (!o.ensemble_json.empty() && o.from_json.empty() && o.without_results != "redraw") {
    std::fprintf(stderr, "compare-runs: --ensemble-json marks a table re-drawn from decisions.json: give it with --from-json or "
                         "--without-results redraw\n");
    return 2;
  }
  try {
    if (!o.without_results.empty())
      if (const std::optional<int> rc = without_results(argv[1], m, o)) return *rc;
    return run_mode(argv[1], m, o);
  } catch (const std::exception& e) {  // a result that cannot be read, a folder that cannot be made
    std::fprintf(stderr, "error: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
}

int main(int argc, char** argv) { return dem::guarded_main("compare-runs", [&] { return tool_main(argc, argv); }); }
