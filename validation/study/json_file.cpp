#include "study/json_file.hpp"

#include <fstream>
#include <stdexcept>

namespace validation {

nlohmann::json read_json_file(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file + ": not JSON (" + e.what() + ")");
  }
}

}  // namespace validation
