#pragma once
// What a figure's note in the report is computed from (figure_entry.hpp: each figure's `notes`):
// the ensemble, the sample the single-run figures show, the paper's values and the verdicts of the
// validation rows about the figure, each row judged once on the ensemble. The note's sentence is a
// template (reports/templates/figure_notes.tsv) filled from these values (report/report.hpp).
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "judge/rows.hpp"
#include "study/results.hpp"
#include "study/series.hpp"

namespace validation {

using Values = std::map<std::string, std::string>;

// The cycles the paper's figures show (Figs. 5-12): what the notes say of "the last cycle" stops there.
constexpr int paper_cycles = 5;
// The energy curves "part" where work and dissipated + change of stored differ by more than this
// fraction of the work done by then.
constexpr double energy_parting_fraction = 0.01;

// Numbers as the notes write them (and significant(), format.hpp).
// "lo–hi" to two significant digits of the larger magnitude, or one value if they print alike.
std::string range_text(double lo, double hi);
// "lo–hi" with `decimals`, one value if both print alike.
std::string range_fixed(double lo, double hi, int decimals);
// "as in the paper", "unlike the paper", or "not judged" (the row's verdict; no row: "not judged").
std::string verdict_phrase(Verdict v);
// The same of a judged row, with " ⚠" after it when its verdict is weak (it carries a warning:
// judge/weak_verdicts.hpp), as the verdict table marks it.
std::string verdict_phrase(const RowResult& r);

// Every verdict a figure note quotes, declared once: its key and the row it is the verdict of. The
// figures' notes fill them from the rows judged on the results (NoteContext::phrase); the report
// fills them again from validation.json, so that a note says what the verdict table says.
struct NoteVerdict {
  std::string key, quantity, density;
};
const std::vector<NoteVerdict>& note_verdicts();

// The smallest and largest of the values added.
struct MinMax {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double x) { lo = std::min(lo, x), hi = std::max(hi, x); }
  bool any() const { return lo <= hi; }
};

// A per-cycle statistics table's row of cycle c (cycle_statistics: cycle, mean, sd, n, min, max).
const std::vector<double>* cycle_row(const Table& t, int c);

// What the report's notes read: the inputs below, the chosen sample's results, the paper's values
// and the rows' verdicts (each row judged once).
struct NoteInputs {
  std::vector<Sample> samples;
  std::string sample;      // name of the sample of the single-run figures ("" : the first)
  std::vector<Row> rows;   // the rows judged (the profile's)
  std::vector<Row> paper;  // every row of reference_data/paper.yaml (the paper's values)
};

class NoteContext {
 public:
  NoteContext(const NoteInputs& inputs, const Sample& sample) : in(inputs), chosen(sample) {}
  const NoteInputs& in;
  const Sample& chosen;

  // The chosen sample's results of density `d`, or nullptr.
  const DensityResults* results_of(const std::string& d) const;
  // The verdict of the validation row about (quantity, density), judged on the ensemble.
  const RowResult* row_result(const std::string& quantity, const std::string& density);
  // Its phrase, or that the profile does not judge it.
  std::string phrase(const std::string& quantity, const std::string& density);
  // A row's values on these samples even when the profile does not judge it (the quick profile
  // leaves out rows that need the full size): the data are shown, the verdict is not.
  const RowResult* values_of(const std::string& quantity, const std::string& density);
  // The paper's value, "—" if it has none.
  std::string paper(const std::string& quantity, const std::string& density) const;

 private:
  const RowResult* judged(std::map<std::string, RowResult>& cache, const Row& r);
  std::map<std::string, RowResult> judged_, valued_;
};

}  // namespace validation
