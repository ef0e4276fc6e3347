#pragma once
// Text the validation tools write: Markdown table cells, numbers, file names. (JSON is written with
// nlohmann-json, never by hand.)
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
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

// fixed() with a negative zero written as zero ("-0.00" -> "0.00"): a value that rounds to zero.
inline std::string fixed_unsigned_zero(double x, int digits = 2) {
  std::string s = fixed(x, digits);
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  return s;
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

// `x` to `digits` significant digits, trailing zeros kept ("0.00016", "0.86", "1.0", "120").
inline std::string significant(double x, int digits = 2) {
  if (!std::isfinite(x)) return "—";
  if (x == 0) return "0";
  int e = static_cast<int>(std::floor(std::log10(std::abs(x))));
  double unit = std::pow(10.0, e - digits + 1);
  if (std::abs(std::round(x / unit)) >= std::pow(10.0, digits)) ++e, unit *= 10;  // 0.0996 -> 0.10
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, digits - 1 - e), std::round(x / unit) * unit);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // "-0.00" -> "0.00"
  return s;
}

// Which side of the values a bound is on, and whether they may equal it: "at most", "stays below",
// "at least", "stays above"; "within lo–hi" is at_least lo and at_most hi.
enum class Bound { at_most, below, at_least, above };
// How a bound's precision is counted: significant digits of the value, or decimals.
enum class Digits { significant, decimals };

// A bound of values whose extreme (unrounded) is `x`, worded so that the sentence stays true of `x`
// itself: rounded outwards at the printed precision (an upper bound up, a lower bound down; a strict
// one on a printed digit moves one digit on), e.g. "within 98.83–99.98" of 98.83519 … 99.97840 where
// rounding to nearest gives 98.84, and "stays below 0.00013" of 0.0001237. A nonzero `x` smaller than
// the last decimal asked for is given two significant digits ("at most 0.00020" of 0.000192, never
// "at most 0.000" or a loose "0.001"). Every bound the notes and sections word goes through here.
inline std::string bound_text(double x, Bound side, int digits, Digits kind = Digits::significant) {
  if (!std::isfinite(x)) return "—";
  const bool upper = side == Bound::at_most || side == Bound::below;
  const bool strict = side == Bound::below || side == Bound::above;
  const int magnitude = x == 0 ? 0 : static_cast<int>(std::floor(std::log10(std::abs(x))));
  int e = kind == Digits::decimals ? -digits : magnitude - digits + 1;
  if (kind == Digits::decimals && x != 0 && std::abs(x) < std::pow(10.0, e)) e = magnitude - 1;  // two significant digits
  const bool by_decimals = kind == Digits::decimals && e == -digits;
  const double unit = std::pow(10.0, e);
  const auto text = [&](double b) {
    if (!by_decimals) return significant(b, magnitude - e + 1);  // a power of ten reached from below prints as one (0.0996 -> 0.10)
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, digits), b == 0 ? 0.0 : b);
    return std::string(buf);
  };
  double b = (upper ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
  // The printed number, read back, must keep the bound (binary fractions, strictness): else one unit on.
  for (int k = 0; k < 3; ++k) {
    const double shown = std::strtod(text(b).c_str(), nullptr);
    const bool holds = upper ? (strict ? shown > x : shown >= x) : (strict ? shown < x : shown <= x);
    if (holds) break;
    b += upper ? unit : -unit;
  }
  return text(b);
}

// The largest shift (in sd units) shown as it is; beyond it the tables and sentences say so and
// write the value, and the tornado charts cut the bar there (reports/gnuplot/tornado.gp: clip()).
constexpr double shift_clip = 10;

// A shift in sd units as the tables print it: two decimals within ±10, else the value with a
// marker that the chart clips it ("+1267 (beyond ±10)").
inline std::string shift_text(double z) {
  if (!std::isfinite(z)) return "—";
  char buf[64];
  if (std::abs(z) <= shift_clip) std::snprintf(buf, sizeof buf, "%+.2f", z);
  else std::snprintf(buf, sizeof buf, "%+.0f (beyond ±%.0f)", z, shift_clip);
  return buf;
}

// A shift in sd units as the sentences say it (the decisions study's explanations): two
// significant digits with its sign and unit ("-3.7 sd", "+0.61 sd"), or beyond ±10 that said, with
// the value to two significant digits ("beyond +10 sd (+57)").
inline std::string shift_phrase(double z) {
  if (!std::isfinite(z)) return "—";
  if (z == 0) return "0 sd";
  const std::string sign = z < 0 ? "-" : "+";
  if (std::abs(z) <= shift_clip) return sign + significant(std::abs(z), 2) + " sd";
  return "beyond " + sign + significant(shift_clip, 2) + " sd (" + sign + significant(std::abs(z), 2) + ")";
}

// Digits grouped by thousands: "8000" -> "8,000"; text that is not digits (or none) as it is.
inline std::string thousands(const std::string& digits) {
  if (digits.find_first_not_of("0123456789") != std::string::npos) return digits;
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}
inline std::string thousands(long n) { return n < 0 ? "-" + thousands(std::to_string(-n)) : thousands(std::to_string(n)); }

// Letters and digits kept, anything else '_': "volumetric strain" -> "volumetric_strain".
inline std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out;
}

// An energy [J]: three significant digits, in powers of ten below 0.01 J.
inline std::string energy_text(double x) {
  if (!std::isfinite(x)) return "—";
  if (x != 0 && std::abs(x) < 1e-2) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", x);
    return buf;
  }
  return significant(x, 3);
}

// A percentage that may be at rounding level: two significant digits, in powers of ten below 0.001.
inline std::string percent_small(double x) {
  if (!std::isfinite(x)) return "—";
  if (x != 0 && std::abs(x) < 1e-3) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", x);
    return buf;
  }
  return significant(x, 2);
}

}  // namespace validation
