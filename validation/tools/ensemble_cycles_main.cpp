// ensemble-cycles: per-cycle statistics of an ensemble, the data of the paper's Figures 7, 10 and
// 11 drawn as a mean with a band (figure-data writes the same tables beside the figures).
//   ensemble-cycles RESULTS_DIR OUT_DIR
// For every density, test and quantity (eps_v in %, coordination number, sliding fraction in %),
// OUT_DIR/<quantity>_<density>_test<N>.dat has one line per cycle: cycle, mean over the samples,
// sample standard deviation, number of samples, min, max (validation/figures/figures.hpp,
// cycle_statistics). Cycle 0 is the first row of the test (the start of shearing); the sliding
// fraction starts at cycle 1, as the paper's Figure 11.
// Exit status: 0; 1 if a result file is there but cannot be read as a complete result, no test
// result was found, or a file cannot be written; 2 for bad arguments or a RESULTS_DIR that is not
// a folder.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "figures/figures.hpp"
#include "io/atomic_file.hpp"
#include "study/manifest.hpp"
#include "study/paths.hpp"
#include "study/results.hpp"
#include "io/failure.hpp"

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  namespace fs = std::filesystem;
  CLI::App app{"ensemble-cycles: per-cycle statistics of an ensemble (eps_v, coordination number, sliding fraction: mean, "
               "sd, samples, min, max per cycle), one file per density, test and quantity"};
  app.name("ensemble-cycles");
  std::string results, out;
  app.add_option("RESULTS_DIR", results, "the study's results folder (an ensemble: seed<N>/)")->required();
  app.add_option("OUT_DIR", out, "where <quantity>_<density>_test<N>.dat go (made if missing)")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
  }
  if (const std::string bad = validation::folder_problem(results); !bad.empty()) {
    std::fprintf(stderr, "ensemble-cycles: RESULTS_DIR '%s' %s (a study's results folder: seed<N>/ folders or one sample's results)\n",
                 results.c_str(), bad.c_str());
    return 2;
  }
  std::vector<std::string> missing;
  const std::vector<std::string> densities = validation::study_densities(results);
  const auto samples = validation::load_samples(results, densities, missing);
  if (validation::report_unreadable("ensemble-cycles", missing)) return 1;  // lost, not merely not run
  const std::string shown = validation::written_path(results);  // as written into the files
  fs::create_directories(out);
  int files = 0;
  try {
    for (const std::string& density : densities)
      for (int test = 1; test <= 5; ++test)
        for (const validation::CycleQuantity& q : validation::cycle_quantities()) {
          validation::Table t = validation::ensemble_cycle_table(samples, density, test, q);
          if (t.rows.empty()) continue;
          t.comments.insert(t.comments.begin(), q.name + ", " + density + ", test " + std::to_string(test) + ", over " +
                                                    std::to_string(samples.size()) + " samples of " + shown);
          dem::write_file_atomically((fs::path(out) / (q.name + "_" + density + "_test" + std::to_string(test) + ".dat")).string(),
                                     t.text());
          ++files;
        }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
  std::printf("ensemble-cycles: %zu samples, %d files, %zu result files missing -> %s\n", samples.size(), files, missing.size(),
              out.c_str());
  if (files == 0) {
    std::fprintf(stderr, "ensemble-cycles: no complete test result in %s (<density>_test<N>.h5): nothing written\n", results.c_str());
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) { return dem::guarded_main("ensemble-cycles", [&] { return tool_main(argc, argv); }); }
