// ensemble-cycles: per-cycle statistics of an ensemble, the data of the paper's Figures 7, 10 and
// 11 drawn as a mean with a band (reports/make_figures.sh).
//   ensemble-cycles RESULTS_DIR OUT_DIR
// For every density, test and quantity (eps_v in %, coordination number, sliding fraction in %),
// OUT_DIR/<quantity>_<density>_test<N>.dat has one line per cycle: cycle, mean over the samples,
// sample standard deviation, number of samples, min, max. Cycle 0 is the first row of the test
// (the start of shearing); the sliding fraction starts at cycle 1, as the paper's Figure 11.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "ensemble.hpp"
#include "quantities.hpp"
#include "results.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc != 3) {
    std::fprintf(stderr, "usage: ensemble-cycles RESULTS_DIR OUT_DIR\n");
    return 2;
  }
  const std::string results = argv[1], out = argv[2];
  std::vector<std::string> missing;
  const auto samples = validation::load_samples(results, {"loose", "medium", "dense"}, missing);
  struct Quantity {
    const char* name;
    const char* column;
    double scale;
    bool from_start;
  };
  const Quantity quantities[] = {{"epsv_percent", "volumetric_strain", 100, true},
                                 {"coordination", "coordination_number", 1, true},
                                 {"sliding_percent", "sliding_fraction", 100, false}};
  fs::create_directories(out);
  int files = 0;
  try {
    for (const char* density : {"loose", "medium", "dense"})
      for (int test = 1; test <= 5; ++test)
        for (const Quantity& q : quantities) {
          std::map<int, std::vector<double>> by_cycle;
          for (const validation::Sample& s : samples) {
            const auto& tests = s.densities.at(density).tests;
            const auto t = std::find_if(tests.begin(), tests.end(), [&](const validation::TestResult& r) { return r.number == test; });
            if (t == tests.end() || !t->series.count(q.column) || t->series.at(q.column).empty()) continue;
            if (q.from_start) by_cycle[0].push_back(q.scale * t->series.at(q.column).front());
            const auto& cycle = t->series.at("cycle");
            const int last = cycle.empty() ? 0 : static_cast<int>(*std::max_element(cycle.begin(), cycle.end()));
            for (int c = 1; c <= last; ++c)
              if (const auto v = validation::at_cycle_end(*t, q.column, c)) by_cycle[c].push_back(q.scale * *v);
          }
          if (by_cycle.empty()) continue;
          std::ostringstream text;
          text << "# " << q.name << ", " << density << ", test " << test << ", over " << samples.size()
               << " samples of " << results << "\n# cycle\tmean\tsd\tn\tmin\tmax\n";
          text.precision(8);
          for (const auto& [c, values] : by_cycle) {
            const validation::Spread s = validation::spread(values);
            text << c << '\t' << s.mean << '\t' << s.sd << '\t' << s.n << '\t' << *std::min_element(values.begin(), values.end())
                 << '\t' << *std::max_element(values.begin(), values.end()) << '\n';
          }
          dem::write_file_atomically(
              (fs::path(out) / (std::string(q.name) + "_" + density + "_test" + std::to_string(test) + ".dat")).string(), text.str());
          ++files;
        }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("ensemble-cycles: %zu samples, %d files, %zu result files missing -> %s\n", samples.size(), files, missing.size(),
              out.c_str());
  return 0;
}
