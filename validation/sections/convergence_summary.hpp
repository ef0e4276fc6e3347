#pragma once
// The convergence study's committed summary (reports/convergence/summary.json): every run's
// settings, cost and headline quantities, stamped with the engine and baseline that made them, so
// that its section is re-drawn, and re-judged, without the results (a study of hours is not run
// again in every session).
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "sections/study_folder.hpp"

namespace validation {

// One sample of one setting at one density: its preparation and its test.
struct ConvergenceRun {
  std::string variant, density;
  int seed = 0;
  double time_step_s = 0, rate_Pa_s = 0;  // the test's time step and stress rate
  double preparation_time_step_s = 0;     // the preparation's time step (the test's may differ)
  long spheres = 0;
  double core_s = 0;                      // (preparation + test) wall time x threads per run
  double preparation_core_s = std::numeric_limits<double>::quiet_NaN();  // of it, the preparation's (NaN: not recorded, schema 1)
  std::map<std::string, double> quantities;
  std::string status;                     // empty: both runs complete; else why not
  std::string engine;                     // software_version of its results
};

struct ConvergenceSummary {
  int schema = 2;         // 2: runs record the preparation's time step (1: it was the test's)
  std::string results;    // the results folder it was read from, relative
  std::string engine;     // the runs' software versions, with their counts when several
  std::string engine_source;      // the engine source every result was checked to be made by (study/stamp.hpp; "": not checked)
  long other_engine_results = 0;  // results not by it from their manifest's inputs
  std::string baseline;   // baseline_of (study/baseline.hpp) the reference's first preparation
  long spheres = 0;       // the reference's spheres and samples (complete runs)
  long samples = 0;
  std::string date;       // when summarised (UTC, YYYY-MM-DD)
  int threads = 1;        // threads per run
  std::vector<ConvergenceRun> runs;
};

// From the pipeline's results (manifest.by_variant); threads: what each run used.
ConvergenceSummary summarise_convergence(const sections::Manifest& manifest, const std::string& results, int threads);

// `now` with the complete runs of `before` (an earlier summary, e.g. the committed one) that `now`
// lacks or has incomplete: a study whose settings ran in several sessions (results do not outlive
// one on a small machine) adds up. Each run keeps its engine; the stamp lists them.
ConvergenceSummary merge_summaries(ConvergenceSummary now, const ConvergenceSummary& before);

// JSON, numbers to 10 significant digits; read back exactly as written. read throws
// std::runtime_error naming the file and the key for a file that is not such a summary.
std::string summary_json(const ConvergenceSummary& s);
ConvergenceSummary read_convergence_summary(const std::string& file);

}  // namespace validation
