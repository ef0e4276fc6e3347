#pragma once
// The report's keys that do not come from the figures' data (report.hpp: figure_values): the
// header and provenance, the runs of every sample, the settings the runs used, the tables other
// tools wrote under the report's folder, the sizes of the decisions and readings studies, the
// convergence and stability studies' settings, the earlier baseline and the figures' list. Each
// function adds its keys to `v`; `report` (tools/report_main.cpp) calls them in this order and
// fills reports/templates/index.md with the result.
#include <filesystem>
#include <string>
#include <vector>

#include "report/baseline_check.hpp"
#include "report/report.hpp"

namespace validation {

// A file's text, "" if it cannot be read.
std::string read_text(const std::filesystem::path& p);

// The options of `report` that name its inputs (empty: not given).
struct ReportSources {
  std::string results, out, templates, baseline, decisions, stability, source, note;
};

// date, results, note, source, tool_version, have_results, missing_results.
void add_provenance(Values& v, const ReportSources& src, bool have_results, std::size_t missing);

// runs_table, total_wall_s and engines (the software versions that wrote the results); returns
// the time series of the chosen sample's runs (`v["sample"]`), named <density>_prepare and
// <density>_test<N>, for the energy table.
std::vector<std::pair<std::string, Columns>> add_runs(Values& v, const std::vector<Sample>& samples,
                                                      const std::vector<std::string>& densities);

// setting.* from the resolved scenes of the study in `results` (run_settings); a setting no scene
// gives is no key at all (the template says "not recorded" there: {{key or "..."}}).
void add_settings(Values& v, const std::string& results, bool have_results);

// file.*: the tables other tools wrote under `report`; decisions.size and file.readings (the
// readings studies' tables, each headed with its recorded size).
void add_tables(Values& v, const std::filesystem::path& report, const std::vector<Row>& paper, const std::string& decisions_results);

// The verdicts the figure notes quote (note_verdicts, figures/notes.hpp), from `judged` (the rows
// of validation.json judged again: read_paper_ensemble), so that a note says what the verdict
// table says, ⚠ on a weak one; and fig10.counted_dense (what the dense coordination row counts).
void add_note_verdicts(Values& v, const PaperEnsemble& judged);

// setup.table (the study in one small table: its samples, spheres, preparation, tests and the rows
// judged, from reports/validation.json and the setting.* keys of `v`, said to come from
// `settings_from`; with `settings_from` "", from reports/figures/values.gp, which figure-data wrote
// from the results) and setup.from (where from).
void add_setup(Values& v, const std::filesystem::path& report, const std::string& settings_from);

// stability.* and validation.prediction_percent from the stability study's results (the
// convergence section's table carries its own settings and stamp).
void add_study_settings(Values& v, const std::string& stability_results);

// baseline.*, state_a.table and shear_control.table (the earlier baseline given by --baseline).
void add_baseline(Values& v, const std::string& baseline_file, const std::vector<Row>& rows, const std::vector<Sample>& samples);

// Every key above that the paper study's results give, in one map (what study_values.json keeps):
// figure_values(in), add_runs, add_settings, add_baseline (with `baseline_file`, "" for none) and
// energy.table (the energy balance of the chosen sample's runs).
Values values_from_results(const ReportInputs& in, const std::string& results, const std::string& baseline_file,
                           const std::vector<std::string>& densities);

// file.figures_readme, figures (every figure with its note, computed from `v`: a note whose data
// is not in `v` says what it lacks), headline_figures (Figs. 0, 13 and 14, not in figures),
// figure.fig00, renders, energy.figure, energy.note: the figures under `report`/figures with the
// notes of `notes_tsv`.
void add_figures(Values& v, const std::filesystem::path& report, const std::string& notes_tsv);

}  // namespace validation
