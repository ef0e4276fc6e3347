#pragma once
// JSON files the tools read (validation.json of a baseline, decisions.json), parsed by
// nlohmann-json with every error naming the file.
#include <string>

#include <nlohmann/json.hpp>

namespace validation {

// The file's JSON; throws std::runtime_error "<file>: cannot be read" or "<file>: not JSON (<the
// parser's message: byte and what it expected>)".
nlohmann::json read_json_file(const std::string& file);

}  // namespace validation
