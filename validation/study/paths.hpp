#pragma once
// Paths as the tools write them.
#include <filesystem>
#include <string>

namespace validation {

// A path as written into data files and tables: relative to the working folder, never an absolute
// path of this machine ("." is written as the folder's own name).
inline std::string written_path(const std::string& p) {
  namespace fs = std::filesystem;
  const fs::path rel = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  return rel.empty() ? fs::path(p).filename().string() : rel.string();
}

// A path as the report names it for its reader: relative to the working folder when inside it,
// else absolute.
inline std::string shown_path(const std::string& p) {
  namespace fs = std::filesystem;
  const fs::path rel = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  return rel.empty() || rel.string().rfind("..", 0) == 0 ? fs::absolute(p).lexically_normal().string() : rel.string();
}

}  // namespace validation
