#include "study/stamp.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "study/baseline.hpp"
#include "study/manifest.hpp"
#include "study/results.hpp"
#include "study/utc_day.hpp"

namespace fs = std::filesystem;

namespace validation {
namespace {

// The day a file was last written, UTC ("" if it cannot be told).
std::string day_written(const std::string& file) {
  std::error_code ec;
  const auto t = fs::last_write_time(file, ec);
  if (ec) return "";
  const auto sys = std::chrono::time_point_cast<std::chrono::system_clock::duration>(t - fs::file_time_type::clock::now() +
                                                                                       std::chrono::system_clock::now());
  return utc_day(std::chrono::system_clock::to_time_t(sys));
}

std::string text_field(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j.at(key).is_string()) return "";
  const std::string s = j.at(key).get<std::string>();
  return s == not_recorded ? "" : s;
}

long count_field(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? j.at(key).get<long>() : 0;
}

}  // namespace

Stamp stamp_of_results(const std::string& dir, const std::string& variant, const std::string& baseline_results) {
  Stamp s = stamp_of_results(dir, variant);
  if (!baseline_results.empty()) s.baseline = stamp_of_results(baseline_results).baseline;
  return s;
}

Stamp stamp_of_results(const std::string& dir, const std::string& variant) {
  const std::vector<ManifestLine> manifest = read_manifest(dir);  // throws naming the folder
  Stamp s;
  const std::vector<std::string> samples = samples_of(manifest);
  s.samples = static_cast<long>(samples.size());
  // The first preparation of the first sample (seed1, or the study's one sample).
  const bool has_variant = std::any_of(manifest.begin(), manifest.end(), [&](const ManifestLine& l) { return l.variant == variant; });
  const ManifestLine* first = nullptr;
  for (const ManifestLine& l : manifest)
    if (l.test == "-" && sample_of(l) == samples.front() && (!has_variant || l.variant == variant)) {
      first = &l;
      break;
    }
  if (first) {
    const std::string file = result_under(dir, *first);
    if (is_complete(file)) {
      s.baseline = baseline_of_result(file);
      {
        dem::h5::Handle f = dem::h5::open_file_read(file);
        if (dem::h5::has_attribute(f, "software_version")) s.engine = dem::h5::get_string_attribute(f, "software_version");
      }
      DensityResults prepared;
      load_preparation(file, prepared);  // its spheres, as every table counts them
      if (prepared.sample.count("particles")) s.spheres = std::lround(prepared.sample.at("particles"));
    }
  }
  const std::string source = manifest_engine_source(dir);
  bool hashes_listed = !source.empty();
  for (const ManifestLine& l : manifest) {
    const std::string file = result_under(dir, l);
    if (!is_complete(file)) continue;
    s.date = std::max(s.date, day_written(file));  // YYYY-MM-DD sorts as it reads
    if (l.input_hash.empty()) {
      hashes_listed = false;
      continue;
    }
    dem::h5::Handle f = dem::h5::open_file_read(file);
    const std::string recorded = dem::h5::has_attribute(f, "input_hash") ? dem::h5::get_string_attribute(f, "input_hash") : "";
    if (recorded != l.input_hash) ++s.other_engine_results;
  }
  if (hashes_listed) s.engine_source = source;
  return s;
}

Stamp combined(const std::vector<Stamp>& stamps) {
  if (std::none_of(stamps.begin(), stamps.end(), [](const Stamp& s) { return s.recorded(); }))
    return stamps.empty() ? Stamp{} : stamps.front();  // what the first one has (its samples, say)
  Stamp out;
  bool first = true;
  const auto join = [](std::string& into, const std::string& value) {
    if (value.empty() || value == into) return;
    if (into.empty()) into = value;
    else if ((", " + into + ",").find(", " + value + ",") == std::string::npos) into += ", " + value;
  };
  for (const Stamp& s : stamps) {
    if (!s.recorded()) continue;  // a study whose results give nothing (not run, or not finished)
    if (first) out = s, out.other_engine_results = 0, first = false;
    join(out.engine, s.engine);
    join(out.engine_source, s.engine_source);
    out.other_engine_results += s.other_engine_results;
    join(out.baseline, s.baseline);
    out.date = std::max(out.date, s.date);
  }
  return out;
}

nlohmann::ordered_json stamp_json(const Stamp& s) {
  nlohmann::ordered_json j;
  j["engine"] = s.engine.empty() ? not_recorded : s.engine;
  j["engine_source"] = s.engine_source.empty() ? not_recorded : s.engine_source;
  if (s.other_engine_results > 0) j["other_engine_results"] = s.other_engine_results;
  j["baseline"] = s.baseline.empty() ? not_recorded : s.baseline;
  if (s.spheres > 0) j["spheres"] = s.spheres;
  else j["spheres"] = not_recorded;
  if (s.samples > 0) j["samples"] = s.samples;
  else j["samples"] = not_recorded;
  j["date"] = s.date.empty() ? not_recorded : s.date;
  return j;
}

Stamp stamp_from_json(const nlohmann::json& j) {
  Stamp s;
  if (!j.is_object()) return s;
  s.engine = text_field(j, "engine");
  s.engine_source = text_field(j, "engine_source");
  s.other_engine_results = count_field(j, "other_engine_results");
  s.baseline = text_field(j, "baseline");
  s.spheres = count_field(j, "spheres");
  s.samples = count_field(j, "samples");
  s.date = text_field(j, "date");
  return s;
}

void write_stamp_file(const std::string& out_dir, const Stamp& s, const std::vector<std::pair<std::string, Stamp>>& parts) {
  nlohmann::ordered_json j = stamp_json(s);
  for (const auto& [name, stamp] : parts) j[name] = stamp_json(stamp);
  dem::write_file_atomically((fs::path(out_dir) / "stamp.json").string(), j.dump(1) + "\n");
}

}  // namespace validation
