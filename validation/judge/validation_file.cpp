#include "judge/validation_file.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "judge/decisions_file.hpp"
#include "study/json_file.hpp"

namespace validation {

namespace {

// j[key] of `type`, else a message naming `where`.key.
const nlohmann::json& member(const nlohmann::json& j, const std::string& key, nlohmann::json::value_t type, const std::string& where,
                             const char* what) {
  if (!j.is_object() || !j.contains(key))
    throw std::runtime_error(where + (where.empty() ? "" : ".") + key + ": missing (" + what + ")");
  const nlohmann::json& v = j.at(key);
  const bool ok = type == nlohmann::json::value_t::number_float ? v.is_number() : v.type() == type;
  if (!ok) throw std::runtime_error(where + (where.empty() ? "" : ".") + key + ": is " + v.type_name() + ", expected " + what);
  return v;
}

std::vector<std::string> strings(const nlohmann::json& j, const std::string& key, const char* what) {
  const nlohmann::json& a = member(j, key, nlohmann::json::value_t::array, "", what);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_string()) throw std::runtime_error(key + "[" + std::to_string(i) + "]: is " + a[i].type_name() + ", expected a string");
    out.push_back(a[i].get<std::string>());
  }
  return out;
}

}  // namespace

std::string keep_densities(std::vector<Row>& rows, const std::vector<std::string>& densities) {
  if (densities.empty()) return "";
  std::set<std::string> known;
  for (const Row& r : rows)
    if (!r.density.empty()) known.insert(r.density);
  for (const std::string& d : densities)
    if (!known.count(d)) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      return "no row of the reference file is of density '" + d + "' (its densities: " + list + ")";
    }
  erase_other_densities(rows, densities);
  return "";
}

RecordedValidation::Borrowed borrowed_density(const std::string& argument, const std::vector<std::string>& judged,
                                              const std::vector<Row>& rows, const std::string& references) {
  const std::size_t a = argument.find(':'), b = a == std::string::npos ? a : argument.find(':', a + 1);
  if (b == std::string::npos || a == 0 || b == a + 1 || b + 1 == argument.size())
    throw std::runtime_error("'" + argument + "': expected DENSITY:READING:FILE (e.g. loose:contact_dashpots:reports/readings/dashpot/decisions.json)");
  const RecordedValidation::Borrowed borrowed{argument.substr(0, a), argument.substr(a + 1, b - a - 1), argument.substr(b + 1)};
  if (judged.empty() || std::find(judged.begin(), judged.end(), borrowed.density) != judged.end())
    throw std::runtime_error("'" + borrowed.density + "' is judged from this study's runs: a borrowed density is one --densities leaves out");
  const DecisionsFile file = read_decisions_file(borrowed.decisions);  // its errors name the file
  const bool has = std::any_of(rows.begin(), rows.end(), [&](const Row& r) {
    return r.density == borrowed.density && file.rows.count(r.name) && file.rows.at(r.name).reading(borrowed.reading);
  });
  if (!has)
    throw std::runtime_error(borrowed.decisions + " has no reading '" + borrowed.reading + "' on a row of density '" + borrowed.density +
                             "' of " + references);
  return borrowed;
}

RecordedValidation read_validation_file(const std::string& file) {
  const nlohmann::json j = read_json_file(file);  // "<file>: cannot be read", "<file>: not JSON (...)"
  using t = nlohmann::json::value_t;
  try {
    if (!j.is_object()) throw std::runtime_error("is " + std::string(j.type_name()) + ", expected an object (validate's validation.json)");
    RecordedValidation r;
    r.profile = member(j, "profile", t::string, "", "the profile's name").get<std::string>();
    if (j.contains("references")) r.references = member(j, "references", t::string, "", "the reference file's path").get<std::string>();
    r.samples = strings(j, "samples", "an array of the samples' names");
    r.missing_samples = strings(j, "missing_samples", "an array of names");
    r.missing_results = strings(j, "missing_results", "an array of files");
    if (j.contains("judged_from")) {
      const nlohmann::json& from = member(j, "judged_from", t::object, "", "what the rows were judged from");
      if (from.contains("densities")) r.densities = strings(from, "densities", "an array of densities");
      if (from.contains("variants")) r.variants = strings(from, "variants", "an array of variants");
      if (from.contains("borrowed")) {
        const nlohmann::json& b = member(from, "borrowed", t::array, "judged_from", "an array of {density, reading, decisions}");
        for (std::size_t i = 0; i < b.size(); ++i) {
          const std::string at = "judged_from.borrowed[" + std::to_string(i) + "]";
          r.borrowed.push_back({member(b[i], "density", t::string, at, "a density").get<std::string>(),
                                member(b[i], "reading", t::string, at, "a reading of the decisions file").get<std::string>(),
                                member(b[i], "decisions", t::string, at, "a decisions.json").get<std::string>()});
        }
      }
    }
    r.stamp = stamp_from_json(j.contains("stamp") ? j.at("stamp") : nlohmann::json());
    const nlohmann::json& rows = member(j, "rows", t::array, "", "an array of the judged rows");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::string at = "rows[" + std::to_string(i) + "]";
      RecordedValidation::RecordedRow row;
      row.name = member(rows[i], "name", t::string, at, "the row's name").get<std::string>();
      row.density = member(rows[i], "density", t::string, at, "the density whose runs it read").get<std::string>();
      const nlohmann::json& per = member(rows[i], "per_sample", t::array, at, "an array of {sample, value, note}");
      for (std::size_t k = 0; k < per.size(); ++k) {
        const std::string where = at + ".per_sample[" + std::to_string(k) + "]";
        RowResult::PerSample ps;
        ps.sample = member(per[k], "sample", t::string, where, "the sample's name").get<std::string>();
        if (!per[k].contains("value")) throw std::runtime_error(where + ".value: missing (a number, or null for none)");
        const nlohmann::json& v = per[k].at("value");
        if (v.is_number()) ps.measured.value = v.get<double>();
        else if (!v.is_null()) throw std::runtime_error(where + ".value: is " + std::string(v.type_name()) + ", expected a number or null");
        if (per[k].contains("note")) ps.measured.note = member(per[k], "note", t::string, where, "a string").get<std::string>();
        if (per[k].contains("misfit")) ps.measured.misfit = member(per[k], "misfit", t::string, where, "a string").get<std::string>();
        row.samples.push_back(std::move(ps));
      }
      r.rows.push_back(std::move(row));
    }
    return r;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
}

std::vector<RejudgedRow> judge_recorded(const RecordedValidation& record, const std::vector<Row>& rows, const std::string& file,
                                        const std::string& references) {
  std::map<std::string, const RecordedValidation::RecordedRow*> by_name;
  for (const auto& r : record.rows)
    if (!by_name.emplace(r.name, &r).second) throw std::runtime_error(file + ": the row '" + r.name + "' twice");
  std::vector<RejudgedRow> out;
  for (const Row& row : rows) {
    const auto it = by_name.find(row.name);
    if (it == by_name.end())
      throw std::runtime_error(file + " has no row '" + row.name + "' of " + references + " (profile " + record.profile +
                               "): it was judged by other rows; validate it from the results");
    out.push_back({row, it->second->density, judge_values(row, it->second->samples)});  // rows.hpp
    by_name.erase(it);
  }
  if (!by_name.empty())
    throw std::runtime_error(file + " has a row " + references + " does not (profile " + record.profile + "): '" + by_name.begin()->first +
                             "'");
  return out;
}

}  // namespace validation
