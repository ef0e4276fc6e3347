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

namespace validation {

// `tmpl` with {{key}} replaced by values.at(key) and {{#if key}}A{{else}}B{{/if}} by A when the key
// is there and not empty, else B ({{else}} optional; blocks nest). An unknown {{key}} throws
// std::runtime_error naming it (a typo in a template is an error, not an empty gap).
std::string fill(const std::string& tmpl, const Values& values);

// What a template writes in a section whose inputs are not on this machine (the study's results,
// say): `report --previous FILE` then takes that section from FILE, an earlier report, instead.
inline constexpr const char* inputs_not_here = "<!-- inputs not here -->";

// What a template writes in place of one paragraph whose inputs are not here (a figure's note, the
// readings the runs used), in a section that is otherwise written from what is here: `report
// --previous` then takes that paragraph from the earlier report. "starting": the paragraph of the
// earlier report whose first line starts with `text`; "after": the paragraph that follows the
// line `text` (a figure's image line: its note).
std::string paragraph_not_here(const std::string& mode, const std::string& text);

// A section's name as keep_sections_without_inputs matches it: its heading without the "#"s,
// without an "Appendix: " prefix ("## Appendix: What was run" -> "What was run") and without a
// "⚠ from another baseline: " mark (other_sections.hpp), so that a section moved into the appendix,
// or headed as from another baseline, still finds itself in an earlier report.
std::string section_name(const std::string& heading_line);

// `fresh` (a report just written) with every level-2 section ("## heading" up to the next) that
// holds inputs_not_here replaced by the body of `previous`'s section of the same name
// (section_name), under `fresh`'s heading, if it has one; then every paragraph_not_here marker
// replaced by that paragraph of `previous` (a marker whose paragraph `previous` lacks is dropped).
// The names of the sections taken from `previous` are appended to `kept`, and, for each paragraph,
// "¶ " and its text (`starting`) or line (`after`). The text before the first heading is `fresh`'s.
std::string keep_sections_without_inputs(const std::string& fresh, const std::string& previous, std::vector<std::string>& kept);


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
// now, and the shift of the mean in units of max(earlier sd, the row's resolution).
std::string baseline_table(const nlohmann::json& before, const std::vector<Row>& rows, const std::vector<Sample>& samples);

// q/p at state A (the start of shearing: the first row of the sample's first test) of every sample.
std::string state_a_table(const std::vector<Sample>& samples);
// How well the cell held its shear stresses at zero during each sample's tests: per density, the
// largest |engineering shear strain| the cell took and the largest |sigma_ij| / p, over every row
// of its tests ("—" where a column is missing, e.g. results written before the columns existed).
std::string shear_control_table(const std::vector<Sample>& samples);

// Throws, naming `what` (the option and file), unless `previous` is a whole report of this
// template: text (no NUL byte, valid UTF-8: not an HDF5 or other binary file), the same title line
// as `fresh`, a "Generated on" line, and the last section of `fresh` present with the file ending
// in a newline (a report cut short is not taken).
void check_previous_report(const std::string& previous, const std::string& fresh, const std::string& what);

}  // namespace validation
