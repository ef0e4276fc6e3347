#include "study/manifest.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace validation {

std::vector<ManifestLine> read_manifest(const std::string& dir) {
  const fs::path file = fs::path(dir) / "runs.tsv";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw std::runtime_error(file.string() + ": no manifest (run the study with build/bin/pipeline first)");
  return pipeline::read_runs_manifest(file).entries;
}

std::string manifest_engine_source(const std::string& dir) {
  const fs::path file = fs::path(dir) / "runs.tsv";
  std::error_code ec;
  return fs::is_regular_file(file, ec) ? pipeline::read_runs_manifest(file).engine_source : std::string();
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
