#include "row_verdicts.hpp"

#include <sstream>

#include "study/markdown_table.hpp"

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
    RowTally t{first[r].name};
    bool judged_somewhere = false;
    for (const SetCount& c : v.sets) {
      const std::optional<bool>& k = sets[c.set].misfit.rows[r].consistent;
      if (!k) continue;
      judged_somewhere = true;
      ++t.judged_sets;
      if (*k) ++t.consistent_sets, t.most_with = std::max(t.most_with, c.consistent);
      if (c.set == best) t.at_best = *k;
    }
    if (judged_somewhere) v.per_row.push_back(t);
  }
  v.rows = static_cast<int>(v.per_row.size());
  for (const SetCount& c : v.sets) v.all_consistent += c.judged == v.rows && c.consistent == v.rows ? 1 : 0;
  return v;
}

nlohmann::json rows_json(const RowVerdicts& v, const std::vector<ParameterSet>& sets) {
  nlohmann::json j;
  j["rows"] = v.rows;
  j["scored_sets"] = v.sets.size();
  j["sets_with_every_row_consistent"] = v.all_consistent;
  if (v.best) j["best_set"] = {{"name", sets[v.best->set].name}, {"consistent", v.best->consistent}, {"judged", v.best->judged}};
  if (v.most) j["most"] = {{"name", sets[v.most->set].name}, {"consistent", v.most->consistent}, {"judged", v.most->judged}};
  for (const RowTally& t : v.per_row) {
    nlohmann::json r{{"name", t.name}, {"consistent_sets", t.consistent_sets}, {"judged_sets", t.judged_sets}};
    if (t.most_with >= 0) r["most_rows_consistent_with_it"] = t.most_with;
    if (t.at_best) r["consistent_at_best_set"] = *t.at_best;
    j["per_row"].push_back(r);
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
  md << " Row by row: in how many sets the row is consistent, and the most rows consistent in one of those sets "
        "(a row whose sets all lose others is one the space trades against them).\n\n";
  validation::MarkdownTable t({"row", "at the best set", "consistent in (of the sets judging it)", "the most rows consistent in such a set"});
  for (const RowTally& r : v.per_row)
    t.row({r.name, !r.at_best ? "not judged" : *r.at_best ? "✅" : "❌",
           std::to_string(r.consistent_sets) + " of " + std::to_string(r.judged_sets),
           r.most_with < 0 ? "—" : std::to_string(r.most_with) + " of " + n});
  md << t.text();
  return md.str();
}

}  // namespace calibration
