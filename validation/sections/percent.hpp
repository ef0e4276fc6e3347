#pragma once
// A relative error or energy closure as the convergence and stability tables print it.
#include <cmath>
#include <cstdio>
#include <string>

namespace sections {

// "1.23 %", below 0.1 % to two significant digits ("0.0042 %"); "—" for a value that is not there.
inline std::string percent(double e) {
  if (!std::isfinite(e)) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, e < 0.001 ? "%.2g %%" : "%.2f %%", 100 * e);
  return buf;
}

}  // namespace sections
