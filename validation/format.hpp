#pragma once
// Text the validation tools write: JSON strings, Markdown table cells, numbers, file names.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace validation {

inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

// A Markdown table cell: '|' would end the cell, a newline the row.
inline std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    if (c == '\n') { out += ' '; continue; }
    out += c;
  }
  return out;
}

// Six significant digits.
inline std::string number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// `digits` decimals ("12.30"); "—" for a value that is not there (NaN, infinite).
inline std::string fixed(double x, int digits = 2) {
  if (!std::isfinite(x)) return "—";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// Letters and digits kept, anything else '_': "volumetric strain" -> "volumetric_strain".
inline std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out;
}

}  // namespace validation
