#include "figures/notes.hpp"

#include <algorithm>
#include <cmath>

#include "figures/figures.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"

namespace validation {

std::string range_fixed(double lo, double hi, int decimals) {
  const std::string a = fixed_unsigned_zero(lo, decimals), b = fixed_unsigned_zero(hi, decimals);
  return a == b ? a : a + "–" + b;
}

std::string range_text(double lo, double hi) {
  const double m = std::max(std::abs(lo), std::abs(hi));
  if (!(m > 0) || !std::isfinite(m)) return range_fixed(lo, hi, 0);
  int e = static_cast<int>(std::floor(std::log10(m)));
  if (std::round(m / std::pow(10.0, e - 1)) >= 100) ++e;
  return range_fixed(lo, hi, std::max(0, 1 - e));
}

std::string verdict_phrase(Verdict v) {
  return v == Verdict::Consistent ? "as in the paper" : v == Verdict::Inconsistent ? "unlike the paper" : "not judged";
}

std::string verdict_phrase(const RowResult& r) { return verdict_phrase(r.verdict) + (r.warnings.empty() ? "" : " ⚠"); }

const std::vector<NoteVerdict>& note_verdicts() {
  static const std::vector<NoteVerdict> list = [] {
    std::vector<NoteVerdict> l;
    for (const std::string& d : paper_densities()) {
      l.push_back({"fig00.verdict_e0_" + d, "void_ratio_after_preparation", d});
      l.push_back({"fig00.verdict_cn_" + d, "coordination_after_preparation", d});
      l.push_back({"fig02.verdict_" + d, "cell_side_cm_after_preparation", d});
      l.push_back({"fig07.verdict_" + d, d == "dense" ? "ev_growth_magnitude" : "ev_growth", d});
      l.push_back({"fig10.verdict_" + d, d == "dense" ? "cn_change_magnitude" : "cn_change", d});
      l.push_back({"fig11.verdict_" + d, d == "loose" ? "sliding_change" : "sliding_change_magnitude", d});
      l.push_back({"fig13.verdict_" + d, "qp_strong_fabric_slope", d});
    }
    l.push_back({"fig06.verdict_loose", "ev_after_cycle", "loose"});
    l.push_back({"fig09.verdict_loose", "strain_increment_alignment_gain", "loose"});
    l.push_back({"fig09.verdict_dense", "strain_increment_alignment_gain_magnitude", "dense"});
    return l;
  }();
  return list;
}

const std::vector<double>* cycle_row(const Table& t, int c) {
  for (const auto& r : t.rows)
    if (static_cast<int>(r[0]) == c) return &r;
  return nullptr;
}

const DensityResults* NoteContext::results_of(const std::string& d) const {
  const auto it = chosen.densities.find(d);
  return it == chosen.densities.end() ? nullptr : &it->second;
}

const RowResult* NoteContext::row_result(const std::string& quantity, const std::string& density) {
  for (const Row& r : in.rows)
    if (r.quantity == quantity && r.density == density) return judged(judged_, r);
  return nullptr;
}

std::string NoteContext::phrase(const std::string& quantity, const std::string& density) {
  const RowResult* r = row_result(quantity, density);
  return r ? verdict_phrase(*r) : std::string("not judged at this size: no row in this profile");
}

const RowResult* NoteContext::values_of(const std::string& quantity, const std::string& density) {
  if (const RowResult* r = row_result(quantity, density)) return r;
  for (const Row& r : in.paper)
    if (r.quantity == quantity && r.density == density) return judged(valued_, r);
  return nullptr;
}

std::string NoteContext::paper(const std::string& quantity, const std::string& density) const {
  const auto x = paper_value(in.paper, quantity, density);
  return x ? number(*x) : std::string("—");
}

const RowResult* NoteContext::judged(std::map<std::string, RowResult>& cache, const Row& r) {
  auto it = cache.find(r.name);
  if (it == cache.end()) it = cache.emplace(r.name, evaluate(r, in.samples)).first;
  return &it->second;
}

}  // namespace validation
