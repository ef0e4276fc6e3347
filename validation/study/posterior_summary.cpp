#include "study/posterior_summary.hpp"

#include <stdexcept>

#include "study/json_file.hpp"

namespace validation {

std::optional<Choice> choice_from(const std::string& word) {
  for (std::size_t i = 0; i < std::size(choice_names); ++i)
    if (word == choice_names[i]) return static_cast<Choice>(i);
  return std::nullopt;
}

std::string chosen_words(Choice chosen) {
  switch (chosen) {
    case Choice::best: return ", the posterior's best prediction among the sets scored";
    case Choice::probe: return ", a new set where the posterior's prediction is best (run at the first size too)";
    case Choice::named: return ", a set of the first size the calibration file names (run once the iterations end)";
  }
  return "";
}

namespace {

std::optional<int> int_at(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j.at(key).is_number_integer() ? std::optional<int>(j.at(key).get<int>()) : std::nullopt;
}

// j[key] of type T, else the error naming the file and where.
template <class T>
T required(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw std::runtime_error(where + "." + key + ": missing");
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(where + "." + key + ": of the wrong type");
  }
}

std::vector<PosteriorSummary::Part::Confirmed> confirmed_of(const nlohmann::json& size, const std::string& where) {
  namespace k = posterior_keys;
  std::vector<PosteriorSummary::Part::Confirmed> out;
  if (!size.contains(k::confirmed)) return out;
  for (const nlohmann::json& c : size.at(k::confirmed)) {
    const std::string word = required<std::string>(c, k::chosen, where + "." + k::confirmed);
    const std::optional<Choice> chosen = choice_from(word);
    if (!chosen) throw std::runtime_error(where + "." + k::confirmed + "." + k::chosen + ": '" + word + "' is not best, probe or named");
    PosteriorSummary::Part::Confirmed x{required<std::string>(c, k::set, where + "." + k::confirmed), *chosen,
                                        required<double>(c, k::predicted_probability, where + "." + k::confirmed), {}};
    for (const nlohmann::json& r : required<nlohmann::json>(c, k::rows, where + "." + k::confirmed)) {
      PosteriorSummary::Part::Confirmed::Row row{required<std::string>(r, k::name, where + ".confirmed.rows"),
                                                 required<double>(r, k::predicted_probability, where + ".confirmed.rows"), std::nullopt,
                                                 std::nullopt};
      if (r.contains(k::consistent) && r.at(k::consistent).is_boolean()) row.consistent = r.at(k::consistent).get<bool>();
      if (r.contains(k::mean))
        row.measured = {required<double>(r, k::mean, where + ".confirmed.rows"), required<double>(r, k::sd, where + ".confirmed.rows"),
                        required<int>(r, k::samples, where + ".confirmed.rows")};
      x.rows.push_back(std::move(row));
    }
    out.push_back(std::move(x));
  }
  return out;
}

// The parts of the largest size: each entry of largest_size_parts with its size's stamp and
// confirmed sets (the size of the same densities).
std::vector<PosteriorSummary::Part> parts_of(const nlohmann::json& j, const std::string& file) {
  namespace k = posterior_keys;
  std::vector<PosteriorSummary::Part> out;
  if (!j.contains(k::largest_size_parts)) return out;
  for (const nlohmann::json& x : j.at(k::largest_size_parts)) {
    const std::string where = file + ": " + k::largest_size_parts;
    PosteriorSummary::Part part;
    part.densities = required<std::vector<std::string>>(x, k::densities, where);
    if (x.contains(k::rows_consistent)) {
      const nlohmann::json& rc = x.at(k::rows_consistent);
      part.scored_sets = required<int>(rc, k::scored_sets, where + "." + k::rows_consistent);
      for (const nlohmann::json& r : required<nlohmann::json>(rc, k::per_row, where + "." + k::rows_consistent)) {
        PosteriorSummary::Part::Row row{required<std::string>(r, k::name, where + ".per_row"), required<int>(r, k::consistent_sets, where + ".per_row"),
                                        required<int>(r, k::judged_sets, where + ".per_row"), int_at(r, k::most_rows_consistent_with_it), std::nullopt};
        if (r.contains(k::set_with_most_rows)) row.set_with_most = r.at(k::set_with_most_rows).get<std::string>();
        part.rows.push_back(std::move(row));
      }
    }
    for (const nlohmann::json& size : required<nlohmann::json>(j, k::sizes, file))
      if (size.contains(k::densities) && size.at(k::densities).get<std::vector<std::string>>() == part.densities) {
        if (size.contains(k::stamp)) part.stamp = stamp_from_json(size.at(k::stamp));
        part.confirmed = confirmed_of(size, file + ": " + k::sizes);
        if (size.contains(k::reach)) {
          const nlohmann::json& x = size.at(k::reach);
          const std::string at = file + ": " + k::sizes + "." + k::reach;
          PosteriorSummary::Part::Reach reach{required<int>(x, k::points, at), {}, required<double>(x, k::largest_probability_all_rows, at)};
          for (const nlohmann::json& r : required<nlohmann::json>(x, k::rows, at))
            reach.rows.emplace_back(required<std::string>(r, k::name, at + ".rows"), required<double>(r, k::largest_probability, at + ".rows"));
          part.reach = std::move(reach);
        }
      }
    out.push_back(std::move(part));
  }
  return out;
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
  p.parts = parts_of(j, file);
  return p;
}

}  // namespace validation
