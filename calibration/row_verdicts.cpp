#include "row_verdicts.hpp"

#include <algorithm>
#include <sstream>

#include "study/markdown_table.hpp"
#include "study/posterior_summary.hpp"

namespace calibration {

namespace {

SetCount count(const ParameterSet& s, std::size_t index) {
  SetCount c{index};
  for (const RowMisfit& m : s.misfit.rows)
    if (m.consistent) ++c.judged, c.consistent += *m.consistent ? 1 : 0;
  return c;
}

}  // namespace

RowVerdicts tally_rows(const std::vector<ParameterSet>& sets, std::size_t best) {
  RowVerdicts v;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (!sets[i].misfit.valued) continue;
    const SetCount c = count(sets[i], i);
    v.sets.push_back(c);
    if (!v.most || c.consistent > v.most->consistent) v.most = c;
    if (i == best) v.best = c;
  }
  if (v.sets.empty()) return v;
  // The rows validate judges in some set, in the order of the reference file (every set's misfit
  // lists the same rows in the same order: references.cpp, score).
  const std::vector<RowMisfit>& first = sets[v.sets.front().set].misfit.rows;
  for (std::size_t r = 0; r < first.size(); ++r) {
    RowTally t{first[r].name, r};
    bool judged_somewhere = false;
    for (const SetCount& c : v.sets) {
      const std::optional<bool>& k = sets[c.set].misfit.rows[r].consistent;
      if (!k) continue;
      judged_somewhere = true;
      ++t.judged_sets;
      if (*k && c.consistent > t.most_with) t.most_with = c.consistent, t.most_with_set = c.set;
      if (*k) ++t.consistent_sets;
      if (c.set == best) t.at_best = *k;
    }
    if (judged_somewhere) v.per_row.push_back(t);
  }
  v.rows = static_cast<int>(v.per_row.size());
  // Pairs: a row q consistent in some set, but in none of the sets where row r is.
  const auto consistent = [&](const SetCount& c, std::size_t row) {
    const std::optional<bool>& k = sets[c.set].misfit.rows[row].consistent;
    return k && *k;
  };
  for (RowTally& a : v.per_row) {
    if (a.consistent_sets == 0) continue;
    for (const RowTally& b : v.per_row) {
      if (&b == &a || b.consistent_sets == 0) continue;
      const bool together =
          std::any_of(v.sets.begin(), v.sets.end(), [&](const SetCount& c) { return consistent(c, a.row) && consistent(c, b.row); });
      if (!together) a.never_with.push_back(b.name);
    }
  }
  for (const SetCount& c : v.sets) v.all_consistent += c.judged == v.rows && c.consistent == v.rows ? 1 : 0;
  return v;
}

nlohmann::json rows_json(const RowVerdicts& v, const std::vector<ParameterSet>& sets) {
  nlohmann::json j;
  namespace keys = validation::posterior_keys;  // what the report reads, declared once
  j["rows"] = v.rows;
  j[keys::scored_sets] = v.sets.size();
  j["sets_with_every_row_consistent"] = v.all_consistent;
  if (v.best)
    j[keys::best_set] = {{keys::name, sets[v.best->set].name}, {keys::consistent, v.best->consistent}, {keys::judged, v.best->judged}};
  if (v.most) j["most"] = {{"name", sets[v.most->set].name}, {"consistent", v.most->consistent}, {"judged", v.most->judged}};
  for (const RowTally& t : v.per_row) {
    nlohmann::json r{{keys::name, t.name}, {keys::consistent_sets, t.consistent_sets}, {keys::judged_sets, t.judged_sets}};
    if (t.most_with >= 0) r[keys::most_rows_consistent_with_it] = t.most_with, r[keys::set_with_most_rows] = sets[t.most_with_set].name;
    if (t.at_best) r[keys::consistent_at_best_set] = *t.at_best;
    if (!t.never_with.empty()) r["never_consistent_with"] = t.never_with;
    j[keys::per_row].push_back(r);
  }
  return j;
}

std::string rows_markdown(const RowVerdicts& v, const std::vector<ParameterSet>& sets) {
  if (v.rows == 0 || v.sets.empty()) return "";
  std::ostringstream md;
  const auto n = std::to_string(v.rows);
  md << "Each scored set's rows judged as `validate` judges a study, on the set's own samples: ";
  if (v.best) md << "at the best set (" << sets[v.best->set].name << "), **" << v.best->consistent << " of " << n << "** rows are consistent; ";
  md << "the most in any of the " << v.sets.size() << " scored sets is **" << v.most->consistent << "** (" << sets[v.most->set].name << "); ";
  if (v.all_consistent == 0) md << "**no set run makes all " << n << " consistent**.";
  else md << "**" << v.all_consistent << (v.all_consistent == 1 ? " set makes" : " sets make") << " all " << n << " consistent**.";
  md << " Row by row: in how many sets the row is consistent, the most rows consistent in one of those sets, and "
        "the rows consistent in some set but in none of those (what the space trades the row against).\n\n";
  validation::MarkdownTable t({"row", "at the best set", "consistent in (of the sets judging it)", "the most rows consistent in such a set",
                               "never consistent together with"});
  for (const RowTally& r : v.per_row) {
    std::string never;
    for (std::size_t k = 0; k < r.never_with.size() && k < 2; ++k) never += (k ? "; " : "") + r.never_with[k];
    if (r.never_with.size() > 2) never += " and " + std::to_string(r.never_with.size() - 2) + " more (posterior.json)";
    t.row({r.name, !r.at_best ? "not judged" : *r.at_best ? "✅" : "❌",
           std::to_string(r.consistent_sets) + " of " + std::to_string(r.judged_sets),
           r.most_with < 0 ? "—" : std::to_string(r.most_with) + " of " + n, r.consistent_sets == 0 ? "" : never.empty() ? "—" : never});
  }
  md << t.text();
  return md.str();
}

}  // namespace calibration
