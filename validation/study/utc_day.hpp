#pragma once
// The day as every stamp, report and benchmark writes it: YYYY-MM-DD in UTC.

#include <ctime>
#include <string>

namespace validation {

// The day of `t` (default: now) in UTC.
inline std::string utc_day(std::time_t t = std::time(nullptr)) {
  std::tm utc{};
  gmtime_r(&t, &utc);
  char day[11];
  std::strftime(day, sizeof day, "%Y-%m-%d", &utc);
  return day;
}

// Whether `d` is a day written so: YYYY-MM-DD, a month 1-12 and a day the month has (not 2026-02-30).
inline bool is_utc_day(const std::string& d) {
  std::tm day{};
  const char* end = strptime(d.c_str(), "%Y-%m-%d", &day);
  if (d.size() != 10 || end == nullptr || *end != '\0') return false;
  std::tm normal = day;
  timegm(&normal);  // moves a day past the month's end into the next month
  return normal.tm_mday == day.tm_mday;
}

}  // namespace validation
