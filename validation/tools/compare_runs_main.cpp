// compare-runs: the tables of a study of variants, from the pipeline's manifest (DIR/runs.tsv).
//   compare-runs convergence RESULTS_DIR OUT_DIR [--reference NAME] [--threads N] [--validation FILE]
//   compare-runs convergence --summary SUMMARY_JSON OUT_DIR [--reference NAME] [--validation FILE]
//   compare-runs stability RESULTS_DIR OUT_DIR [--report-only]
//   compare-runs decisions RESULTS_DIR OUT_DIR [--reference NAME] [--references FILE] [--ensemble PAPER_RESULTS]
//                          [--baseline-results DIR]
//   compare-runs decisions --from-json DECISIONS_JSON OUT_DIR [--references FILE]
//   compare-runs critical-state RESULTS_DIR OUT_DIR [--ensemble DIR] [--rates DIR]
//   compare-runs liquefaction OUT_DIR RESULTS_DIR...
// Every mode takes --draw GNUPLOT_DIR (reports/gnuplot): its section's figures drawn in OUT_DIR
// once its data are written (sections/draw.hpp declares them). convergence without results
// (RESULTS_DIR has no runs.tsv) but with OUT_DIR/summary.json re-draws from that summary, and says so.
// Each mode is a file of compare_runs/ (what it writes: modes.hpp); this one parses the arguments
// (every sub-command answers --help) and calls it. stability, critical-state and liquefaction also
// write OUT_DIR/stamp.json, decisions a "stamp" in decisions.json (study/stamp.hpp).
// Exit status: 0; 1 if a stability case is not acceptable, the reference or baseline is missing,
// or an output cannot be written; 2 on bad arguments (the error names the option) or an unreadable
// manifest or references file.
#include <cstdio>
#include <filesystem>
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

CLI::App* study_mode(CLI::App& app, const std::string& name, const std::string& what, Folders& f) {
  CLI::App* cmd = app.add_subcommand(name, what);
  cmd->add_option("RESULTS_DIR", f.results, "the study's results folder (its runs.tsv, written by build/bin/pipeline)")->required();
  cmd->add_option("OUT_DIR", f.out, "where the tables and the figures' data go (made if missing)")->required();
  return cmd;
}

// OUT/stamp.json from the studies a section was made from (their engine, baseline, size, date:
// study/stamp.hpp), once its tables are written (`status` 0 or 1); the report says it under the
// section's heading.
int stamped(int status, const std::string& out, const std::vector<std::string>& studies) {
  if (status != 0 && status != 1) return status;
  std::vector<validation::Stamp> stamps;
  for (const std::string& dir : studies) {
    if (dir.empty()) continue;
    try {
      stamps.push_back(validation::stamp_of_results(dir));
    } catch (const std::exception& e) {  // a study not run: its section says so, and it has no stamp
      std::fprintf(stderr, "compare-runs: no stamp from %s: %s\n", dir.c_str(), e.what());
    }
  }
  validation::write_stamp_file(out, validation::combined(stamps));
  return status;
}

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  CLI::App app{"compare-runs: the tables of a study of variants (convergence, stability, decisions, critical state, liquefaction), "
               "from the pipeline's manifest RESULTS_DIR/runs.tsv"};
  app.name("compare-runs");
  app.require_subcommand(1);

  Folders convergence_f, stability_f, decisions_f, critical_f;
  std::string reference = "reference", baseline = "baseline", references = "reference_data/paper.yaml", ensemble, baseline_results;
  bool report_only = false;
  // Not study_mode(): with --summary the one folder given is OUT_DIR (checked after parsing).
  std::string convergence_summary, validation_json;
  int threads_per_run = 1;
  CLI::App* convergence = app.add_subcommand(
      "convergence", "the error budget of the reference's settings in time step, rate and size, every setting's error against the "
                     "converged values with its cost: summary.json (from results), table.md, errors.dat, front.dat");
  convergence->add_option("RESULTS_DIR", convergence_f.results,
                          "the study's results folder (its runs.tsv, written by build/bin/pipeline); left out with --summary");
  convergence->add_option("OUT_DIR", convergence_f.out, "where the tables and the figure's data go (made if missing)");
  convergence->add_option("--reference", reference, "the variant at the paper's settings")->capture_default_str();
  convergence->add_option("--threads", threads_per_run, "threads each run used (core-seconds = wall time x threads)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  convergence->add_option("--validation", validation_json,
                          "the paper study's validation.json: each inconsistent row's miss against the budget")
      ->check(CLI::ExistingFile);
  convergence
      ->add_option("--summary", convergence_summary,
                   "re-draw the section from this summary.json (written beside table.md from the results), without the results "
                   "(compare-runs convergence --summary FILE OUT_DIR)")
      ->check(CLI::ExistingFile);

  CLI::App* stability = study_mode(app, "stability", "what became of each case: table.md (exit 1 if a case is not acceptable)", stability_f);
  stability->add_flag("--report-only", report_only, "mark a case that is not acceptable in the table, and exit 0");

  // Not study_mode(): with --from-json the one folder given is OUT_DIR (checked after parsing).
  std::string from_json;
  CLI::App* decisions = app.add_subcommand("decisions",
                                           "every validation row on every reading's ensemble against the baseline's: table.md, decisions.json, "
                                           "tornado_<group>.dat, tornado_values.gp");
  decisions->add_option("RESULTS_DIR", decisions_f.results,
                        "the study's results folder (its runs.tsv, written by build/bin/pipeline); left out with --from-json");
  decisions->add_option("OUT_DIR", decisions_f.out, "where the tables and the figures' data go (made if missing)");
  CLI::Option* reference_opt = decisions->add_option("--reference", baseline, "the baseline reading")->capture_default_str();
  decisions->add_option("--references", references, "the validation rows (the paper's values)")->capture_default_str();
  CLI::Option* ensemble_opt =
      decisions->add_option("--ensemble", ensemble, "the paper study's results: verdicts and causes are judged on its full-size ensemble");
  CLI::Option* baseline_results_opt =
      decisions->add_option("--baseline-results", baseline_results,
                            "for a study of readings only (no baseline of its own): the study whose samples of the same seeds are the "
                            "baseline (e.g. results/study/paper)");
  decisions
      ->add_option("--from-json", from_json,
                   "re-draw table.md, tornado_<group>.dat and tornado_values.gp from this decisions.json alone, without the study's "
                   "results (compare-runs decisions --from-json FILE OUT_DIR): shifts restated against the rows' resolutions")
      ->check(CLI::ExistingFile)
      ->excludes(reference_opt)
      ->excludes(ensemble_opt)
      ->excludes(baseline_results_opt);

  CLI::App* critical = study_mode(app, "critical-state",
                                  "peak and critical state of each constant-p shear, the peaks in the pi-plane: table.md, "
                                  "critical_state.dat, pi_plane.dat, values.gp",
                                  critical_f);
  std::string critical_ensemble, critical_rates, critical_references;
  critical->add_option("--ensemble", critical_ensemble,
                       "an ensemble study's results (pipeline/studies/critical_state_ensemble.yaml): mean ± sd over its samples "
                       "of each loading and μ (ensemble.dat)");
  critical->add_option("--rates", critical_rates,
                       "a rates study's results (pipeline/studies/critical_state_rates.yaml): critical q/p against sqrt(I) with "
                       "this study's runs of the same μ, taken to I -> 0 (rates.dat, rates_qs.dat)");
  critical
      ->add_option("--references", critical_references,
                   "validation rows (e.g. reference_data/literature.yaml): a critical_state_friction_angle row that reads a rate "
                   "series' run is compared with the series' quasi-static φ (with --rates)")
      ->check(CLI::ExistingFile);

  std::string liquefaction_out;
  std::vector<std::string> liquefaction_folders;
  CLI::App* liquefaction = app.add_subcommand("liquefaction",
                                              "CSR against N_L and r_u against cycles of the undrained cyclic tests of every folder: "
                                              "table.md, csr_nl.dat, ru.dat, values.gp");
  liquefaction->add_option("OUT_DIR", liquefaction_out, "where the tables and the figures' data go (made if missing)")->required();
  liquefaction->add_option("RESULTS_DIR", liquefaction_folders, "the studies' results folders")->required();

  std::string draw_dir;
  for (CLI::App* mode : {convergence, stability, decisions, critical, liquefaction})
    mode->add_option("--draw", draw_dir, "draw the section's figures in OUT_DIR with the gnuplot scripts of this folder (reports/gnuplot)")
        ->check(CLI::ExistingDirectory);

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
  // decisions: RESULTS_DIR and OUT_DIR, or OUT_DIR alone with --from-json (then in `results`).
  if (*decisions) {
    const bool both = !decisions_f.out.empty(), none = decisions_f.results.empty();
    const char* error = !from_json.empty() ? (both ? "--from-json takes OUT_DIR alone (no RESULTS_DIR)" : none ? "--from-json needs OUT_DIR" : nullptr)
                                           : (!both ? "decisions needs RESULTS_DIR and OUT_DIR (or --from-json FILE OUT_DIR)" : nullptr);
    if (error) {
      std::fprintf(stderr, "compare-runs: %s\nRun with --help for more information.\n", error);
      return 2;
    }
  }
  if (*convergence) {
    const bool both = !convergence_f.out.empty(), none = convergence_f.results.empty();
    const char* error = !convergence_summary.empty() ? (both ? "--summary takes OUT_DIR alone (no RESULTS_DIR)" : none ? "--summary needs OUT_DIR" : nullptr)
                                                     : (!both ? "convergence needs RESULTS_DIR and OUT_DIR (or --summary FILE OUT_DIR)" : nullptr);
    if (error) {
      std::fprintf(stderr, "compare-runs: %s\nRun with --help for more information.\n", error);
      return 2;
    }
  }
  // Without its results, the convergence section is re-drawn from the summary its results left.
  if (*convergence && convergence_summary.empty() && !std::filesystem::exists(std::filesystem::path(convergence_f.results) / "runs.tsv") &&
      std::filesystem::exists(std::filesystem::path(convergence_f.out) / "summary.json")) {
    convergence_summary = (std::filesystem::path(convergence_f.out) / "summary.json").string();
    std::fprintf(stderr, "compare-runs: no results in %s; the convergence section re-drawn from %s\n", convergence_f.results.c_str(),
                 convergence_summary.c_str());
    convergence_f.results = convergence_f.out;
  }
  // A mode's status, its figures drawn when its data are written (0, or 1: a stability case not
  // acceptable); a figure that cannot be drawn makes a 0 a 1.
  const std::string mode = argv[1];
  const auto drawn = [&](int status, const std::string& out) {
    if (draw_dir.empty() || (status != 0 && status != 1)) return status;
    const int d = compare_runs::draw_section(mode, out, draw_dir);
    return status == 0 ? d : status;
  };
  try {
    if (*convergence && !convergence_summary.empty()) {
      std::filesystem::create_directories(convergence_f.results);
      return drawn(compare_runs::convergence_from_summary(convergence_summary, convergence_f.results, reference, validation_json),
                   convergence_f.results);
    }
    // A study with nothing finished (planned, or started) draws no section: its committed tables stay.
    const auto nothing_finished = [](const std::string& dir) {
      std::fprintf(stderr, "compare-runs: no finished run in %s (its runs.tsv lists runs, none has a result or a recorded stop: "
                           "a study planned or still running); nothing written\n", dir.c_str());
      return 1;
    };
    if (*liquefaction) {
      bool any = false;
      for (const std::string& dir : liquefaction_folders) any = any || compare_runs::any_outcome(compare_runs::read_manifest(dir), dir);
      if (!any) return nothing_finished(validation::joined(liquefaction_folders, ", "));
      return drawn(stamped(compare_runs::liquefaction(liquefaction_out, liquefaction_folders), liquefaction_out, liquefaction_folders),
                   liquefaction_out);
    }
    if (*decisions && !from_json.empty())
      return drawn(compare_runs::decisions_from_json(from_json, decisions_f.results, references), decisions_f.results);
    const Folders& f = *convergence ? convergence_f : *stability ? stability_f : *decisions ? decisions_f : critical_f;
    compare_runs::Manifest manifest;
    try {
      manifest = compare_runs::read_manifest(f.results);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
    if (!compare_runs::any_outcome(manifest, f.results)) return nothing_finished(f.results);
    std::filesystem::create_directories(f.out);
    if (*convergence) return drawn(compare_runs::convergence(manifest, f.results, f.out, reference, threads_per_run, validation_json), f.out);
    if (*stability) return stamped(compare_runs::stability(manifest, f.results, f.out, report_only), f.out, {f.results});
    if (*decisions) return drawn(compare_runs::decisions(manifest, f.results, f.out, references, baseline, ensemble, baseline_results), f.out);
    if (*critical) {
      for (const std::string& dir : {critical_ensemble, critical_rates})
        if (!dir.empty()) {
          try {
            if (!compare_runs::any_outcome(compare_runs::read_manifest(dir), dir)) return nothing_finished(dir);
          } catch (const std::exception& e) {
            std::fprintf(stderr, "error: %s\n", e.what());
            return 2;
          }
        }
      return drawn(stamped(compare_runs::critical_state(manifest, f.results, f.out, critical_ensemble, critical_rates, critical_references),
                           f.out, {f.results, critical_ensemble, critical_rates}),
                   f.out);
    }
    return 2;  // not reached: parse() requires one sub-command
  } catch (const std::exception& e) {  // a result that cannot be read, a folder that cannot be made
    std::fprintf(stderr, "error: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
}

int main(int argc, char** argv) { return dem::guarded_main("compare-runs", [&] { return tool_main(argc, argv); }); }
