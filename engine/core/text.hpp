#pragma once
// Checks of text read from files (scenes, studies, reports): where it stops being text.
#include <cstddef>
#include <string>

namespace dem {

// The offset of the first byte that is a NUL, another control character but tab, newline and
// carriage return (when `controls`), or not part of valid UTF-8; std::string::npos if none.
std::size_t first_non_text(const std::string& s, bool controls = false);

// The line (from 1) of byte `offset` of `s`.
std::size_t line_of(const std::string& s, std::size_t offset);

}  // namespace dem
