#pragma once
// A content hash for keying results and checkpoints on their inputs.
#include <string>

namespace dem {

// FNV-1a, 64 bit, as 16 hex digits: stable across platforms and compilers.
std::string content_hash(const std::string& text);

}  // namespace dem
