// compare-runs stability: what became of each case of the stability study (the paper's time step and
// stiffness cases), one row per run: OUT/table.md.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "sections/variants.hpp"
#include "sections/modes.hpp"
#include "sections/percent.hpp"
#include "io/atomic_file.hpp"
#include "study/markdown_table.hpp"

namespace fs = std::filesystem;

namespace sections {

namespace {
// The largest value of a time-series column over the run, to 3 significant digits; "—" if the
// result has no such column or no row.
std::string largest(const validation::Columns& series, const std::string& column) {
  const auto it = series.find(column);
  if (it == series.end() || it->second.empty()) return "—";
  double m = it->second.front();
  for (const double x : it->second) m = std::max(m, x);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", m);
  return buf;
}
}  // namespace

int stability(const Manifest& manifest, const std::string& results, const std::string& out, bool report_only) {
  // The time step against the law's critical step as the engine checks it, and against the
  // leapfrog limit at the stiffest contact seen (for Hertz, whose stiffness grows with the overlap,
  // the limit at the largest overlap of the run; the same for the linear laws once in contact).
  validation::MarkdownTable table({"case", "settings", "outcome", "steps (last row written)", "dt / critical (engine)",
                                   "dt / critical at the stiffest contact seen", "energy closure error", "message"});
  int bad = 0;
  for (const std::string& v : manifest.variants) {
    for (const ManifestLine& l : manifest.by_variant.at(v)) {
      validation::CaseRun run;
      run.complete = validation::is_complete(l.result);
      const std::string file = run.complete ? l.result : l.result + ".partial";
      std::error_code ec;
      if (fs::exists(file, ec)) {
        try {
          run.series = validation::read_columns(file, "timeseries");
        } catch (const std::exception&) {
        }
      }
      if (!run.complete) read_stop(l.result, run);
      validation::CaseOutcome o = validation::classify_case(run);
      // The engine names the resolved scene first; the case column already says which it is.
      if (const auto at = o.message.find(".yaml: "); at != std::string::npos && o.message.rfind('/', at) != std::string::npos)
        o.message = o.message.substr(at + 7);
      bad += !o.acceptable;
      table.row({l.test == "-" ? v : v + " " + l.test, relative_paths(l.settings, results), (o.acceptable ? "" : "⚠ ") + o.outcome,
                 std::to_string(o.steps), largest(run.series, "time_step_over_critical"),
                 largest(run.series, "time_step_over_contact_critical"), o.closure ? percent(*o.closure) : "—", o.message});
    }
  }
  const fs::path md = fs::path(out) / "table.md";
  try {
    dem::write_file_atomically(md.string(), table.text());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("stability: %zu cases, %d not acceptable -> %s\n", manifest.variants.size(), bad, md.c_str());
  return bad > 0 && !report_only ? 1 : 0;
}

}  // namespace sections
