#pragma once
// The report's appendix sections that other studies make (compare-runs), declared once: each
// section's heading, the template key of its table and where its stamp is (study/stamp.hpp). The
// report prints, under each such heading, which engine and baseline its numbers come from, and
// refuses a section made on another baseline than the paper study's unless asked to
// keep it (then headed ⚠). The paper study's own stamp is reports/validation.json's.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "study/stamp.hpp"

namespace validation {

struct OtherStudySection {
  // The section's heading without its "## ": a level-2 heading of the template, whole; or (level 3)
  // the start of a heading inside another section's table (a part another study feeds: "The
  // critical state on " is followed by its number of samples).
  std::string heading;
  std::string table_key;   // the template key of its table: empty (the study has not run) -> no stamp line
  std::string stamp_file;  // relative to the report's folder
  std::string stamp_key;   // the key of stamp_file that holds the stamp; "": its top level
  // Its study prepares from its own scene by design (the stability matrix: 216 spheres compressed
  // fast), so its baseline is said but never compared with the paper study's; its engine is.
  std::string own_scene;   // "": the paper study's preparation; else that scene
  int level = 2;           // 3: a part of another section, its heading matched by its start
  // Where its stamp is recorded when stamp_file has none (a study run before its section kept
  // stamps): a reader of the report's folder that gives the stamp only when that record is of the
  // same data (nothing recorded otherwise); none: stamp_file only.
  Stamp (*recorded_elsewhere)(const std::filesystem::path& report) = nullptr;
};

// The critical-state ensemble's stamp from the literature check of the same study
// (REPORT/literature/validation.json), when its critical-state rows' samples are the ensemble's
// (REPORT/critical_state/ensemble.dat: the μ = 0 compression's void ratio and friction angle, mean
// and sd over as many samples, equal to the ten digits the file writes); nothing recorded otherwise.
Stamp ensemble_stamp_from_literature(const std::filesystem::path& report);
// make bench's stamp from REPORT/bench.json: its "stamp" when it has one, else what it records of
// its engine (engine.version, engine.particles; no baseline, samples or date: not recorded).
Stamp bench_stamp(const std::filesystem::path& report);

// The list, in the report's order.
const std::vector<OtherStudySection>& other_study_sections();
// A section's name as the report's header lists it: its heading's (section_name), or for a part
// (level 3), its section's with the part's stamp key ("Critical state: ... (its ensemble part)").
std::string section_shown(const OtherStudySection& section);

// A section's stamp as its file records it; nothing recorded when the file, or its key, is not there.
Stamp read_section_stamp(const std::filesystem::path& report, const OtherStudySection& section);
// The paper study's: the "stamp" of REPORT/validation.json.
Stamp read_paper_stamp(const std::filesystem::path& report);

// "made by engine `E` on baseline `B` (8,000 spheres, 5 samples, 2026-11-27)"; a stamp with nothing
// recorded: "not recorded: made before stamps (its engine and baseline are unknown)".
std::string stamp_text(const Stamp& s);
// The same as the first words of a sentence: "Made by engine ..." or "Stamp not recorded: ...".
std::string stamp_sentence(const Stamp& s);
// "8,000 spheres, 3 samples" from a stamp; "size not recorded" without one.
std::string size_of(const Stamp& s);

// What differs between a section's stamp and the paper study's: "baseline", "engine", "baseline and
// engine" or "". Baselines: "" when one of the two is not recorded (nothing to compare), and not
// compared unless `baselines` (not for a study of its own scene). Engines by their source hash, not
// the commit (which changes with every commit whatever it touches): once the paper study's is
// recorded, a stamped section whose results are not all checked to be that engine's differs
// (another source, some results stale, or no source recorded: not checked), and so does a
// section with no stamp at all (`unstamped`; before the paper study's engine source was recorded,
// such a section was only said to be so in its line, "Stamp not recorded").
std::string stamp_difference(const Stamp& section, const Stamp& paper, bool baselines = true);

// What differs between the stamp of the results a report reads (`results`) and that of the
// validation.json whose verdicts it shows (`judged`): stamp_difference's baseline and engine, and
// the spheres and the samples (another profile or another study on the same baseline), each said
// with both values; "" when they agree or `judged` is not stamped (made before stamps).
std::string judged_difference(const Stamp& results, const Stamp& judged);

// The sections, of those whose table key is filled in `values`, whose stamp differs from `paper`
// (stamp_difference), each with what differs: what stamp_sections refuses or heads ⚠.
std::vector<std::pair<OtherStudySection, std::string>> sections_from_elsewhere(const std::filesystem::path& report,
                                                                               const std::map<std::string, std::string>& values,
                                                                               const Stamp& paper);

// The outcome of stamping a report's text.
struct StampedReport {
  std::string text;
  std::vector<std::string> refused;  // one message per section refused (empty: the text can be written)
  std::vector<std::string> other;    // the headings of the sections kept from another baseline
};

// `text` (a filled report) with a stamp line under the heading of every listed section whose
// table key is filled in `values`; a section whose stamp differs from `paper` (stamp_difference)
// is refused, or, with `allow_other`, headed "⚠ from another baseline: ..." with both
// stamps said. Throws std::runtime_error when a listed heading is not in `text` (the list and the
// template disagree). A stamp line already under a heading (a section kept from an earlier
// report) is replaced.
StampedReport stamp_sections(const std::string& text, const std::filesystem::path& report, const std::map<std::string, std::string>& values,
                             const Stamp& paper, bool allow_other);

// The marks stamp_sections puts before a heading's name (section_name takes them off).
// What stamp_difference says of a section with no stamp (read after "another").
inline constexpr const char* unstamped = "engine and baseline (not stamped)";

// The heading mark of a section whose `differs` (stamp_difference) is not the paper study's:
// "⚠ from another baseline: ", "⚠ from another engine: ", ..., "⚠ not stamped: ".
inline std::string other_mark(const std::string& differs) {
  return differs == unstamped ? "⚠ not stamped: " : "⚠ from another " + differs + ": ";
}

}  // namespace validation
