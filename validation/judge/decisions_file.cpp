#include "judge/decisions_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "study/format.hpp"

namespace validation {

namespace fs = std::filesystem;

namespace {

std::optional<double> number_at(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? std::optional<double>(j.at(key).get<double>()) : std::nullopt;
}

}  // namespace

std::optional<double> DecisionsFile::Finding::mean_shift(const std::string& name) const {
  const Reading* r = reading(name);
  if (!r || !r->mean || !baseline_mean) return std::nullopt;
  return *r->mean - *baseline_mean;
}

const DecisionsFile::Reading* DecisionsFile::Finding::reading(const std::string& name) const {
  for (const auto& [n, r] : readings)
    if (n == name) return &r;
  return nullptr;
}

DecisionsFile::Finding finding_from_json(const nlohmann::json& row) {
  DecisionsFile::Finding finding;
  finding.group = row.contains("group") && row.at("group").is_string() ? row.at("group").get<std::string>() : "rows";
  finding.baseline_mean = number_at(row, "baseline_mean");
  finding.baseline_sd = number_at(row, "baseline_sd");
  if (row.contains("baseline_verdict") && row.at("baseline_verdict").is_string())
    finding.baseline_verdict = verdict_from_string(row.at("baseline_verdict").get<std::string>());
  if (row.contains("readings"))
    for (const auto& [name, effect] : row.at("readings").items()) {
      DecisionsFile::Reading r;
      r.mean = number_at(effect, "mean");
      r.shift_sd = number_at(effect, "shift_sd");
      if (effect.contains("verdict") && effect.at("verdict").is_string()) r.verdict = verdict_from_string(effect.at("verdict").get<std::string>());
      if (effect.contains("missing_runs")) r.missing_runs = effect.at("missing_runs").get<std::vector<std::string>>();
      finding.readings.emplace_back(name, std::move(r));
    }
  finding.explanation = row.at("explanation").get<std::string>();
  finding.judged = row.at("judged").get<bool>();
  finding.explained_by = row.at("made_consistent_by").get<std::vector<std::string>>();
  finding.outcome = outcome_from_string(row.at("outcome").get<std::string>());
  if ((finding.outcome == Outcome::Explained) != !finding.explained_by.empty())
    throw std::runtime_error("`outcome` '" + std::string(to_string(finding.outcome)) + "' with " +
                             std::to_string(finding.explained_by.size()) + " reading(s) in `made_consistent_by`: 'explained' goes with one or more, any other outcome with none");
  return finding;
}

DecisionsFile read_decisions_file(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot be read");
  // ordered: the readings in the file's order, as the study ran them
  const nlohmann::ordered_json oj = nlohmann::ordered_json::parse(in);
  const nlohmann::json j = oj;  // the same, for lookups
  if (!j.is_object() || !j.contains("rows") || !j.at("rows").is_array()) throw std::runtime_error("has no list of rows");
  DecisionsFile f;
  f.path = file;
  f.schema = j.contains("schema") && j.at("schema").is_number() ? j.at("schema").get<int>() : 1;
  if (f.schema != 2)
    throw std::runtime_error("is of schema " + std::to_string(f.schema) + " (no `schema` key: 1); this tool reads schema 2, which records " +
                             "each row's `judged` and `made_consistent_by` as data: run its decisions study again (compare-runs decisions)");
  if (j.contains("baseline") && j.at("baseline").is_string()) f.baseline = j.at("baseline").get<std::string>();
  if (j.contains("baseline_results") && j.at("baseline_results").is_string()) f.baseline_results = j.at("baseline_results").get<std::string>();
  if (const auto p = number_at(j, "particles")) f.particles = std::lround(*p);
  if (const auto n = number_at(j, "samples")) f.samples = static_cast<std::size_t>(std::lround(*n));
  if (j.contains("stamp")) f.stamp = stamp_from_json(j.at("stamp"));
  if (const auto n = number_at(j, "missing_results")) f.missing_results = static_cast<std::size_t>(std::lround(*n));
  if (oj.contains("settings") && oj.at("settings").is_object())
    for (const auto& [reading, text] : oj.at("settings").items())
      if (text.is_string()) f.settings.emplace_back(reading, text.get<std::string>());
  for (const nlohmann::ordered_json& row : oj.at("rows")) {
    const std::string name = row.at("name").get<std::string>();
    DecisionsFile::Finding finding = finding_from_json(nlohmann::json(row));
    // The readings in the file's order (nlohmann::json sorts its keys).
    if (row.contains("readings")) {
      std::vector<std::pair<std::string, DecisionsFile::Reading>> ordered;
      for (const auto& [reading, effect] : row.at("readings").items())
        if (const DecisionsFile::Reading* r = finding.reading(reading)) ordered.emplace_back(reading, *r);
      finding.readings = std::move(ordered);
    }
    if (!f.rows.count(name)) f.order.push_back(name);
    f.rows[name] = std::move(finding);
  }
  return f;
}

nlohmann::ordered_json decisions_file_json(const DecisionsFile& f) {
  using json = nlohmann::ordered_json;
  const auto value = [](const std::optional<double>& x) { return x && std::isfinite(*x) ? json(*x) : json(nullptr); };
  json rows = json::array();
  for (const std::string& name : f.order) {
    const DecisionsFile::Finding& d = f.rows.at(name);
    json readings = json::object();
    for (const auto& [reading, r] : d.readings) {
      readings[reading] = {{"mean", value(r.mean)}, {"shift_sd", value(r.shift_sd)}, {"verdict", to_string(r.verdict)}};
      if (!r.missing_runs.empty()) readings[reading]["missing_runs"] = r.missing_runs;
    }
    rows.push_back({{"name", name},
                    {"group", d.group},
                    {"baseline_mean", value(d.baseline_mean)},
                    {"baseline_sd", value(d.baseline_sd)},
                    {"baseline_verdict", to_string(d.baseline_verdict)},
                    {"readings", readings},
                    {"judged", d.judged},
                    {"made_consistent_by", d.explained_by},
                    {"outcome", to_string(d.outcome)},
                    {"explanation", d.explanation}});
  }
  json out = {{"schema", 2}, {"baseline", f.baseline}};
  if (!f.baseline_results.empty()) out["baseline_results"] = f.baseline_results;
  out["particles"] = f.particles ? json(*f.particles) : json(nullptr);
  out["samples"] = f.samples.value_or(0);
  out["stamp"] = stamp_json(f.stamp);  // the engine and baseline its numbers come from (the report says them)
  out["shift_unit"] = "max(baseline sd, the row's resolution)";
  if (!f.settings.empty()) {
    json settings = json::object();
    for (const auto& [reading, text] : f.settings) settings[reading] = text;
    out["settings"] = settings;
  }
  out["rows"] = rows;
  out["missing_results"] = f.missing_results;
  return out;
}

std::string size_label(const DecisionsFile& f) {
  if (!f.particles) return "size not recorded";
  std::string s = thousands(*f.particles) + " spheres";
  if (f.samples) s += ", " + std::to_string(*f.samples) + " sample" + (*f.samples == 1 ? "" : "s");
  return s;
}

std::string study_label(const DecisionsFile& f) {
  const fs::path p(f.path);
  const std::string folder = p.parent_path().filename().string();
  return folder.empty() ? p.stem().string() : folder;
}

std::vector<const DecisionsFile*> findings_for(const std::vector<DecisionsFile>& files, const std::string& row) {
  std::vector<const DecisionsFile*> by_size;
  for (const DecisionsFile& f : files) by_size.push_back(&f);
  // Most spheres first, an unrecorded size last; stable: the order given on a tie.
  std::stable_sort(by_size.begin(), by_size.end(), [](const DecisionsFile* a, const DecisionsFile* b) {
    return a->particles.value_or(-1) > b->particles.value_or(-1);
  });
  std::vector<const DecisionsFile*> out;
  for (const DecisionsFile* f : by_size) {
    const auto it = f->rows.find(row);
    if (it == f->rows.end() || !it->second.judged) continue;
    if (out.empty() || f->particles.value_or(-1) == out.front()->particles.value_or(-1)) out.push_back(f);
  }
  std::stable_partition(out.begin(), out.end(), [&](const DecisionsFile* f) { return !f->rows.at(row).explained_by.empty(); });
  if (out.empty())
    for (const DecisionsFile* f : by_size)
      if (f->rows.count(row)) return {f};
  return out;
}

std::optional<std::string> turned_inconsistent(const DecisionsFile& file, const std::string& reading, const Row& row,
                                               const RowResult& full) {
  const auto finding = file.rows.find(row.name);
  if (full.verdict != Verdict::Consistent || finding == file.rows.end() || !finding->second.judged) return std::nullopt;
  const std::optional<double> by = finding->second.mean_shift(reading);
  if (!by || shifted(row, full, *by).verdict != Verdict::Inconsistent) return std::nullopt;
  return row.name + " (" + shift_phrase(shift_in_sd(*by, finding->second.baseline_sd.value_or(0.0), row.resolution)) + ")";
}

std::string cause_text(const std::vector<DecisionsFile>& files, const std::string& row, const TurnsInconsistent& side_effects) {
  const std::vector<const DecisionsFile*> picked = findings_for(files, row);
  if (picked.empty()) return files.size() > 1 ? "no decisions study has judged this row" : "the decisions study has not judged this row";
  std::string text;
  for (const DecisionsFile* f : picked) {
    const DecisionsFile::Finding& finding = f->rows.at(row);
    std::string one = finding.explanation;
    for (const std::string& reading : finding.explained_by) {
      if (!side_effects) break;
      const std::vector<std::string> broken = side_effects(*f, reading);
      if (broken.empty()) {
        one += "; " + reading + " turns no consistent row inconsistent";
        continue;
      }
      one += "; but " + reading + " turns " + std::to_string(broken.size()) + " consistent row" + (broken.size() == 1 ? "" : "s") +
             " inconsistent: ";
      for (std::size_t i = 0; i < broken.size(); ++i) one += (i ? ", " : "") + broken[i];
    }
    if (picked.size() > 1) one = "*" + study_label(*f) + "*: " + one;
    text += (text.empty() ? "" : " · ") + one;
  }
  return files.size() > 1 ? size_label(*picked.front()) + ": " + text : text;
}

std::string cause_line(const std::vector<DecisionsFile>& files, const std::string& row, const TurnsInconsistent& side_effects,
                       std::size_t limit) {
  const std::vector<const DecisionsFile*> picked = findings_for(files, row);
  std::string line;
  if (picked.empty()) {
    line = "no decisions study judged it";
  } else {
    const DecisionsFile& f = *picked.front();
    const DecisionsFile::Finding& finding = f.rows.at(row);
    switch (finding.outcome) {
      case Outcome::Explained: {
        const std::string& reading = finding.explained_by.front();
        line = reading + (finding.explained_by.size() > 1 ? " (+" + std::to_string(finding.explained_by.size() - 1) + ")" : "") +
               " explains it";
        if (side_effects) {
          const std::size_t broken = side_effects(f, reading).size();
          line += broken == 0 ? ", breaks no other row" : ", breaks " + std::to_string(broken) + " other row" + (broken == 1 ? "" : "s");
        }
        break;
      }
      case Outcome::WithinScatter: line = "within scatter; no reading explains it"; break;
      case Outcome::Unexplained: line = "no reading explains it"; break;
      case Outcome::NotJudged: line = "not judged by the decisions study"; break;
      case Outcome::Consistent: line = "consistent in the decisions study"; break;
    }
  }
  // Cut at a code point (a byte that does not continue one, 10xxxxxx, starts one).
  const auto starts = [&](std::size_t i) { return (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80; };
  std::size_t points = 0;
  for (std::size_t i = 0; i < line.size(); ++i) points += starts(i);
  if (points > limit && limit > 0) {
    std::size_t kept = 0, at = 0;  // keep limit - 1 code points, then "…"
    for (; at < line.size(); ++at)
      if (starts(at) && kept++ == limit - 1) break;
    line = line.substr(0, at) + "…";
  }
  return line;
}

}  // namespace validation
