#pragma once
// Files the tools write are complete or absent: written to <file>.tmp, flushed to disk, renamed.
#include <string>

namespace validation {

// Writes `text` to `file` through <file>.tmp, fsync of the file and of its folder, then a rename;
// throws std::runtime_error naming the file and the reason if any step fails (the old file, if
// any, is then left as it was).
void write_file_atomically(const std::string& file, const std::string& text);

}  // namespace validation
