#include "study/results.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/hdf5.hpp"
#include "io/result_file.hpp"

namespace validation {

namespace {

// Whether `f` is a complete result (io/result_file.hpp: the engine's one check).
bool complete(const dem::h5::Handle& f) { return dem::result_problem(f).empty(); }

}  // namespace

Columns read_columns(const std::string& file, const std::string& group) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  return dem::read_table(f, group, file);
}

bool is_complete(const std::string& file) {
  try {
    return complete(dem::h5::open_file_read(file));
  } catch (const std::exception&) {
    return false;
  }
}

std::string test_label(const std::string& name) {
  const bool numbered = name.size() > 4 && name.compare(0, 4, "test") == 0 &&
                        name.find_first_not_of("0123456789", 4) == std::string::npos;
  return numbered ? name.substr(4) : name;
}

std::string test_label(const TestResult& t) { return t.name.empty() ? std::to_string(t.number) : test_label(t.name); }

void load_preparation(const std::string& file, DensityResults& r) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  dem::check_complete_result(f, file);
  for (const auto& [name, values] : dem::read_table(f, "timeseries", file))
    if (!values.empty()) r.sample[name] = values.back();
  // The number of spheres, from the particle frames (frames x particles x 3).
  if (dem::h5::exists(f, "particles/all/position/value")) {
    const std::vector<hsize_t> shape = dem::h5::shape(f, "particles/all/position/value");
    if (shape.size() == 3) r.sample["particles"] = static_cast<double>(shape[1]);
  }
  r.prepared = true;
}

TestResult load_test(const std::string& file, const std::string& name) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  dem::check_complete_result(f, file);
  const std::string label = test_label(name);
  const int number = label != name ? std::atoi(label.c_str()) : 0;
  return {number, dem::read_table(f, "timeseries", file), dem::read_table(f, "legs", file), name};
}

DensityResults load_density(const std::string& preparation, const std::map<int, std::string>& tests,
                            std::vector<std::string>& missing) {
  DensityResults r;
  try {
    load_preparation(preparation, r);
  } catch (const std::exception&) {
    missing.push_back(preparation);
  }
  for (const auto& [n, file] : tests) {
    try {
      r.tests.push_back(load_test(file, "test" + std::to_string(n)));
    } catch (const std::exception&) {
      missing.push_back(file);
    }
  }
  return r;
}

std::map<std::string, DensityResults> load_results(const std::string& dir, const std::vector<std::string>& densities,
                                                   std::vector<std::string>& missing) {
  namespace fs = std::filesystem;
  std::map<std::string, DensityResults> all;
  for (const std::string& d : densities) {
    std::map<int, std::string> tests;
    for (int n = 1; n <= 5; ++n) tests[n] = (fs::path(dir) / (d + "_test" + std::to_string(n) + ".h5")).string();
    all[d] = load_density((fs::path(dir) / (d + "_prepare.h5")).string(), tests, missing);
  }
  return all;
}

std::vector<std::pair<std::string, std::string>> sample_dirs(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::pair<long long, std::string>> seeds;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() < 5 || name.compare(0, 4, "seed") != 0) continue;
    std::error_code status;
    const bool folder = e.is_directory(status);
    if (status) throw fs::filesystem_error("a sample folder", e.path(), status);  // e.g. a link to itself
    if (!folder) continue;
    const std::string digits = name.substr(4);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 18) continue;
    seeds.emplace_back(std::stoll(digits), name);
  }
  std::sort(seeds.begin(), seeds.end());
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [seed, name] : seeds) out.emplace_back(name, (fs::path(dir) / name).string());
  if (out.empty()) out.emplace_back("", dir);
  return out;
}

std::vector<Sample> load_samples(const std::string& dir, const std::vector<std::string>& densities,
                                 std::vector<std::string>& missing) {
  std::vector<Sample> out;
  for (const auto& [name, folder] : sample_dirs(dir)) out.push_back({name, folder, load_results(folder, densities, missing)});
  return out;
}

std::string folder_problem(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (st.type() == fs::file_type::not_found) return "does not exist";
  if (ec) return ec.message();
  return fs::is_directory(st) ? "" : "is not a folder";
}

std::vector<std::string> unreadable_results(const std::vector<std::string>& missing) {
  std::vector<std::string> out;
  for (const std::string& file : missing) {
    std::error_code ec;
    const auto st = std::filesystem::symlink_status(file, ec);
    if (!ec && st.type() != std::filesystem::file_type::not_found) out.push_back(file);
  }
  return out;
}

bool report_unreadable(const std::string& tool, const std::vector<std::string>& missing) {
  const std::vector<std::string> lost = unreadable_results(missing);
  for (const std::string& file : lost) {
    std::string why;
    try {
      const dem::h5::Handle f = dem::h5::open_file_read(file);
      why = dem::result_problem(f);
      if (why.empty()) {  // complete: its tables are what cannot be read
        why = "its columns cannot be read";
        for (const char* table : {"timeseries", "legs"}) dem::read_table(f, table, file);
      }
    } catch (const std::exception& e) {
      why = e.what();
    }
    std::fprintf(stderr, "%s: %s: cannot be read as a complete result (%s)\n", tool.c_str(), file.c_str(), why.c_str());
  }
  return !lost.empty();
}

const TestResult* find_test(const DensityResults& r, int number) {
  for (const TestResult& x : r.tests)
    if (x.number == number) return &x;
  return nullptr;
}

const std::vector<double>& column(const Columns& c, const std::string& name) {
  const auto it = c.find(name);
  if (it == c.end()) throw std::out_of_range("the result has no column '" + name + "'");
  return it->second;
}

}  // namespace validation
