#include "decisions_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <stdexcept>

#include "format.hpp"

namespace validation {

namespace {

std::optional<double> number_at(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? std::optional<double>(j.at(key).get<double>()) : std::nullopt;
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

const DecisionsFile* finding_for(const std::vector<DecisionsFile>& files, const std::string& row) {
  std::vector<const DecisionsFile*> by_size;
  for (const DecisionsFile& f : files) by_size.push_back(&f);
  // Most spheres first, an unrecorded size last; stable: the first given on a tie.
  std::stable_sort(by_size.begin(), by_size.end(), [](const DecisionsFile* a, const DecisionsFile* b) {
    return a->particles.value_or(-1) > b->particles.value_or(-1);
  });
  for (const DecisionsFile* f : by_size)
    if (const auto it = f->rows.find(row); it != f->rows.end() && it->second.judged) return f;
  for (const DecisionsFile* f : by_size)
    if (f->rows.count(row)) return f;
  return nullptr;
}

std::string cause_text(const std::vector<DecisionsFile>& files, const std::string& row) {
  const DecisionsFile* f = finding_for(files, row);
  if (!f) return files.size() > 1 ? "no decisions study has judged this row" : "the decisions study has not judged this row";
  const std::string& explanation = f->rows.at(row).explanation;
  return files.size() > 1 ? size_label(*f) + ": " + explanation : explanation;
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
