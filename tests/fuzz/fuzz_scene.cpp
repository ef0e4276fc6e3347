// libFuzzer: any byte string as a scene YAML. Allowed outcomes: a scene, or dem::ConfigError (the
// message a user sees). Anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    dem::scene_from_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const dem::ConfigError&) {
  }
  return 0;
}
