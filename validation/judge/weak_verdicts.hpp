#pragma once
// A verdict that cannot mean much ("weak"), marked the same way wherever a verdict is shown (the
// verdict tables, the appendices, the decisions and check tables, the figure notes): the mark ⚠
// after the verdict, and a legend that names every kind of warning the text shows. Each kind is
// declared once here: the words its warnings start with (judge_values writes them, rows.cpp) and
// its line in the legend.
#include <optional>
#include <string>
#include <vector>

#include "judge/rows.hpp"

namespace validation {

enum class Weakness {
  Misfit,         // the quantity does not fit the runs it read (a monotonic-shear quantity on cyclic tests)
  QuasiStatic,    // a quasi-static reference against runs at a finite rate (not judged)
  WidthOnly,      // consistent only because the interval of one sample is wide: no sample in the reference's region
  TooFewSamples,  // the interval of one sample wider than too_few_width times the row's tolerance
};

// The words a warning of each kind starts with (a misfit's are the quantity's own).
inline constexpr const char* quasi_static_words = "not judged: the reference holds in the quasi-static limit";
inline constexpr const char* width_only_words = "consistent by width only";
inline constexpr const char* too_few_words = "samples too few to judge";

// The kind of a warning judge_values wrote.
Weakness weakness_of(const std::string& warning);
// The kinds among a result's warnings, each once, in the order of the enum.
std::vector<Weakness> weaknesses(const RowResult& r);

// "samples too few to judge: the interval of one sample (0.179 wide, 3 samples) is 5.8 times the
// tolerance 0.1 (more than 4)" when `s` (rule interval, check within, a tolerance above 0) has an
// interval of one sample wider than too_few_width times the tolerance; none otherwise. Also for a
// spread a file records as mean, sd and n (summary_spread).
std::optional<std::string> too_few_warning(const Row& row, const Spread& s);

// The mark of a verdict: "✅", "❌" or "—", followed by " ⚠" when `weak`.
std::string verdict_mark(Verdict v, bool weak = false);
// The same of a result: weak when it carries a warning.
std::string verdict_mark(const RowResult& r);
// The mark with the verdict's words: "✅ consistent ⚠".
std::string verdict_words(Verdict v, bool weak = false);

// The legend of the ⚠ mark naming each kind in `kinds` (every kind when empty): one sentence,
// "⚠ marks a verdict that cannot mean much: ...".
std::string weak_legend(const std::vector<Weakness>& kinds = {});

}  // namespace validation
