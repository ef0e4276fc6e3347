#include "report/other_sections.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "judge/validation_file.hpp"
#include "study/ensemble.hpp"
#include "study/format.hpp"
#include "study/series.hpp"
#include "study/json_file.hpp"
#include "study/settings.hpp"

namespace fs = std::filesystem;

namespace validation {

const std::vector<OtherStudySection>& other_study_sections() {
  static const std::vector<OtherStudySection> list = {
      {"Appendix: What the paper's open choices change", "file.decisions", "decisions/decisions.json", "stamp", ""},
      {"Appendix: Convergence: error against run time", "file.convergence", "convergence/summary.json", "", ""},
      {"Appendix: Stability", "file.stability", "stability/stamp.json", "", "scenes/stability/base.yaml"},
      {"Appendix: Critical state: friction, void ratio and coordination against μ", "file.critical_state", "critical_state/stamp.json", "", ""},
      {"Appendix: Liquefaction: cyclic stress ratio against cycles", "file.liquefaction", "liquefaction/stamp.json", "", ""},
      {"Appendix: Calibration: parameters from references", "file.calibration", "calibration/synthetic_triaxial/stamp.json", "",
       "pipeline/studies/calibration_triaxial.yaml"},
      // Its sets vary the preparation (the readings are its parameters): a baseline of its own by design.
      {"Appendix: Calibration: the paper's open choices, jointly", "file.calibration_open_choices",
       "calibration/paper_open_choices/stamp.json", "", "pipeline/studies/calibration_paper.yaml"},
      {"Appendix: Against published DEM values", "file.literature", "literature/validation.json", "stamp", ""},
      {"Appendix: Thornton's face-centred cubic array", "file.literature_fcc", "literature/fcc/validation.json", "stamp",
       "pipeline/studies/fcc_thornton.yaml"},
      // The parts of the critical-state section other studies feed (compare-runs critical-state
      // --ensemble, --rates): each study's own stamp, beside the section's in its stamp.json.
      {"The critical state on ", "file.critical_state", "critical_state/stamp.json", "ensemble", "", 3, ensemble_stamp_from_literature},
      {"Rate convergence: ", "file.critical_state", "critical_state/stamp.json", "rates", "", 3},
      // The earlier baseline (report --baseline; the Makefile's BASELINE): its validation.json's stamp.
      // Its cell was kept orthorhombic: a baseline of its own by design.
      {"Appendix: This baseline against the earlier one (orthorhombic cell)", "baseline.table", "baselines/orthorhombic_validation.json",
       "stamp", "reports/baselines/orthorhombic_validation.json"},
      // make bench's packings are its own (dem-bench): bench.json's stamp.
      {"Appendix: Performance", "file.bench", "bench.json", "stamp", "engine/bench (dem-bench's packings)", 2, bench_stamp},
  };
  return list;
}

std::string section_shown(const OtherStudySection& section) {
  const auto name = [](const std::string& heading) { return heading.rfind("Appendix: ", 0) == 0 ? heading.substr(10) : heading; };
  if (section.level == 2) return name(section.heading);
  for (const OtherStudySection& s : other_study_sections())
    if (s.level == 2 && s.table_key == section.table_key) return name(s.heading) + " (its " + section.stamp_key + " part)";
  return name(section.heading);
}

namespace {

Stamp stamp_in(const fs::path& file, const std::string& key) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return {};
  const nlohmann::json j = read_json_file(file.string());  // a file there but not JSON: an error, naming it
  if (key.empty()) return stamp_from_json(j);
  return j.is_object() && j.contains(key) ? stamp_from_json(j.at(key)) : Stamp{};
}

std::string read_whole(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The stamp lines stamp_sections writes, to replace one already there.
bool is_stamp_line(const std::string& line) {
  return line.rfind("*Made by engine ", 0) == 0 || line.rfind("*Stamp not recorded", 0) == 0 || line.rfind("*⚠ Made by engine ", 0) == 0;
}

}  // namespace

std::string stamp_sentence(const Stamp& s) {
  std::string text = stamp_text(s);
  if (!s.recorded()) return "Stamp " + text;
  text[0] = 'M';
  return text;
}

std::string size_of(const Stamp& s) {
  if (s.spheres <= 0 || s.samples <= 0) return "size not recorded";
  return thousands(s.spheres) + " spheres, " + std::to_string(s.samples) + " sample" + (s.samples == 1 ? "" : "s");
}

Stamp read_section_stamp(const fs::path& report, const OtherStudySection& section) {
  const Stamp own = stamp_in(report / section.stamp_file, section.stamp_key);
  return own.recorded() || !section.recorded_elsewhere ? own : section.recorded_elsewhere(report);
}

Stamp ensemble_stamp_from_literature(const fs::path& report) {
  const fs::path dat = report / "critical_state" / "ensemble.dat", json = report / "literature" / "validation.json";
  std::error_code ec;
  if (!fs::is_regular_file(dat, ec) || !fs::is_regular_file(json, ec)) return {};
  const Table t = table_from_text(read_whole(dat), dat.string());
  const RecordedValidation record = read_validation_file(json.string());
  const auto equal = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); };
  // A recorded row whose samples' mean and sd are (mean, sd) over n samples.
  const auto recorded = [&](double mean, double sd, double n) {
    for (const RecordedValidation::RecordedRow& r : record.rows) {
      std::vector<double> x;
      for (const RowResult::PerSample& ps : r.samples)
        if (ps.measured.value) x.push_back(*ps.measured.value);
      if (x.size() < 2 || static_cast<double>(x.size()) != n) continue;
      const Spread s = spread(x);
      if (equal(s.mean, mean) && equal(s.sd, sd)) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t.at(i, "mu") == 0 && t.at(i, "loading") == 1 &&
        recorded(t.at(i, "e_cs"), t.at(i, "e_cs_sd"), t.at(i, "samples")) &&
        recorded(t.at(i, "phi_cs"), t.at(i, "phi_cs_sd"), t.at(i, "samples")))
      return stamp_in(json, "stamp");
  return {};
}

Stamp bench_stamp(const fs::path& report) {
  const fs::path file = report / "bench.json";
  std::error_code ec;
  if (!fs::exists(file, ec)) return {};
  const nlohmann::json j = read_json_file(file.string());
  if (j.is_object() && j.contains("stamp")) return stamp_from_json(j.at("stamp"));
  Stamp s;
  if (j.is_object() && j.contains("engine") && j.at("engine").is_object()) {
    const nlohmann::json& e = j.at("engine");
    if (e.contains("version") && e.at("version").is_string()) s.engine = e.at("version").get<std::string>();
    if (e.contains("particles") && e.at("particles").is_number_integer()) s.spheres = e.at("particles").get<long>();
  }
  if (j.is_object() && j.contains("date") && j.at("date").is_string()) s.date = j.at("date").get<std::string>();
  return s;
}

Stamp read_paper_stamp(const fs::path& report) { return stamp_in(report / "validation.json", "stamp"); }

std::string stamp_text(const Stamp& s) {
  if (!s.recorded()) return "not recorded: made before stamps (its engine and baseline are unknown)";
  std::string engine = s.engine.empty() ? "an engine not recorded" : "engine `" + s.engine + "`";
  if (!s.engine_source.empty() || s.other_engine_results > 0) {
    engine += " (source " + (s.engine_source.empty() ? std::string("not recorded") : "`" + s.engine_source + "`");
    if (s.other_engine_results > 0)
      engine += "; " + std::to_string(s.other_engine_results) + (s.other_engine_results == 1 ? " result" : " results") +
                " not made by it from their inputs";
    engine += ")";
  }
  const std::string baseline = s.baseline.empty() ? "a baseline not recorded" : "baseline `" + s.baseline + "`";
  const std::string spheres = s.spheres > 0 ? thousands(s.spheres) + " spheres" : "spheres not recorded";
  const std::string samples = s.samples > 0 ? std::to_string(s.samples) + " sample" + (s.samples == 1 ? "" : "s") : "samples not recorded";
  return "made by " + engine + " on " + baseline + " (" + spheres + ", " + samples + ", " + (s.date.empty() ? "date not recorded" : s.date) + ")";
}

std::string stamp_difference(const Stamp& section, const Stamp& paper, bool baselines) {
  if (!paper.engine_source.empty() && !section.recorded()) return unstamped;
  const bool baseline = baselines && !section.baseline.empty() && !paper.baseline.empty() && section.baseline != paper.baseline;
  const bool engine = !paper.engine_source.empty() && (section.engine_source != paper.engine_source || section.other_engine_results > 0);
  return baseline && engine ? "baseline and engine" : baseline ? "baseline" : engine ? "engine" : "";
}

std::string judged_difference(const Stamp& results, const Stamp& judged) {
  if (!judged.recorded()) return "";
  std::vector<std::string> differs;
  const std::string d = stamp_difference(results, judged);
  const auto field = [&](const std::string& what, const std::string& here, const std::string& there) {
    differs.push_back(what + " (" + (here.empty() ? not_recorded : here) + " here, " + (there.empty() ? not_recorded : there) + " judged)");
  };
  if (d.find("baseline") != std::string::npos) field("baseline", results.baseline, judged.baseline);
  if (d.find("engine") != std::string::npos) field("engine source", results.engine_source, judged.engine_source);
  if (results.spheres > 0 && judged.spheres > 0 && results.spheres != judged.spheres)
    field("spheres", std::to_string(results.spheres), std::to_string(judged.spheres));
  if (results.samples > 0 && judged.samples > 0 && results.samples != judged.samples)
    field("samples", std::to_string(results.samples), std::to_string(judged.samples));
  return joined(differs, ", ");
}

std::vector<std::pair<OtherStudySection, std::string>> sections_from_elsewhere(const fs::path& report,
                                                                               const std::map<std::string, std::string>& values,
                                                                               const Stamp& paper) {
  std::vector<std::pair<OtherStudySection, std::string>> out;
  for (const OtherStudySection& section : other_study_sections()) {
    const auto key = values.find(section.table_key);
    if (key == values.end() || key->second.empty()) continue;
    const std::string differs = stamp_difference(read_section_stamp(report, section), paper, section.own_scene.empty());
    if (!differs.empty()) out.emplace_back(section, differs);
  }
  return out;
}

StampedReport stamp_sections(const std::string& text, const fs::path& report, const std::map<std::string, std::string>& values,
                             const Stamp& paper, bool allow_other) {
  StampedReport out{text, {}, {}};
  for (const OtherStudySection& section : other_study_sections()) {
    const std::string marks = std::string(static_cast<std::size_t>(section.level), '#') + " ";
    // A level-2 heading whole; a part's (level 3) by its start, to the end of its line.
    const std::size_t at = out.text.find("\n" + marks + section.heading + (section.level == 2 ? "\n" : ""));
    if (at == std::string::npos && section.level == 2)
      throw std::runtime_error("the report has no heading '" + marks + section.heading +
                               "' (validation/report/other_sections.cpp lists it: the list and the template disagree)");
    if (at == std::string::npos) continue;  // a part its section does not have (its study not run)
    const std::string heading = out.text.substr(at + 1, out.text.find('\n', at + 1) - at - 1);
    const auto key = values.find(section.table_key);
    if (key == values.end() || key->second.empty()) continue;  // not run yet: the section says so, and has no numbers
    const Stamp stamp = read_section_stamp(report, section);
    const std::string differs = stamp_difference(stamp, paper, section.own_scene.empty());
    // A section of its own scene says whose baseline its numbers are on, as its stamp records it.
    const std::string own = section.own_scene.empty() || !stamp.recorded() || stamp.baseline.empty() ? ""
                            : stamp.baseline == paper.baseline
                                ? " Its baseline is the paper study's, though it may run a scene of its own (`" + section.own_scene + "`)."
                                : " Its baseline is its own scene's (`" + section.own_scene + "`), not the paper study's, by design.";
    std::string line = "*" + stamp_sentence(stamp) + "." + own + "*";
    std::string new_heading = heading;
    if (!differs.empty()) {
      if (!allow_other) {
        out.refused.push_back("section '" + heading.substr(marks.size()) + "' (" + section.stamp_file + ") is from another " + differs +
                              " than the paper study (this section's numbers were " + stamp_text(stamp) + "; the paper study's " +
                              stamp_text(paper) + "); `report --allow-other-baseline` keeps it, headed ⚠");
        continue;
      }
      const std::string mark = other_mark(differs);
      const std::string whole = heading.substr(marks.size());  // the heading as the text has it
      const std::string name = whole.rfind("Appendix: ", 0) == 0 ? whole.substr(10) : whole;
      new_heading = marks + (name == whole ? "" : "Appendix: ") + mark + name;
      line = "*⚠ " + stamp_sentence(stamp) + "; the paper study's numbers were " + stamp_text(paper) + " (kept by `report --allow-other-baseline`)." +
             own + "*";
      out.other.push_back(heading.substr(marks.size()));
    }
    // The heading, a blank line, then the stamp line (one already there replaced).
    const std::size_t body = at + 1 + heading.size() + 1;
    std::size_t rest = body;
    while (rest < out.text.size() && out.text[rest] == '\n') ++rest;
    const std::size_t line_end = out.text.find('\n', rest);
    if (line_end != std::string::npos && is_stamp_line(out.text.substr(rest, line_end - rest))) {
      rest = line_end + 1;
      while (rest < out.text.size() && out.text[rest] == '\n') ++rest;
    }
    out.text = out.text.substr(0, at + 1) + new_heading + "\n\n" + line + "\n\n" + out.text.substr(rest);
  }
  return out;
}

}  // namespace validation
