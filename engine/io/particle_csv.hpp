#pragma once
// Particles from a CSV file: a header line `x,y,z,radius` (metres), then one sphere per line.
#include <string>

#include "cell/periodic_cell.hpp"
#include "core/particles.hpp"

namespace dem {

// Reads spheres into `particles` (positions wrapped into the cell). Throws std::runtime_error
// naming the file and line for a missing header, a wrong column count, a non-number, a non-finite
// value or a non-positive radius.
void read_particle_csv(const std::string& file, const PeriodicCell& cell, double density_kg_per_m3, Particles& particles);

// The same from the file's bytes, read once by the caller (a FIFO can be read only once: the run
// parses and hashes the same bytes, engine/run/run_scene.cpp). `file` names the source in errors.
void parse_particle_csv(const std::string& text, const std::string& file, const PeriodicCell& cell, double density_kg_per_m3,
                        Particles& particles);

// The whole content of `file`, opened once (also a FIFO); throws std::runtime_error naming the
// file when it is a directory or cannot be read.
std::string read_whole_file(const std::string& file);

}  // namespace dem
