#pragma once
// The modes of compare-runs, one file each (sections/<mode>.cpp); tools/compare_runs_main.cpp parses the
// arguments and calls one. Each returns the process's exit status: 0; 1 when the mode's judgement
// fails (a stability case not acceptable, the reference or baseline missing) or its output cannot
// be written; 2 on bad input (an unreadable manifest or references file).
#include <string>
#include <vector>

#include "sections/study_folder.hpp"

namespace sections {

// The error budget of `reference`'s settings (sections/convergence.cpp): OUT/summary.json (every
// run's settings, cost and quantities, stamped; threads: per run; an OUT/summary.json already there
// keeps the complete runs these results lack), table.md, errors.dat, front.dat.
// validation_json (optional): the paper study's, its inconsistent rows read against the budget.
int convergence(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& reference,
                int threads, const std::string& validation_json);
// The same from a committed summary.json, without the results (summary.json is not rewritten).
int convergence_from_summary(const std::string& file, const std::string& out, const std::string& reference,
                             const std::string& validation_json);

// What became of each case: OUT/summary.json and OUT/table.md. Exit 1 if a case is not acceptable,
// unless report_only.
int stability(const Manifest& manifest, const std::string& results, const std::string& out, bool report_only);
// The table re-drawn from a committed summary.json (FILE), without the results (summary.json is not
// rewritten): exit 0, 2 on a summary that cannot be read, 1 on a table that cannot be written.
int stability_from_summary(const std::string& file, const std::string& out);

// Every validation row of `references` on every reading's ensemble against the baseline reading's:
// OUT/table.md, decisions.json, tornado_<group>.dat and tornado_values.gp. `results`: the folder
// of `manifest`. `ensemble` (optional): the paper study's results, on which the verdicts and
// causes are judged. `baseline_results` (optional): a study of readings only (no baseline of its
// own, e.g. pipeline/studies/readings_loose.yaml) takes its baseline from that study's results,
// the samples of the seeds it has itself. Only the rows of the densities the readings run are
// judged; a reading lacking a run a row reads is not judged on it. decisions.json records the size
// (`particles`, from the baseline's preparations, and `samples`).
int decisions(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& references,
              const std::string& baseline, const std::string& ensemble, const std::string& baseline_results = "");

// The decisions study's section re-drawn from its decisions.json alone (FILE; its results not at
// hand): OUT/table.md, tornado_<group>.dat and tornado_values.gp in decisions()'s formats. Each
// shift is restated from the recorded means as (mean - baseline mean) / max(baseline sd, the row's
// resolution in `references`); the explanations as the file has them (read_decisions_file reads
// schema 2 only). With `ensemble_json` (the paper study's
// validation.json), the marks are the verdicts of its full-size ensemble, each reading's shift of
// the mean applied to its samples, as decisions() draws them from the results; without it, the
// verdicts the file records (of the study's own samples), and the first paragraph says so. The
// first paragraph says where the table comes from, its size (size_label) and what it cannot
// re-draw (the readings' settings). Exit 2 on a file or references that cannot be read, 1 on an
// output that cannot be written.
int decisions_from_json(const std::string& file, const std::string& out, const std::string& references,
                        const std::string& ensemble_json = "");

// Peak and critical state of each constant-p shear and the peaks in the pi-plane: OUT/table.md,
// critical_state.dat, pi_plane.dat and values.gp. `ensemble` (optional): an ensemble study's
// results (pipeline/studies/critical_state_ensemble.yaml), the mean and sd over its samples of each
// loading and μ (ensemble.dat). `rates` (optional): a rates study's results
// (pipeline/studies/critical_state_rates.yaml), the critical q/p of compression against sqrt(I)
// with the main study's runs of the same μ, fitted and taken to I -> 0 (rates.dat, rates_qs.dat).
// ensemble.dat, rates.dat and rates_qs.dat are written either way (no rows without the option).
// `references` (optional, with `rates`): validation rows (reference_data/literature.yaml); a row of
// critical_state_friction_angle that reads a rate series' run (its density_test is the run's name) is
// set beside that series' quasi-static φ, since the row's own verdict is at the study's rate.
int critical_state(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& ensemble = "",
                   const std::string& rates = "", const std::string& references = "");

// CSR against N_L and r_u against cycles of the undrained cyclic tests of every folder, the holds
// beside them: OUT/table.md, csr_nl.dat, ru.dat and values.gp.
int liquefaction(const std::string& out, const std::vector<std::string>& folders);

}  // namespace sections
