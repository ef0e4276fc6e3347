#include "io/failure.hpp"

#include <filesystem>
#include <new>

namespace dem {

std::string describe_failure(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return std::string("out of memory (") + e.what() + ")";
  if (const auto* fe = dynamic_cast<const std::filesystem::filesystem_error*>(&e)) {
    std::string where = fe->path1().string();
    if (!fe->path2().empty()) where += " and " + fe->path2().string();
    return (where.empty() ? std::string() : where + ": ") + fe->code().message();
  }
  return e.what();
}

}  // namespace dem
