#include "study/posterior_summary.hpp"

#include <stdexcept>

#include "study/json_file.hpp"

namespace validation {

namespace {

std::optional<int> int_at(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j.at(key).is_number_integer() ? std::optional<int>(j.at(key).get<int>()) : std::nullopt;
}

}  // namespace

PosteriorSummary read_posterior_summary(const std::string& file) {
  namespace k = posterior_keys;
  const nlohmann::json j = read_json_file(file);  // errors name the file
  PosteriorSummary p;
  if (!j.is_object() || !j.contains(k::best_set) || !j.at(k::best_set).is_object() || !j.at(k::best_set).contains(k::name) ||
      !j.at(k::best_set).at(k::name).is_string())
    throw std::runtime_error(file + ": " + k::best_set + "." + k::name + ": missing (the best set's name, a string)");
  p.best_set = j.at(k::best_set).at(k::name).get<std::string>();
  if (j.contains(k::stamp)) p.stamp = stamp_from_json(j.at(k::stamp));
  if (j.contains(k::rows_consistent) && j.at(k::rows_consistent).is_object()) {
    const nlohmann::json& rc = j.at(k::rows_consistent);
    if (rc.contains(k::best_set)) p.best_consistent = int_at(rc.at(k::best_set), k::consistent), p.best_judged = int_at(rc.at(k::best_set), k::judged);
    if (rc.contains(k::per_row) && rc.at(k::per_row).is_array())
      for (const nlohmann::json& r : rc.at(k::per_row)) {
        if (!r.is_object() || !r.contains(k::name) || !r.at(k::name).is_string())
          throw std::runtime_error(file + ": " + k::rows_consistent + "." + k::per_row + ": a row without a name");
        PosteriorSummary::Row row{r.at(k::name).get<std::string>(), std::nullopt};
        if (r.contains(k::consistent_at_best_set) && r.at(k::consistent_at_best_set).is_boolean())
          row.consistent_at_best_set = r.at(k::consistent_at_best_set).get<bool>();
        p.rows.push_back(std::move(row));
      }
  }
  return p;
}

}  // namespace validation
