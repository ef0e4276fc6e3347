#include "plan/reuse.hpp"

#include <filesystem>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/result_file.hpp"

namespace pipeline {

std::string reuse_problem(const std::string& result, const std::string& hash) {
  std::error_code ec;
  if (!std::filesystem::exists(result, ec)) return "not run yet";
  if (!std::filesystem::is_regular_file(result, ec)) return "not a regular file";
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    if (const std::string why = dem::result_problem(f); !why.empty()) return "not a complete result (" + why + ")";
    if (!dem::h5::has_attribute(f, "input_hash") || dem::h5::get_string_attribute(f, "input_hash") != hash)
      return "written for other inputs";
    return "";
  } catch (const std::exception& e) {
    return std::string("unreadable, truncated or corrupt (") + e.what() + ")";
  }
}

bool up_to_date(const std::string& result, const std::string& hash) { return reuse_problem(result, hash).empty(); }

std::string outcome_file(const std::string& result) { return result + ".outcome"; }

std::optional<Stop> read_stop(const std::string& result) {
  try {
    const YAML::Node n = dem::load_yaml(outcome_file(result));
    Stop s;
    s.input_hash = n["input_hash"].as<std::string>();
    s.exit_code = n["exit_code"].as<int>();
    s.message = n["message"].as<std::string>();
    return s;
  } catch (const std::exception&) {
    return std::nullopt;  // missing or unreadable: the run is run again
  }
}

void write_stop(const std::string& result, const Stop& stop) {
  YAML::Emitter e;
  e << YAML::BeginMap << YAML::Key << "input_hash" << YAML::Value << stop.input_hash << YAML::Key << "exit_code"
    << YAML::Value << stop.exit_code << YAML::Key << "outcome" << YAML::Value
    << (stop.exit_code == 2 ? "refused" : "stopped") << YAML::Key << "message" << YAML::Value
    << YAML::DoubleQuoted << stop.message << YAML::EndMap;
  dem::write_file_atomically(outcome_file(result), std::string(e.c_str()) + "\n");  // never half an outcome
}

std::optional<Stop> recorded_stop(const std::string& result, const std::string& hash) {
  auto s = read_stop(result);
  if (s && s->input_hash == hash) return s;
  return std::nullopt;
}

}  // namespace pipeline
