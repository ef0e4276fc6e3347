#include "sections/liquefaction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "study/format.hpp"
#include "study/columns.hpp"

namespace validation {

StageRows stage_rows(const Columns& series, int stage) {
  const std::vector<double>& s = column(series, "stage");
  const auto first = std::find(s.begin(), s.end(), static_cast<double>(stage));
  if (first == s.end()) throw std::runtime_error("the time series has no row of stage " + std::to_string(stage));
  const auto last = std::find(s.rbegin(), s.rend(), static_cast<double>(stage));
  return {static_cast<std::size_t>(first - s.begin()), static_cast<std::size_t>(s.rend() - last) - 1};
}

ControlStage summarise_control_stage(const Columns& series, int stage, double period_s) {
  const StageRows r = stage_rows(series, stage);
  const std::vector<double>& t = column(series, col::time);
  const std::vector<double>& ru = column(series, col::pore_pressure_ratio);
  ControlStage out;
  out.start_time_s = t[r.first];
  out.end_time_s = t[r.last];
  // The stage's first row is written before its first step, from the state the engine takes p0 of.
  out.p0_Pa = column(series, col::p)[r.first];
  out.ru_end = ru[r.last];
  out.ru_max = *std::max_element(ru.begin() + static_cast<std::ptrdiff_t>(r.first), ru.begin() + static_cast<std::ptrdiff_t>(r.last) + 1);
  out.cycles = period_s > 0 ? (out.end_time_s - out.start_time_s) / period_s : std::nan("");
  return out;
}

std::string stop_criterion(const std::string& stage_end) {
  const std::string prefix = "until.";
  if (stage_end.rfind(prefix, 0) != 0) return "";
  return stage_end.substr(prefix.size(), stage_end.find(' ') - prefix.size());
}

std::optional<double> csr_from_name(const std::string& run) {
  const auto at = run.rfind("_csr");
  if (at == std::string::npos) return std::nullopt;
  const std::string digits = run.substr(at + 4);
  char* end = nullptr;
  const double csr = std::strtod(digits.c_str(), &end);
  if (digits.empty() || *end != '\0' || !std::isfinite(csr)) return std::nullopt;
  return csr;
}

double cyclic_stress_ratio(double amplitude_Pa, double p0_Pa) { return p0_Pa > 0 ? amplitude_Pa / (2 * p0_Pa) : std::nan(""); }

double value_since_start(const Columns& series, int stage, const std::string& name, double t_s) {
  const StageRows r = stage_rows(series, stage);
  const std::vector<double>& t = column(series, col::time);
  const std::vector<double>& v = column(series, name);
  const double at = t[r.first] + t_s;
  if (t_s < 0 || at > t[r.last]) return std::nan("");
  for (std::size_t i = r.first; i < r.last; ++i)
    if (at <= t[i + 1]) return t[i + 1] > t[i] ? v[i] + (v[i + 1] - v[i]) * (at - t[i]) / (t[i + 1] - t[i]) : v[i + 1];
  return v[r.last];
}

Table ru_against_cycles(const Columns& series, int stage, double period_s) {
  const StageRows r = stage_rows(series, stage);
  const std::vector<double>& t = column(series, col::time);
  const std::vector<double>& ru = column(series, col::pore_pressure_ratio);
  Table out;
  out.columns = {"cycles [1]", "r_u [1]", "time since the stage start [s]"};
  for (std::size_t i = r.first; i <= r.last; ++i) out.rows.push_back({(t[i] - t[r.first]) / period_s, ru[i], t[i] - t[r.first]});
  return out;
}

namespace {

// The median of values (sorted here).
double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  if (n % 2) return v[n / 2];
  // Both middle values infinite: the median is too (inf + inf is inf, never NaN).
  return std::isinf(v[n / 2 - 1]) ? v[n / 2 - 1] : v[n / 2 - 1] / 2 + v[n / 2] / 2;
}

}  // namespace

CensoredSummary summarise_censored(const std::vector<CensoredCycles>& samples) {
  if (samples.empty()) throw std::invalid_argument("summarise_censored: no samples");
  CensoredSummary s;
  s.samples = static_cast<int>(samples.size());
  std::vector<double> low, high;
  for (const CensoredCycles& c : samples) {
    (c.censored ? s.censored : s.liquefied) += 1;
    low.push_back(c.cycles);
    high.push_back(c.censored ? std::numeric_limits<double>::infinity() : c.cycles);
  }
  s.median_low = median_of(low);
  s.median_high = median_of(high);
  s.median_censored = s.median_high != s.median_low;
  // The least and the largest of the values as measured (a censored sample at its N; at a tie the
  // liquefied one is the least, the censored one the largest). A censored least is a bound, "> N";
  // so is a censored largest. With tests of different durations a censored N below the largest
  // liquefied N_L leaves that largest a lower bound, written as the value (not the case here:
  // every test of a study runs the same number of cycles).
  s.least = samples.front(), s.largest = samples.front();
  for (const CensoredCycles& c : samples) {
    if (c.cycles < s.least.cycles || (c.cycles == s.least.cycles && !c.censored)) s.least = c;
    if (c.cycles > s.largest.cycles || (c.cycles == s.largest.cycles && c.censored)) s.largest = c;
  }
  return s;
}

std::string censored_text(const CensoredCycles& c, int digits) { return (c.censored ? "> " : "") + fixed(c.cycles, digits); }

std::string median_text(const CensoredSummary& s, int digits) {
  if (!s.median_censored) return fixed(s.median_low, digits);
  if (std::isinf(s.median_high)) return "> " + fixed(s.median_low, digits);
  return fixed(s.median_low, digits) + " – " + fixed(s.median_high, digits);
}

}  // namespace validation
