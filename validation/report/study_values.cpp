#include "report/study_values.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "study/json_file.hpp"

namespace fs = std::filesystem;

namespace validation {

void write_study_values(const fs::path& report, const StudyValues& s) {
  nlohmann::ordered_json j;
  j["stamp"] = stamp_json(s.stamp);
  j["results"] = s.results;
  j["values"] = s.values;  // a std::map: keys sorted, so the file diffs well from one run to the next
  dem::write_file_atomically((report / study_values_file).string(), j.dump(1) + "\n");
}

std::optional<StudyValues> read_study_values(const fs::path& report) {
  const fs::path file = report / study_values_file;
  std::error_code ec;
  if (!fs::exists(file, ec)) return std::nullopt;
  const nlohmann::json j = read_json_file(file.string());  // not JSON: an error naming the file
  const auto bad = [&](const std::string& why) { return std::runtime_error(file.string() + ": " + why + " (written by build/bin/report; write it again with the results here)"); };
  if (!j.is_object() || !j.contains("values") || !j.at("values").is_object()) throw bad("no \"values\" object");
  StudyValues s;
  s.stamp = stamp_from_json(j.value("stamp", nlohmann::json()));
  s.results = j.value("results", std::string());
  for (const auto& [key, value] : j.at("values").items()) {
    if (!value.is_string()) throw bad("value \"" + key + "\" is not text");
    s.values[key] = value.get<std::string>();
  }
  return s;
}

}  // namespace validation
