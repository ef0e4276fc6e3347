#include "judge/weak_verdicts.hpp"

#include <algorithm>
#include <sstream>

#include "study/format.hpp"
#include "study/settings.hpp"

namespace validation {

namespace {

bool starts_with(const std::string& s, const char* words) { return s.rfind(words, 0) == 0; }

// "0.179", "5.8": three significant digits, as the warnings have always printed them.
std::string three_digits(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

}  // namespace

Weakness weakness_of(const std::string& warning) {
  if (starts_with(warning, quasi_static_words)) return Weakness::QuasiStatic;
  if (starts_with(warning, width_only_words)) return Weakness::WidthOnly;
  if (starts_with(warning, too_few_words)) return Weakness::TooFewSamples;
  return Weakness::Misfit;
}

std::vector<Weakness> weaknesses(const RowResult& r) {
  std::vector<Weakness> out;
  for (Weakness k : {Weakness::Misfit, Weakness::QuasiStatic, Weakness::WidthOnly, Weakness::TooFewSamples})
    if (std::any_of(r.warnings.begin(), r.warnings.end(), [&](const std::string& w) { return weakness_of(w) == k; })) out.push_back(k);
  return out;
}

std::optional<std::string> too_few_warning(const Row& row, const Spread& s) {
  if (row.rule != "interval" || row.check != "within" || !(row.tolerance > 0) || !s.low || !s.high) return std::nullopt;
  const double width = *s.high - *s.low;
  if (!(width > too_few_width * row.tolerance)) return std::nullopt;
  return std::string(too_few_words) + ": the interval of one sample (" + three_digits(width) + " wide, " + std::to_string(s.n) +
         " samples) is " + three_digits(width / row.tolerance) + " times the tolerance " + number(row.tolerance) + " (more than " +
         number(too_few_width) + ")";
}

std::string verdict_mark(Verdict v, bool weak) {
  return std::string(v == Verdict::Consistent ? "✅" : v == Verdict::Inconsistent ? "❌" : "—") + (weak ? " ⚠" : "");
}

std::string verdict_mark(const RowResult& r) { return verdict_mark(r.verdict, !r.warnings.empty()); }

std::string verdict_words(Verdict v, bool weak) {
  return verdict_mark(v) + " " + to_string(v) + (weak ? " ⚠" : "");
}

std::string weak_legend(const std::vector<Weakness>& kinds) {
  const std::vector<Weakness> all = {Weakness::Misfit, Weakness::QuasiStatic, Weakness::WidthOnly, Weakness::TooFewSamples};
  std::vector<std::string> lines;
  for (Weakness k : kinds.empty() ? all : kinds)
    switch (k) {
      case Weakness::Misfit: lines.push_back("the quantity does not fit the runs it read (one meant for a monotonic shear read cyclic tests)"); break;
      case Weakness::QuasiStatic:
        lines.push_back("the reference holds in the quasi-static limit (I → 0) and the runs are sheared at a finite rate, so the row is not judged");
        break;
      case Weakness::WidthOnly:
        lines.push_back("consistent by width only: none of the samples lies in the reference's region (e.g. 0 of 5), only the interval of one sample "
                        "reaches it");
        break;
      case Weakness::TooFewSamples:
        lines.push_back("samples too few: the interval of one sample is more than " + number(too_few_width) + " times the row's tolerance");
        break;
    }
  return "⚠ marks a verdict that cannot mean much: " + joined(lines, "; or ");
}

}  // namespace validation
