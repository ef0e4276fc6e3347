#pragma once
// Text the validation tools write: Markdown table cells, numbers, file names. (JSON is written with
// nlohmann-json, never by hand.)
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace validation {

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

// Digits from the scatter: the power of ten of the last digit that shows `sd` to two significant
// digits (sd = 0.0002257 -> -5: "0.00023"; 0.18 -> -2; 12.3 -> 0; 123 -> 1: "120").
inline int scatter_exponent(double sd) {
  int e = static_cast<int>(std::floor(std::log10(std::abs(sd)))) - 1;
  // 0.0996 rounds to 0.100 at e = -3: three digits; one place fewer then.
  if (std::round(std::abs(sd) / std::pow(10.0, e)) >= 100) ++e;
  return e;
}

// `x` rounded to a multiple of 10^exponent, written with the decimals that exponent asks for.
inline std::string rounded(double x, int exponent) {
  if (!std::isfinite(x)) return "—";
  const double unit = std::pow(10.0, exponent);
  double r = std::round(x / unit) * unit;
  if (r == 0) r = 0;  // no "-0.00"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", exponent < 0 ? -exponent : 0, r);
  return buf;
}

// "mean ± sd" with the sd to two significant digits and the mean to the same decimal
// ("0.00045 ± 0.00023"). Without a scatter (sd = 0 or not finite): the mean to six significant digits.
inline std::string mean_pm_sd(double mean, double sd) {
  if (!(sd > 0) || !std::isfinite(sd)) return number(mean);
  const int e = scatter_exponent(sd);
  return rounded(mean, e) + " ± " + rounded(sd, e);
}

// A value printed to the digits a scatter `sd` allows (six significant digits without one).
inline std::string to_scatter(double x, double sd) {
  if (!(sd > 0) || !std::isfinite(sd)) return number(x);
  return rounded(x, scatter_exponent(sd));
}

// A shift of a mean in units of a scatter: `delta` / max(sd, resolution) (a scatter below the
// quantity's resolution says nothing: its samples agree to the last digit that means something).
// None when both are 0.
inline double shift_in_sd(double delta, double sd, double resolution) {
  const double unit = std::max(std::isfinite(sd) ? sd : 0.0, resolution);
  return unit > 0 ? delta / unit : std::nan("");
}

// A shift in sd units as the tables print it: two decimals within ±10, else the value with a
// marker that the chart clips it ("+1267 (beyond ±10)").
inline std::string shift_text(double z) {
  if (!std::isfinite(z)) return "—";
  char buf[64];
  if (std::abs(z) <= 10) std::snprintf(buf, sizeof buf, "%+.2f", z);
  else std::snprintf(buf, sizeof buf, "%+.0f (beyond ±10)", z);
  return buf;
}

// Letters and digits kept, anything else '_': "volumetric strain" -> "volumetric_strain".
inline std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out;
}

}  // namespace validation
