#include "study/manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace validation {

std::vector<ManifestLine> read_manifest(const std::string& dir) {
  const fs::path file = fs::path(dir) / "runs.tsv";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": no manifest (run the study with build/bin/pipeline first)");
  std::vector<ManifestLine> lines;
  std::map<std::string, int> line_of;  // variant and run -> the line that lists it
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, '\t')) f.push_back(cell);
    const std::string at = file.string() + ": line " + std::to_string(no);
    if (f.size() < 8) throw std::runtime_error(at + ": " + std::to_string(f.size()) + " fields, 8 expected");
    // A run listed twice for one variant would count a sample twice; a preparation several variants
    // share is listed once under each of them.
    if (const auto [it, fresh] = line_of.emplace(f[0] + '\t' + f[3], no); !fresh)
      throw std::runtime_error(at + ": the run '" + f[3] + "' again" + (f[0] == "-" ? "" : " for variant '" + f[0] + "'") +
                               " (line " + std::to_string(it->second) + " lists it)");
    lines.push_back({f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[6] == "1", f.size() > 8 && !f[8].empty() ? f[8] : "-",
                     f.size() > 9 ? f[9] : ""});
  }
  return lines;
}

std::string manifest_engine_source(const std::string& dir) {
  std::ifstream in(fs::path(dir) / "runs.tsv");
  std::string line;
  const std::string prefix = "# engine source ";
  if (!std::getline(in, line) || line.rfind(prefix, 0) != 0) return "";
  return line.substr(prefix.size());
}

std::string sample_of(const ManifestLine& line) { return line.seed == "-" ? "" : "seed" + line.seed; }

std::string result_under(const std::string& dir, const ManifestLine& line) {
  return (fs::path(dir) / sample_of(line) / fs::path(line.result).filename()).string();
}

namespace {

std::vector<std::string> distinct(const std::vector<ManifestLine>& manifest, std::string ManifestLine::*column) {
  std::vector<std::string> out;
  for (const ManifestLine& l : manifest)
    if (l.*column != "-" && std::find(out.begin(), out.end(), l.*column) == out.end()) out.push_back(l.*column);
  return out;
}

}  // namespace

std::vector<std::string> variants_of(const std::vector<ManifestLine>& manifest) { return distinct(manifest, &ManifestLine::variant); }
std::vector<std::string> densities_of(const std::vector<ManifestLine>& manifest) { return distinct(manifest, &ManifestLine::density); }
const std::vector<std::string>& paper_densities() {
  static const std::vector<std::string> densities = {"loose", "medium", "dense"};
  return densities;
}

std::vector<std::string> study_densities(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / "runs.tsv", ec)) return paper_densities();
  const std::vector<std::string> listed = densities_of(read_manifest(dir));
  return listed.empty() ? paper_densities() : listed;
}

std::vector<std::string> tests_of(const std::vector<ManifestLine>& manifest) { return distinct(manifest, &ManifestLine::test); }

std::vector<std::string> samples_of(const std::vector<ManifestLine>& manifest) {
  std::vector<long long> seeds;
  for (const ManifestLine& l : manifest) {
    if (l.seed == "-" || l.seed.find_first_not_of("0123456789") != std::string::npos || l.seed.size() > 18) continue;
    if (std::find(seeds.begin(), seeds.end(), std::stoll(l.seed)) == seeds.end()) seeds.push_back(std::stoll(l.seed));
  }
  std::sort(seeds.begin(), seeds.end());
  std::vector<std::string> out;
  for (long long s : seeds) out.push_back("seed" + std::to_string(s));
  if (out.empty()) out.push_back("");
  return out;
}

}  // namespace validation
