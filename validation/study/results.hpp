#pragma once
// The study's results as the validation reads them: per density, the prepared sample's last row
// and each test's time series and legs.
#include <map>
#include <string>
#include <vector>

namespace validation {

using Columns = std::map<std::string, std::vector<double>>;

struct TestResult {
  int number = 0;    // N of a test named test<N> (the paper's tests 1..5), else 0
  Columns series;    // /timeseries
  Columns legs;      // /legs
  std::string name;  // the study's name of the test: test1, compression, ...
};

// How notes name a test: "3" for test3 (the paper's tests), else its name.
std::string test_label(const TestResult& t);
std::string test_label(const std::string& name);

struct DensityResults {
  bool prepared = false;
  std::map<std::string, double> sample;  // last time-series row of the preparation
  std::vector<TestResult> tests;
  // The runs the study lists for this density whose results are missing or not complete
  // ("prepare", "test1", ...), where the reader records them (compare-runs decisions): a row that
  // reads one of them has no value for this sample (decisions.hpp).
  std::vector<std::string> missing_runs;
};

// A column of a time series; throws std::out_of_range naming it when the result has none.
const std::vector<double>& column(const Columns& c, const std::string& name);

// The test numbered `number` (test<N>) of a density's results, or nullptr.
const TestResult* find_test(const DensityResults& r, int number);

// One group (timeseries or legs) of a result file, complete or not (.partial results of stopped
// runs too); throws if the file cannot be read.
Columns read_columns(const std::string& file, const std::string& group);
// True if the file is a complete result.
bool is_complete(const std::string& file);

// A density's results from its preparation's result and its tests' (test number -> result file,
// the tests named test<N>); files that are missing or not complete are left out and listed in `missing`.
DensityResults load_density(const std::string& preparation, const std::map<int, std::string>& tests,
                            std::vector<std::string>& missing);

// One complete result: the preparation's last time-series row (and `particles`, the sphere count)
// into `r.sample`, or a test's series and legs; throws if the file is missing or not complete.
void load_preparation(const std::string& file, DensityResults& r);
TestResult load_test(const std::string& file, const std::string& name);

// Reads DIR/<density>_prepare.h5 and DIR/<density>_test<N>.h5 (N = 1..5) for each density; files
// that are missing or not complete are left out and listed in `missing`.
std::map<std::string, DensityResults> load_results(const std::string& dir, const std::vector<std::string>& densities,
                                                   std::vector<std::string>& missing);

// One sample of an ensemble: a seed's results.
struct Sample {
  std::string name;  // seed1, seed2, ... ("" for a study of one sample)
  std::string dir;
  std::map<std::string, DensityResults> densities;
};

// The folders of an ensemble's samples: DIR/seed<N>/ in the order of N, or DIR itself when it has
// none (a study of one sample).
std::vector<std::pair<std::string, std::string>> sample_dirs(const std::string& dir);

// load_results of every sample folder.
std::vector<Sample> load_samples(const std::string& dir, const std::vector<std::string>& densities,
                                 std::vector<std::string>& missing);

// Why `dir` cannot be a results folder ("does not exist", "is not a folder", the system's reason
// when its status cannot be read, e.g. a symbolic link loop), or "" when it is a folder.
std::string folder_problem(const std::string& dir);

// Of the result files listed as missing or not complete, those that are there: a file that exists
// but cannot be read as a complete result (truncated, damaged, not HDF5, a link loop) was lost,
// not merely not run, and a tool that reads results fails on it instead of leaving it out.
std::vector<std::string> unreadable_results(const std::vector<std::string>& missing);

// Prints each unreadable result ("<tool>: <file>: cannot be read as a complete result (<why>)") to
// stderr; true if there was one.
bool report_unreadable(const std::string& tool, const std::vector<std::string>& missing);

}  // namespace validation
