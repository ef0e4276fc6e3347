#pragma once
// LAMMPS's side of `make bench`: reports/bench/lammps_bench.sh runs LAMMPS (REPS repetitions of
// warm-up, timed run, `run 0`, each followed by a "BENCH ..." print) and `bench-report lammps-json`
// turns its logs into lammps_<packing>_<friction>.json with these functions (nlohmann-json; the
// script used to print the JSON with awk). The fields, and their six significant digits, are
// those the awk wrote: bench-report reads them back.
//
// What is read from a log (LAMMPS 2020-2023 thermo output, the lines the script's input prints):
//   BENCH warm contacts_per_atom Z pressure_Pa P   after the warm-up    -> *_start (mean over reps)
//   BENCH timed                                     the timed run starts
//   Loop time of T on P procs for N steps with A atoms   (timed)      -> rate N A / T [particle-steps/s]
//   C% CPU use with ...                             (timed)            -> rate 100 / C (per CPU second)
//   Ave neighs/atom = X                             (timed)            -> neighbours_per_atom = 2 X (mean; half list)
//   Neighbor list builds = B                        (timed)            -> neighbour_list_builds (summed)
//   Dangerous builds = D                            (every run)        -> dangerous_builds (summed; ends the timed run)
//   BENCH end contacts_per_atom Z pressure_Pa P     after `run 0`      -> *_end (mean over reps)
// Medians are sorted[REPS / 2] (as dem-bench's), min and max the extremes.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace dem::bench {

// One friction's runs: {"friction", "particle_steps_per_s_median", "min", "max", "cpu_rate_median",
// "coordination_number_start", "coordination_number_end", "neighbours_per_atom", "pressure_Pa_start",
// "pressure_Pa_end", "neighbour_list_builds", "dangerous_builds"[, "peak_rss_MB"]}; `peak_rss_kB`
// is GNU time's maximum resident set size (%M), when it was measured. Throws std::runtime_error
// when the log does not hold `reps` timed runs and `reps` "BENCH end" lines.
nlohmann::ordered_json lammps_runs(const std::string& log_text, double friction, int reps, std::optional<double> peak_rss_kB);

// The version in a LAMMPS log's first line "LAMMPS (29 Oct 2020)" -> "29 Oct 2020" (the line as it
// is when it has another form).
std::string lammps_version(const std::string& log_text);

// The line the script prints for one friction (a console table; `lammps_runs_header` heads it).
std::string lammps_runs_line(const nlohmann::ordered_json& runs);
std::string lammps_runs_header();

// `x` to six significant digits (printf's %.6g), as the values of the file have always been.
double six_digits(double x);

}  // namespace dem::bench
