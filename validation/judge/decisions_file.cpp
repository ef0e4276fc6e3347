#include "judge/decisions_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

#include "study/format.hpp"

namespace validation {

namespace fs = std::filesystem;

namespace {

std::optional<double> number_at(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? std::optional<double>(j.at(key).get<double>()) : std::nullopt;
}

// The readings explain() names after "consistent under ": "a (-2.1 sd, t = 2.23), b (...), its
// shift of the mean applied ..." -> {a, b} (each name followed by its parenthesised shift).
std::vector<std::string> explaining_readings(const std::string& explanation) {
  const std::string lead = "consistent under ";
  if (explanation.rfind(lead, 0) != 0) return {};
  static const std::regex named(R"((?:^|\), )([A-Za-z0-9_.+-]+) \()");
  const std::string rest = explanation.substr(lead.size());
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(rest.begin(), rest.end(), named); it != std::sregex_iterator(); ++it) out.push_back((*it)[1].str());
  return out;
}

}  // namespace

DecisionsFile read_decisions_file(const std::string& file, const std::vector<Row>& rows) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot be read");
  const nlohmann::json j = nlohmann::json::parse(in);
  DecisionsFile f;
  f.path = file;
  if (const auto p = number_at(j, "particles")) f.particles = std::lround(*p);
  if (const auto n = number_at(j, "samples")) f.samples = static_cast<std::size_t>(std::lround(*n));
  const bool restate = !j.contains("schema");  // written before the floor and the phrase
  std::map<std::string, double> resolution;
  for (const Row& r : rows) resolution[r.name] = r.resolution;
  for (const nlohmann::json& row : j.at("rows")) {
    const std::string name = row.at("name").get<std::string>();
    DecisionsFile::Finding finding;
    finding.explanation = row.at("explanation").get<std::string>();
    finding.judged = row.contains("judged") ? row.at("judged").get<bool>() : finding.explanation.rfind("not judged", 0) != 0;
    finding.explained_by = row.contains("made_consistent_by") ? row.at("made_consistent_by").get<std::vector<std::string>>()
                                                              : explaining_readings(finding.explanation);
    if (const auto base = number_at(row, "baseline_mean"); base && row.contains("readings"))
      for (const auto& [reading, effect] : row.at("readings").items())
        if (const auto mean = number_at(effect, "mean")) finding.mean_shift[reading] = *mean - *base;
    finding.baseline_sd = number_at(row, "baseline_sd").value_or(0.0);
    if (restate) finding.explanation = restate_shifts(finding.explanation, row, resolution.count(name) ? resolution.at(name) : 0.0);
    f.rows[name] = std::move(finding);
  }
  return f;
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
  const auto by = finding->second.mean_shift.find(reading);
  if (by == finding->second.mean_shift.end() || shifted(row, full, by->second).verdict != Verdict::Inconsistent) return std::nullopt;
  return row.name + " (" + shift_phrase(shift_in_sd(by->second, finding->second.baseline_sd, row.resolution)) + ")";
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
    const std::string& e = finding.explanation;
    if (!finding.explained_by.empty()) {
      const std::string& reading = finding.explained_by.front();
      line = reading + (finding.explained_by.size() > 1 ? " (+" + std::to_string(finding.explained_by.size() - 1) + ")" : "") +
             " explains it";
      if (side_effects) {
        const std::size_t broken = side_effects(f, reading).size();
        line += broken == 0 ? ", breaks no other row" : ", breaks " + std::to_string(broken) + " other row" + (broken == 1 ? "" : "s");
      }
    } else if (e.rfind("no reading does: within scatter", 0) == 0) {
      line = "within scatter; no reading explains it";
    } else if (e.rfind("unexplained", 0) == 0) {
      line = "no reading explains it";
    } else if (e.rfind("not judged", 0) == 0) {
      line = "not judged by the decisions study";
    } else if (e.rfind("consistent on", 0) == 0) {
      line = "consistent in the decisions study";
    } else {
      line = "see the cause in full";
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

std::string restate_shifts(const std::string& explanation, const nlohmann::json& row, double resolution) {
  // "<reading> (<anything but parentheses><number>[ (beyond ±10)] sd": the forms explain() wrote.
  static const std::regex shift(R"(([A-Za-z0-9_.+-]+) \(([^()]*?)([-+]?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?)(?: \(beyond ±10\))? sd)");
  std::string out;
  auto from = explanation.cbegin();
  for (std::smatch m; std::regex_search(from, explanation.cend(), m, shift); from = m[0].second) {
    const std::string reading = m[1].str();
    double z = std::stod(m[3].str());
    const nlohmann::json* readings = row.contains("readings") ? &row.at("readings") : nullptr;
    if (readings && readings->contains(reading)) {
      const auto mean = number_at(readings->at(reading), "mean");
      const auto base = number_at(row, "baseline_mean");
      const double sd = number_at(row, "baseline_sd").value_or(0.0);
      if (mean && base) {
        const double again = shift_in_sd(*mean - *base, sd, resolution);
        if (std::isfinite(again)) z = again;
      }
    }
    out.append(from, m[0].first);
    out += reading + " (" + m[2].str() + shift_phrase(z);
  }
  out.append(from, explanation.cend());
  return out;
}

}  // namespace validation
