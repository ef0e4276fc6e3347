// compare-runs stability: what became of each case of the stability study (the paper's time step and
// stiffness cases), one row per run: OUT/summary.json (stability_summary.hpp) and OUT/table.md; or
// the table re-drawn from a committed summary.json, without the results.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "sections/variants.hpp"
#include "sections/modes.hpp"
#include "sections/stability_summary.hpp"
#include "io/atomic_file.hpp"

namespace fs = std::filesystem;

namespace sections {

namespace {
// The largest value of a time-series column over the run; none if the result has no such column or no row.
std::optional<double> largest(const validation::Columns& series, const std::string& column) {
  const auto it = series.find(column);
  if (it == series.end() || it->second.empty()) return std::nullopt;
  return *std::max_element(it->second.begin(), it->second.end());
}
}  // namespace

int stability(const Manifest& manifest, const std::string& results, const std::string& out, bool report_only) {
  std::vector<StabilityCase> cases;
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
      cases.push_back({l.test == "-" ? v : v + " " + l.test, relative_paths(l.settings, results), o.acceptable, o.outcome,
                       static_cast<long>(o.steps), largest(run.series, "time_step_over_critical"),
                       largest(run.series, "time_step_over_contact_critical"), o.closure, o.message});
    }
  }
  const fs::path md = fs::path(out) / "table.md";
  try {
    dem::write_file_atomically((fs::path(out) / "summary.json").string(), stability_summary_json(cases));
    dem::write_file_atomically(md.string(), stability_table(cases));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("stability: %zu cases, %d not acceptable -> %s\n", manifest.variants.size(), bad, md.c_str());
  return bad > 0 && !report_only ? 1 : 0;
}

int stability_from_summary(const std::string& file, const std::string& out) {
  std::vector<StabilityCase> cases;
  try {
    cases = read_stability_summary(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  const fs::path md = fs::path(out) / "table.md";
  try {
    dem::write_file_atomically(md.string(), stability_table(cases));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  const long bad = std::count_if(cases.begin(), cases.end(), [](const StabilityCase& c) { return !c.acceptable; });
  std::printf("stability: re-drawn from %s: %zu cases, %ld not acceptable -> %s\n", file.c_str(), cases.size(), bad, md.c_str());
  return 0;
}

}  // namespace sections
