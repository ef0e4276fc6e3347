// libFuzzer: any byte string as a study YAML (written to a scratch file: the loader reads files).
// Allowed outcomes: a study, or dem::ConfigError. Anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = "/tmp/dem_fuzz_study_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  try {
    pipeline::load_study(file);
  } catch (const dem::ConfigError&) {
  }
  return 0;
}
