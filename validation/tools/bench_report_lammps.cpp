// bench-report lammps-json: the JSON file of one reports/bench/lammps_bench.sh call, from the logs
// LAMMPS wrote (engine/bench/lammps_log.hpp reads them). The script runs programs; this writes the
// file with nlohmann-json (it used to be printed with awk and a here-document).
//
//   bench-report lammps-json LOG_DIR OUT.json --frictions "0.5 0" --atoms N --steps N --reps N
//                [--tiles N] --package TEXT --settings TEXT
//
// LOG_DIR holds log.mu<FRICTION> for each friction (as written on the command line) and, when GNU
// time measured it, rss.mu<FRICTION> (the peak resident set size in kB). The version is the first
// log's banner with the Debian package's version (--package). Prints the console table of the runs.
// Exit status 1 (with the file's name) when a log is missing or does not hold every repetition.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench/lammps_log.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error(p.string() + ": missing (the LAMMPS run that writes it did not finish)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int lammps_json_main(int argc, char** argv) {
  CLI::App app{"bench-report lammps-json: the JSON file of one lammps_bench.sh call from its LAMMPS logs"};
  std::string log_dir, out, frictions, package = "unknown", settings;
  long long atoms = 0, steps = 0;
  int reps = 0, tiles = 1;
  app.add_option("LOG_DIR", log_dir, "folder of log.mu<FRICTION> (and rss.mu<FRICTION>)")->required();
  app.add_option("OUT", out, "the JSON file to write")->required();
  app.add_option("--frictions", frictions, "the frictions run, in order, as written in the logs' names")->required();
  app.add_option("--atoms", atoms, "spheres of the packing read (before tiling)")->required();
  app.add_option("--tiles", tiles, "the packing tiled n x n x n")->capture_default_str();
  app.add_option("--steps", steps, "timed steps of each repetition")->required();
  app.add_option("--reps", reps, "repetitions")->required();
  app.add_option("--package", package, "the Debian lammps package's version")->capture_default_str();
  app.add_option("--settings", settings, "the contact law and fixes, as the file quotes them")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    std::vector<std::string> names;
    std::istringstream in(frictions);
    for (std::string w; in >> w;) names.push_back(w);
    if (names.empty()) throw std::invalid_argument("--frictions names no friction");
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    std::string version;
    std::printf("%s", dem::bench::lammps_runs_header().c_str());
    for (const std::string& mu : names) {
      const fs::path log = fs::path(log_dir) / ("log.mu" + mu), rss = fs::path(log_dir) / ("rss.mu" + mu);
      const std::string text = read_file(log);
      if (version.empty()) version = dem::bench::lammps_version(text);
      std::optional<double> rss_kB;
      if (std::ifstream r(rss); r) {
        double kB = 0;
        if (r >> kB) rss_kB = kB;
      }
      try {
        runs.push_back(dem::bench::lammps_runs(text, std::stod(mu), reps, rss_kB));
      } catch (const std::exception& e) {
        throw std::runtime_error(log.string() + ": " + e.what());
      }
      std::printf("%s", dem::bench::lammps_runs_line(runs.back()).c_str());
    }
    const long long particles = atoms * tiles * tiles * tiles;
    nlohmann::ordered_json j;
    j["code"] = "LAMMPS";
    j["version"] = version + " (Debian lammps " + package + ")";
    j["particles"] = particles;
    j["tiles"] = tiles;
    j["steps"] = steps;
    j["repetitions"] = reps;
    j["threads"] = 1;
    j["settings"] = settings;
    j["runs"] = runs;
    if (fs::path(out).has_parent_path()) fs::create_directories(fs::path(out).parent_path());
    std::ofstream f(out);
    f << j.dump(2) << "\n";
    if (!f.flush()) throw std::runtime_error(out + ": cannot be written");
    std::printf("LAMMPS %s, %lld spheres, %lld steps x %d repetitions, 1 core -> %s\n", version.c_str(), particles, steps, reps, out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-report lammps-json: %s\n", e.what());
    return 1;
  }
  return 0;
}
