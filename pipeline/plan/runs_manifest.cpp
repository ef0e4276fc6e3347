#include "plan/runs_manifest.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace pipeline {

namespace {

const char* const engine_line = "# engine source ";
const char* const columns_line = "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\tinput_hash";

}  // namespace

std::string manifest_text(const RunsManifest& m) {
  std::ostringstream text;
  text << engine_line << m.engine_source << "\n" << columns_line << "\n";
  for (const ManifestEntry& e : m.entries)
    text << e.variant << '\t' << e.density << '\t' << e.test << '\t' << e.run << '\t' << e.result << '\t' << e.starts_from << '\t'
         << (e.may_fail ? 1 : 0) << '\t' << e.settings << '\t' << e.seed << '\t' << e.input_hash << '\n';
  return text.str();
}

RunsManifest read_runs_manifest(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  RunsManifest m;
  std::map<std::string, int> line_of;  // variant and run -> the line that lists it
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (no == 1 && line.rfind(engine_line, 0) == 0) m.engine_source = line.substr(std::string(engine_line).size());
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, '\t');) f.push_back(cell);
    const std::string at = file.string() + ": line " + std::to_string(no);
    if (f.size() < 8) throw std::runtime_error(at + ": " + std::to_string(f.size()) + " fields, 8 expected");
    // A run listed twice for one variant would count a sample twice; a preparation several variants
    // share is listed once under each of them.
    if (const auto [it, fresh] = line_of.emplace(f[0] + '\t' + f[3], no); !fresh)
      throw std::runtime_error(at + ": the run '" + f[3] + "' again" + (f[0] == "-" ? "" : " for variant '" + f[0] + "'") +
                               " (line " + std::to_string(it->second) + " lists it)");
    ManifestEntry e{f[0], f[1], f[2], f[3], f[4], f[5], f[6] == "1", f[7], "-", ""};
    if (f.size() > 8 && !f[8].empty()) e.seed = f[8];
    if (f.size() > 9) e.input_hash = f[9];
    m.entries.push_back(std::move(e));
  }
  return m;
}

}  // namespace pipeline
