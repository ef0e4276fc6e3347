#include "config/study_copy.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "io/atomic_file.hpp"

namespace pipeline {

namespace fs = std::filesystem;

namespace {

// A path key of a study and its value: `output: ../../results/study`,
// `scene: ../../scenes/tests/test1.yaml`, `particles.csv: "my.csv"`, `{csv: x.csv, ...}`. Group 1
// is everything before the value, 2 the key, 3 the quote, 4 the value.
const std::regex path_value(R"re(((?:^|[\s{,])["']?(output|preparation|scene|csv|state|particles\.csv|particles\.state)["']?\s*:\s*)(["']?)([^"',}\s#][^"',}\s]*)\3)re");
const std::regex name_line(R"re(^name\s*:.*$)re");

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw dem::ConfigError(file + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The part of a YAML line that is not a comment (a # at the start or after a blank, outside quotes).
std::size_t comment_start(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) { if (c == quote) quote = 0; continue; }
    if (c == '"' || c == '\'') quote = c;
    else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) return i;
  }
  return line.size();
}

std::string rewrite_line(const std::string& line, const fs::path& from_dir, const fs::path& to_dir, const std::string& stem,
                         const std::string& output) {
  const std::size_t cut = comment_start(line);
  const std::string code = line.substr(0, cut), comment = line.substr(cut);
  if (std::regex_match(code, name_line)) return "name: " + stem + (comment.empty() ? "" : "   " + comment);
  std::string out;
  auto begin = code.cbegin();
  for (std::sregex_iterator it(code.begin(), code.end(), path_value), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(begin, m[0].first);
    std::string value = m[4].str();
    if (m[2].str() == "output") {
      value = output;
    } else if (!fs::path(value).is_absolute()) {
      const fs::path target = fs::absolute(from_dir / value).lexically_normal();
      value = target.lexically_relative(to_dir).generic_string();
      if (value.empty()) value = target.string();
    }
    out += m[1].str() + m[3].str() + value + m[3].str();
    begin = m[0].second;
  }
  out.append(begin, code.cend());
  return out + comment;
}

}  // namespace

std::string study_copy_text(const std::string& text, const std::string& from_file, const std::string& to_file,
                            const CopyChanges& changes) {
  const fs::path from_dir = fs::absolute(fs::path(from_file)).lexically_normal().parent_path();
  const fs::path to_dir = fs::absolute(fs::path(to_file)).lexically_normal().parent_path();
  const std::string stem = fs::path(to_file).stem().string();
  const std::string output = changes.output.empty() ? "results/" + stem
                                                     : fs::absolute(changes.output).lexically_normal().lexically_relative(to_dir).generic_string();
  std::ostringstream out;
  out << "# Written by `pipeline new` from " << fs::absolute(fs::path(from_file)).lexically_normal().string()
      << ": its paths rewritten to resolve from this file's folder, its results in " << output
      << (changes.output.empty() ? " beside it" : "") << (changes.variants.empty() ? "" : ", its variants given at the end") << ".\n";
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!changes.variants.empty() && std::regex_search(line, std::regex(R"(^variants\s*:)")))
      throw dem::ConfigError(from_file + ": has variants of its own; a copy with --variant adds none to them");
    out << rewrite_line(line, from_dir, to_dir, stem, output) << "\n";
  }
  if (!changes.variants.empty()) out << "variants:\n";
  for (const std::string& v : changes.variants) {
    if (v.find_first_not_of(" \t") == std::string::npos || v.find('\n') != std::string::npos)
      throw dem::ConfigError("--variant '" + v + "': one variant on one line, a YAML mapping such as {name: v, set: {material.friction: 0.3}}");
    out << "  - " << v << "\n";
  }
  return out.str();
}

void write_study_copy(const std::string& from_file, const std::string& to_file, bool force, const CopyChanges& changes) {
  const fs::path to(to_file);
  if (to.extension() != ".yaml" && to.extension() != ".yml")
    throw dem::ConfigError(to_file + ": a study file must end in .yaml or .yml");
  std::error_code ec;
  if (fs::exists(to, ec) && !force) throw dem::ConfigError(to_file + ": exists; choose another name or pass --force");
  if (fs::exists(to, ec) && fs::equivalent(to, fs::path(from_file), ec))
    throw dem::ConfigError(to_file + ": is the study it would copy (" + from_file + ")");
  const std::string copy = study_copy_text(read_text(from_file), from_file, to_file, changes);
  std::string tmp;  // beside the copy, so that its paths resolve as the copy's will
  try {
    tmp = dem::write_temp_beside(to_file, copy);
  } catch (const std::runtime_error& e) {
    throw dem::ConfigError(e.what());
  }
  try {
    (void)load_study(tmp);  // every path of the copy resolves, every key is checked
    dem::rename_durably(tmp, to_file);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

std::string find_study(const std::string& from, const std::vector<std::string>& folders) {
  std::error_code ec;
  if (fs::is_regular_file(from, ec)) return from;
  std::set<std::string> names;
  for (const std::string& folder : folders) {
    const fs::path candidate = fs::path(folder) / (from + ".yaml");
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
    for (const auto& e : fs::directory_iterator(folder, ec))
      if (e.path().extension() == ".yaml") names.insert(e.path().stem().string());
  }
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw dem::ConfigError("--from " + from + ": neither a study file nor a shipped study" +
                         (known.empty() ? std::string(" (no shipped studies found)") : " (shipped: " + known + ")"));
}

}  // namespace pipeline
