#include "sections/stability_summary.hpp"

#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "sections/percent.hpp"
#include "study/json_file.hpp"
#include "study/markdown_table.hpp"

namespace sections {

namespace {

constexpr int schema = 1;

nlohmann::ordered_json optional_number(const std::optional<double>& x) { return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(); }

// A largest value as the table gives it: 3 significant digits; "—" when there is none.
std::string largest_text(const std::optional<double>& x) {
  if (!x) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", *x);
  return buf;
}

}  // namespace

std::string stability_summary_json(const std::vector<StabilityCase>& cases) {
  nlohmann::ordered_json j;
  j["schema"] = schema;
  j["cases"] = nlohmann::ordered_json::array();
  for (const StabilityCase& c : cases)
    j["cases"].push_back({{"name", c.name},
                          {"settings", c.settings},
                          {"acceptable", c.acceptable},
                          {"outcome", c.outcome},
                          {"steps", c.steps},
                          {"dt_over_critical", optional_number(c.dt_over_critical)},
                          {"dt_over_contact_critical", optional_number(c.dt_over_contact_critical)},
                          {"closure", optional_number(c.closure)},
                          {"message", c.message}});
  return j.dump(1) + "\n";
}

std::vector<StabilityCase> read_stability_summary(const std::string& file) {
  const nlohmann::json j = validation::read_json_file(file);  // not JSON: an error naming the file
  const auto bad = [&](const std::string& why) { return std::runtime_error(file + ": " + why + " (written by compare-runs stability)"); };
  if (!j.is_object() || !j.contains("schema") || j.at("schema") != schema) throw bad("schema must be " + std::to_string(schema));
  if (!j.contains("cases") || !j.at("cases").is_array()) throw bad("no \"cases\" list");
  std::vector<StabilityCase> out;
  for (std::size_t i = 0; i < j.at("cases").size(); ++i) {
    const nlohmann::json& c = j.at("cases")[i];
    const std::string at = "cases[" + std::to_string(i) + "].";
    const auto member = [&](const char* key) -> const nlohmann::json& {
      if (!c.is_object() || !c.contains(key)) throw bad(at + key + ": missing");
      return c.at(key);
    };
    const auto text = [&](const char* key) {
      if (!member(key).is_string()) throw bad(at + key + ": not text");
      return member(key).get<std::string>();
    };
    const auto number = [&](const char* key) -> std::optional<double> {
      const nlohmann::json& v = member(key);
      if (v.is_null()) return std::nullopt;
      if (!v.is_number()) throw bad(at + key + ": neither a number nor null");
      return v.get<double>();
    };
    StabilityCase s;
    s.name = text("name"), s.settings = text("settings"), s.outcome = text("outcome"), s.message = text("message");
    if (!member("acceptable").is_boolean()) throw bad(at + "acceptable: not true or false");
    s.acceptable = member("acceptable").get<bool>();
    if (!member("steps").is_number_integer()) throw bad(at + "steps: not a whole number");
    s.steps = member("steps").get<long>();
    s.dt_over_critical = number("dt_over_critical"), s.dt_over_contact_critical = number("dt_over_contact_critical");
    s.closure = number("closure");
    out.push_back(std::move(s));
  }
  return out;
}

std::string stability_table(const std::vector<StabilityCase>& cases) {
  // The time step against the law's critical step as the engine checks it, and against the
  // leapfrog limit at the stiffest contact seen (for Hertz, whose stiffness grows with the overlap,
  // the limit at the largest overlap of the run; the same for the linear laws once in contact).
  validation::MarkdownTable table({"case", "settings", "outcome", "steps (last row written)", "dt / critical (engine)",
                                   "dt / critical at the stiffest contact seen", "energy closure error", "message"});
  for (const StabilityCase& c : cases)
    table.row({c.name, c.settings, (c.acceptable ? "" : "⚠ ") + c.outcome, std::to_string(c.steps), largest_text(c.dt_over_critical),
               largest_text(c.dt_over_contact_critical), c.closure ? percent(*c.closure) : "—", c.message});
  return table.text();
}

}  // namespace sections
