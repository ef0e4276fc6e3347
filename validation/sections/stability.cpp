// compare-runs stability: what became of each case of the stability study (SPEC's time step and
// stiffness cases), one row per run: OUT/table.md.
#include <cstdio>
#include <filesystem>

#include "sections/variants.hpp"
#include "sections/modes.hpp"
#include "sections/percent.hpp"
#include "io/atomic_file.hpp"
#include "study/markdown_table.hpp"

namespace fs = std::filesystem;

namespace compare_runs {

int stability(const Manifest& manifest, const std::string& results, const std::string& out, bool report_only) {
  validation::MarkdownTable table({"case", "settings", "outcome", "steps (last row written)", "energy closure error", "message"});
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
                 std::to_string(o.steps), o.closure ? percent(*o.closure) : "—", o.message});
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

}  // namespace compare_runs
