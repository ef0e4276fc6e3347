// libFuzzer: any byte string as a particle CSV file, read into a 5 cm cell. Allowed outcomes:
// particles, or std::runtime_error naming the file and line (the reader's contract; `dem run` reports
// it as bad input). Anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/particles.hpp"
#include "io/particle_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = "/tmp/dem_fuzz_csv_" + std::to_string(getpid()) + ".csv";
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  dem::Particles particles;
  try {
    dem::read_particle_csv(file, dem::PeriodicCell(dem::Vec3(0.05, 0.05, 0.05)), 2650, particles);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
