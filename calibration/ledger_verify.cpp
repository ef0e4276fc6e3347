// A ledger scored on runs that hash otherwise here, taken after a verification (RunOptions::
// ledger_verify). A run's hash covers its resolved scene's text and the engine's source, so a change
// of either (a new scene key written with its default, another engine) leaves every entry
// unfound, though the physics may be the same. Whether it is, is measured: some of those sets, spread
// over the ledger, run again here and are scored; each must give every row's mean and sd bit for bit
// as the ledger has them. Then the others are taken, each with the text of what verified it, and are
// written back with this plan's hashes: a later calibration finds them without running anything.
#include <cstdio>
#include <string>
#include <vector>

#include "config/yaml_section.hpp"
#include "loop.hpp"
#include "sets.hpp"
#include "study/format.hpp"
#include "study/settings.hpp"

namespace calibration {

namespace {

// "" when the two scores are the same bit for bit (every row's value, mean and sd at every point),
// else the first difference.
std::string first_difference(const SetMisfit& ledger, const SetMisfit& here) {
  if (ledger.rows.size() != here.rows.size())
    return std::to_string(here.rows.size()) + " rows here, " + std::to_string(ledger.rows.size()) + " in the ledger";
  for (std::size_t i = 0; i < here.rows.size(); ++i) {
    const RowMisfit &a = ledger.rows[i], &b = here.rows[i];
    if (a.name != b.name) return "row " + std::to_string(i + 1) + " is " + b.name + " here, " + a.name + " in the ledger";
    if (a.valued != b.valued) return a.name + ": " + (b.valued ? "valued here, not in the ledger" : "not valued here (" + b.note + ")");
    if (a.model.size() != b.model.size() || a.model_sd.size() != b.model_sd.size() || a.samples != b.samples)
      return a.name + ": " + std::to_string(b.samples) + " samples here, " + std::to_string(a.samples) + " in the ledger";
    for (std::size_t j = 0; j < a.model.size(); ++j)
      if (a.model[j] != b.model[j] || a.model_sd[j] != b.model_sd[j])
        return a.name + (a.model.size() > 1 ? " at point " + std::to_string(j + 1) : "") + ": " +
               validation::significant(b.model[j], 17) + " (sd " + validation::significant(b.model_sd[j], 17) + ") here, " +
               validation::significant(a.model[j], 17) + " (sd " + validation::significant(a.model_sd[j], 17) + ") in the ledger";
  }
  return "";
}

}  // namespace

void verify_ledger(Loop& l, std::size_t k) {
  SizeState& size = l.at[k];
  SizeOutcome& so = l.out.sizes[k];
  if (l.o.ledger_verify <= 0 || size.ledger.sets.empty()) return;
  std::vector<ParameterSet> entries;
  for (const ScoredSet& e : size.ledger.sets) entries.push_back({e.name, 0, e.u, 0, {}, ""});
  const auto hashes = run_hashes_by_set(plan_sets(l.c, size.study, *size.profile, entries, so.results, l.out.engine));
  std::vector<ScoredSet*> unfound;
  for (ScoredSet& e : size.ledger.sets)
    if (const auto h = hashes.find(e.name); h != hashes.end() && h->second != e.run_hashes) unfound.push_back(&e);
  if (unfound.empty()) {
    std::printf("[calibrate] --ledger-verify: every set of %s is found by its runs' hashes: nothing to verify\n", size.ledger_file.c_str());
    return;
  }
  // The verification sets: spread evenly over the unfound ones in the ledger's order, the first first.
  const std::size_t n = unfound.size(), count = std::min(n, static_cast<std::size_t>(l.o.ledger_verify));
  std::vector<ParameterSet> picks;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i) {
    const ScoredSet& e = *unfound[i * n / count];
    picks.push_back({e.name, 0, e.u, 0, {}, ""});
    names.push_back(e.name);
  }
  const std::vector<pipeline::PlannedRun> runs = plan_sets(l.c, size.study, *size.profile, picks, so.results, l.out.engine);
  std::printf("[calibrate] --ledger-verify: %zu of the %zu sets of %s hash otherwise here (scored by engine %s); %zu of them run "
              "again first (%s): %zu runs\n",
              n, size.ledger.sets.size(), size.ledger_file.c_str(), size.ledger.stamp.engine_source.c_str(), count, validation::joined(names, ", ").c_str(),
              runs.size());
  std::fflush(stdout);
  if (!l.o.plan_only) {
    if (l.o.ledger_only) throw dem::ConfigError("--ledger-verify runs sets, --ledger-only runs none: give one of them");
    execute_sets(l, k, picks, runs);
    const auto samples = samples_of_sets(runs);
    for (const ParameterSet& p : picks) {
      const auto found = samples.find(p.name);
      const SetMisfit here = score_complete(size.refs, found == samples.end() ? std::vector<validation::Sample>{} : found->second);
      const ScoredSet& e = *size.ledger.find_set(p.name, p.u);
      if (const std::string why = first_difference(e.misfit, here); !why.empty())
        throw dem::ConfigError("--ledger-verify: set " + p.name + " of " + size.ledger_file + ", run again here, does not score as the ledger has it (" +
                               why + "): its sets are not taken; run without --ledger-verify to score them again");
    }
  }
  const std::string by = "scored by engine " + size.ledger.stamp.engine_source + " on " + size.ledger.stamp.date + " on runs that hash otherwise here; " +
                         std::to_string(count) + " of the ledger's " + std::to_string(n) + " such sets (" + validation::joined(names, ", ") + "), run again by engine " +
                         l.out.engine + ", scored bit for bit as it has them";
  for (ScoredSet* e : unfound) e->run_hashes = hashes.at(e->name), e->verified_by = by;
  // The verification sets are scored on their runs here when drawn, not taken.
  std::erase_if(size.ledger.sets, [&](const ScoredSet& e) { return std::find(names.begin(), names.end(), e.name) != names.end(); });
  std::printf("[calibrate] --ledger-verify: %s\n", l.o.plan_only ? "the plan assumes they score as the ledger has them" : "verified");
}

}  // namespace calibration
