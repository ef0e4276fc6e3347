#pragma once
// Particles from a CSV file: a header line `x,y,z,radius` (metres), then one sphere per line.
#include <csignal>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "cell/periodic_cell.hpp"
#include "core/particles.hpp"

namespace dem {

// What a particle file may hold, checked when it is read.
constexpr double csv_min_radius_m = 1e-6;             // radii in [1 um, 1 m]
constexpr double csv_max_radius_m = 1.0;
constexpr double csv_min_centre_distance = 0.5;       // two centres at least this x the sum of their radii apart
constexpr std::size_t csv_max_bytes = 256u << 20;     // 256 MiB (about 3 million spheres)
constexpr std::size_t csv_max_echo = 80;              // characters of a bad token an error repeats

// Reads spheres into `particles` (positions wrapped into the cell). Throws std::runtime_error
// naming the file and line for a missing header, a wrong column count, a non-number (repeated up
// to csv_max_echo characters), a non-finite value, a radius outside [csv_min_radius_m,
// csv_max_radius_m], a centre more than one radius outside the cell [0, L] on an axis, two centres
// (the nearest periodic images) closer than csv_min_centre_distance x the sum of their radii (both
// lines named), or fewer than 2 spheres.
void read_particle_csv(const std::string& file, const PeriodicCell& cell, double density_kg_per_m3, Particles& particles);

// The same from the file's bytes, read once by the caller (a FIFO can be read only once: the run
// parses and hashes the same bytes, engine/run/run_scene.cpp). `file` names the source in errors.
void parse_particle_csv(const std::string& text, const std::string& file, const PeriodicCell& cell, double density_kg_per_m3,
                        Particles& particles);

// The whole content of `file`, opened once (also a FIFO); throws std::runtime_error naming the
// file when it is a directory, cannot be read, or holds more than `max_bytes` (read no further:
// /dev/zero is refused after max_bytes). It never blocks in open() or read(): a FIFO is opened
// without waiting for its writer and then waited for in steps of read_wait_step_ms, so that when
// `stop` is given and becomes non-zero (a signal asked the run to stop, run/run_scene.hpp) it
// throws ReadStopped within one step, however long the writer takes (or if it never comes).
std::string read_whole_file(const std::string& file, std::size_t max_bytes = csv_max_bytes,
                            const volatile std::sig_atomic_t* stop = nullptr);
inline constexpr int read_wait_step_ms = 100;
struct ReadStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dem
