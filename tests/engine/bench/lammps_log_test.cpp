// LAMMPS's side of `make bench` (engine/bench/lammps_log.hpp, `bench-report lammps-json`): a log
// of the shape reports/bench/lammps_bench.sh makes LAMMPS write, with numbers chosen so that each
// field's value is known by hand, read into the JSON the script used to print with awk.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/lammps_log.hpp"
#include "engine/io/io_test_support.hpp"

namespace fs = std::filesystem;

namespace {

// One repetition as LAMMPS logs it: the input's commands echoed, the warm-up run, the timed run and
// `run 0`, each run's timing and neighbour lines, and the script's three "BENCH" prints.
std::string repetition(double loop_s, double cpu_percent, double z_warm, double p_warm, double neighs, int builds, int dangerous_warm,
                       int dangerous_timed, double z_end, double p_end) {
  const auto run = [](const std::string& loop, double cpu, double ave, int list_builds, int dangerous, int steps) {
    return "Loop time of " + loop + " on 1 procs for " + std::to_string(steps) + " steps with 8000 atoms\n\n" + std::to_string(cpu) +
           "% CPU use with 1 MPI tasks x 1 OpenMP threads\n\nTotal # of neighbors = 40000\nAve neighs/atom = " + std::to_string(ave) +
           "\nNeighbor list builds = " + std::to_string(list_builds) + "\nDangerous builds = " + std::to_string(dangerous) + "\n";
  };
  return "include         /tmp/x/in.setup\nrun             200\n" + run("0.5", 99.0, 9, 100, dangerous_warm, 200) +
         "print           \"BENCH warm contacts_per_atom ${z} pressure_Pa ${p}\"\nBENCH warm contacts_per_atom " + std::to_string(z_warm) +
         " pressure_Pa " + std::to_string(p_warm) + "\nprint           \"BENCH timed\"\nBENCH timed\nrun             1000\n" +
         run(std::to_string(loop_s), cpu_percent, neighs, builds, dangerous_timed, 1000) + "run             0\n" + run("1.2e-05", 0.0, 7, 0, 0, 0) +
         "BENCH end contacts_per_atom " + std::to_string(z_end) + " pressure_Pa " + std::to_string(p_end) + "\nclear\n";
}

// Three repetitions: timed loops of 2, 2.5 and 4 s for 1000 steps x 8000 atoms, i.e. 4e6, 3.2e6
// and 2e6 particle-steps/s; at 100 %, 80 % and 100 % CPU, 4e6, 4e6 and 2e6 per CPU second.
const std::string log_text = "LAMMPS (29 Oct 2020)\n" + repetition(2.0, 100, 4.5, 1.0e5, 10, 5, 2, 1, 4.4, 9.0e4) +
                             repetition(2.5, 80, 4.8, 1.1e5, 11, 6, 0, 1, 4.4, 9.0e4) + repetition(4.0, 100, 5.1, 1.2e5, 12, 7, 0, 1, 4.4, 9.3e4);

}  // namespace

TEST_CASE("lammps log: the runs' JSON, every field known by hand", "[bench][lammps]") {
  const nlohmann::ordered_json r = dem::bench::lammps_runs(log_text, 0.5, 3, 204800.0);
  // The fields in the order the script wrote them (bench-report reads them by name; the order is the file's look).
  std::vector<std::string> keys;
  for (const auto& [k, v] : r.items()) keys.push_back(k);
  CHECK(keys == std::vector<std::string>{"friction", "particle_steps_per_s_median", "min", "max", "cpu_rate_median",
                                         "coordination_number_start", "coordination_number_end", "neighbours_per_atom",
                                         "pressure_Pa_start", "pressure_Pa_end", "neighbour_list_builds", "dangerous_builds",
                                         "peak_rss_MB"});
  CHECK(r["friction"] == 0.5);
  CHECK(r["particle_steps_per_s_median"] == 3.2e6);  // sorted[3 / 2] of 2e6, 3.2e6, 4e6
  CHECK(r["min"] == 2e6);
  CHECK(r["max"] == 4e6);
  CHECK(r["cpu_rate_median"] == 4e6);  // sorted[1] of 2e6, 4e6, 4e6
  CHECK(r["coordination_number_start"] == Approx(4.8));
  CHECK(r["coordination_number_end"] == Approx(4.4));
  CHECK(r["neighbours_per_atom"] == Approx(22));  // 2 x the mean of 10, 11, 12 (LAMMPS's half list)
  CHECK(r["pressure_Pa_start"] == Approx(1.1e5));
  CHECK(r["pressure_Pa_end"] == Approx(9.1e4));
  CHECK(r["neighbour_list_builds"] == 18);  // the timed runs' 5 + 6 + 7, not the warm-ups' 100s
  CHECK(r["dangerous_builds"] == 5);        // every run's: 2 in the first warm-up and 1 per timed run
  CHECK(r["peak_rss_MB"] == 200.0);         // 204800 kB
  // Six significant digits, as the awk's %.6g: 2 / 3 of a rate is written 2.66667e6, not 2666666.67.
  CHECK(dem::bench::six_digits(8e6 / 3) == 2.66667e6);
  CHECK(dem::bench::lammps_version(log_text) == "29 Oct 2020");
  // Without a peak memory, no such field.
  CHECK_FALSE(dem::bench::lammps_runs(log_text, 0, 3, std::nullopt).contains("peak_rss_MB"));
  // A log that lacks a repetition is an error naming both counts.
  CHECK_THROWS_WITH(dem::bench::lammps_runs(log_text, 0.5, 4, std::nullopt), Catch::Contains("expected 4") && Catch::Contains("found 3 and 3"));
}

TEST_CASE("bench-report lammps-json: the file lammps_bench.sh used to write, from its logs", "[bench][lammps][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "lammps_json";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // What the script leaves: log.mu<FRICTION> per friction and GNU time's rss.mu<FRICTION> (kB).
  std::ofstream(dir / "log.mu0.5") << log_text;
  std::ofstream(dir / "log.mu0") << log_text;
  std::ofstream(dir / "rss.mu0.5") << "102400\n";
  const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/bench-report";
  const auto r = dem::test::run_command(
      "'" + bin + "' lammps-json '" + dir.string() + "' '" + (dir / "out" / "lammps.json").string() +
      "' --frictions '0.5 0' --atoms 1000 --tiles 2 --steps 1000 --reps 3 --package '20201029+dfsg1-1' "
      "--settings 'pair_style gran/hooke/history 1.0e6 1.0e6 G GT MU 1; fix nve/sphere; fix viscous GV; fixed periodic box' 2>&1");
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(dir / "out" / "lammps.json");
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  CHECK(keys == std::vector<std::string>{"code", "version", "particles", "tiles", "steps", "repetitions", "threads", "settings", "runs"});
  CHECK(j["code"] == "LAMMPS");
  CHECK(j["version"] == "29 Oct 2020 (Debian lammps 20201029+dfsg1-1)");
  CHECK(j["particles"] == 8000);  // 1000 atoms tiled 2 x 2 x 2
  CHECK(j["tiles"] == 2);
  CHECK(j["steps"] == 1000);
  CHECK(j["repetitions"] == 3);
  CHECK(j["threads"] == 1);
  CHECK(j["settings"] == "pair_style gran/hooke/history 1.0e6 1.0e6 G GT MU 1; fix nve/sphere; fix viscous GV; fixed periodic box");
  REQUIRE(j["runs"].size() == 2);
  CHECK(j["runs"][0]["friction"] == 0.5);
  CHECK(j["runs"][0]["peak_rss_MB"] == 100.0);
  CHECK(j["runs"][1]["friction"] == 0);
  CHECK_FALSE(j["runs"][1].contains("peak_rss_MB"));  // no rss file: not measured
  CHECK(j["runs"][1]["particle_steps_per_s_median"] == 3.2e6);
  // The console table: a heading and one line per friction.
  CHECK(r.out.find("particle-steps/s (med)") != std::string::npos);
  CHECK(r.out.find("3.200e+06") != std::string::npos);
  // A missing log is an error naming it.
  const auto bad = dem::test::run_command("'" + bin + "' lammps-json '" + dir.string() + "' '" + (dir / "x.json").string() +
                                          "' --frictions '0.25' --atoms 1000 --steps 1000 --reps 3 --package p --settings s 2>&1");
  CHECK(bad.exit_code == 1);
  CHECK(bad.out.find("log.mu0.25") != std::string::npos);
}
