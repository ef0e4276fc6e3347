#pragma once
// The study report (reports/index.md, written by build/bin/report): static text from templates
// (reports/templates/), every number in it computed here from the results, the validation rows
// and reference_data/. A figure's note is a template sentence whose numbers come from the same
// data the figure plots, and whose "as in the paper" / "unlike the paper" comes from the verdict
// of the validation row about it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "figures/figures.hpp"
#include "figures/notes.hpp"
#include "study/format.hpp"
#include "judge/quantities.hpp"
#include "study/results.hpp"
#include "judge/rows.hpp"
#include "judge/validation_file.hpp"

namespace validation {

// `tmpl` with {{key}} replaced by values.at(key), {{key or "text"}} by the value or, when the key is
// absent or empty (a value that may be missing: a setting no scene gives), by text, and
// {{#if key}}A{{else}}B{{/if}} by A when the key is there and not empty, else B ({{else}} optional;
// blocks nest). An unknown {{key}} throws std::runtime_error naming it (a typo in a template is an
// error, not an empty gap).
std::string fill(const std::string& tmpl, const Values& values);

// A section's name: its heading without the "#"s, without an "Appendix: " prefix ("## Appendix:
// What was run" -> "What was run") and without a "⚠ from another baseline: " mark
// (other_sections.hpp).
std::string section_name(const std::string& heading_line);

// What the notes are computed from: the ensemble, the sample the single-run figures show, the
// rows the validation judges (their verdicts are computed here, on the same samples) and the
// paper's rows (for the paper's values).
using ReportInputs = NoteInputs;

// Every value the figure notes and the energy note use, keyed "figNN.name" (Figs. 2, 3, 4, 6, 7,
// 10, 11, 13 and "energy.*"); a figure whose data is missing has no keys, and its note says so.
// The constants the text quotes are keys too, always there: "paper.particles" (8,000),
// "cycles.shown" (5), "energy.parting_percent" (1) and "shift.clip" (10, format.hpp).
Values figure_values(const ReportInputs& in);

// The notes of the figures: `notes_tsv` is the template file (file<TAB>sentence); the note of
// `png` filled from `values`, or a sentence saying which data it lacks.
std::string figure_note(const std::string& notes_tsv, const std::string& png, const Values& values);

// The energy balance of runs (name, time series), each from its common row: work, change of
// stored energy, dissipation, the largest gap relative to the run's own work and the engine's
// closure error (relative to the stored energy at the start plus the work).
std::string energy_table(const std::vector<std::pair<std::string, const Columns*>>& runs);

// Every row now against an earlier baseline's validation.json: mean ± sd and verdict before and
// now (each row's result as judged, e.g. reports/validation.json's rows judged again: its verdict
// marked ⚠ when weak, verdict_mark, as everywhere a verdict is shown), and the shift of the mean in
// units of max(earlier sd, the row's resolution). Rendered when the report is written, from these
// typed values: no table text is kept.
std::string baseline_table(const nlohmann::json& before, const std::vector<RejudgedRow>& now);
// The same with each row judged now on `samples` (evaluate).
std::string baseline_table(const nlohmann::json& before, const std::vector<Row>& rows, const std::vector<Sample>& samples);

// q/p at state A (the start of shearing: the first row of the sample's first test) of every sample.
std::string state_a_table(const std::vector<Sample>& samples);
// How well the cell held its shear stresses at zero during each sample's tests: per density, the
// largest |engineering shear strain| the cell took and the largest |sigma_ij| / p, over every row
// of its tests ("—" where a column is missing, e.g. results written before the columns existed).
std::string shear_control_table(const std::vector<Sample>& samples);

}  // namespace validation
