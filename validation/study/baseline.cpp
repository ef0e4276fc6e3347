#include "study/baseline.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "io/hdf5.hpp"

namespace validation {
namespace {

// The keys left out, as paths from the root: set per study, or a place rather than a setting.
const std::vector<std::vector<std::string>> left_out = {
    {"name"},
    {"output"},
    {"particles", "lattice", "n"},
    {"particles", "lattice", "seed"},
    {"particles", "state"},
    {"particles", "csv"},
    {"material", "friction"},
    // The friction's own stiffness: the resolved scene writes it only with friction > 0 (a dense
    // preparation at friction 0 has none), so it would set a study's baseline by which density it
    // prepares first.
    {"material", "ks"},
};

bool is_left_out(const std::vector<std::string>& path) {
  for (const auto& p : left_out)
    if (p == path) return true;
  return false;
}

// A node as one canonical string: maps with sorted keys, numbers by their value, strings with
// their length first (so that no string can pass for a structure).
void canonical(const YAML::Node& n, std::vector<std::string>& path, std::string& out) {
  switch (n.Type()) {
    case YAML::NodeType::Map: {
      // Sorted by key through their indices: a YAML::Node assigned to (as std::sort would) rebinds
      // the node it refers to inside the tree.
      std::vector<YAML::Node> values;
      std::vector<std::pair<std::string, std::size_t>> keys;
      for (const auto& kv : n) {
        keys.emplace_back(kv.first.Scalar(), values.size());
        values.push_back(kv.second);
      }
      std::sort(keys.begin(), keys.end());
      out += '{';
      for (const auto& [key, at] : keys) {
        path.push_back(key);
        if (!is_left_out(path)) {
          out += std::to_string(key.size()) + ':' + key + '=';
          canonical(values[at], path, out);
          out += ';';
        }
        path.pop_back();
      }
      out += '}';
      break;
    }
    case YAML::NodeType::Sequence:
      out += '[';
      for (const YAML::Node& item : n) {
        canonical(item, path, out);  // items share their list's path: nothing inside a list is left out
        out += ',';
      }
      out += ']';
      break;
    case YAML::NodeType::Scalar: {
      double x = 0;
      if (YAML::convert<double>::decode(n, x)) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", x);
        out += std::string("n") + buf;
      } else {
        out += 's' + std::to_string(n.Scalar().size()) + ':' + n.Scalar();
      }
      break;
    }
    default:
      out += '~';  // null or undefined
  }
}

std::uint64_t fnv1a64(const std::string& s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64: offset basis and prime (Fowler, Noll, Vo)
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace

std::string baseline_of(const std::string& scene_yaml, const std::string& where) {
  YAML::Node root;
  try {
    root = dem::parse_yaml(scene_yaml, where);
  } catch (const dem::ConfigError& e) {
    throw std::runtime_error(e.what());
  }
  std::vector<std::string> path;
  std::string text;
  canonical(root, path, text);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(fnv1a64(text)));
  return buf;
}

std::string baseline_of_result(const std::string& result) {
  std::error_code ec;
  if (!std::filesystem::exists(result, ec)) return "";
  std::string text, source;
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    if (dem::h5::has_attribute(f, "copied_from")) source = dem::h5::get_string_attribute(f, "copied_from");
    if (dem::h5::has_text(f, "scene_yaml")) text = dem::h5::read_text(f, "scene_yaml");
  } catch (const std::exception& e) {
    throw std::runtime_error(result + ": cannot be read as a result (" + e.what() + ")");
  }
  // A copy (the pipeline's, of a run of the same scene but for its name) made before copies kept
  // the resolved scene holds the study's text of it (no defaults filled in): its baseline is that of
  // the run it copies while that run is here (a copy is made from a finished result, so the chain
  // back to the run that computed it has no loop).
  if (!source.empty() && source != result && std::filesystem::exists(source, ec)) return baseline_of_result(source);
  return text.empty() ? "" : baseline_of(text, result);
}

}  // namespace validation
