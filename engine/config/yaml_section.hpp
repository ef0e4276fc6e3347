#pragma once
// Typed, validated reading of one YAML mapping. Each key is declared once, where it is read, with
// its unit, range, default and a line of documentation; the same declaration feeds the error
// messages and `dem keys` (the key reference). Unknown and duplicate keys are errors, and every
// error names the file, the full key path, the line, what is allowed and what was found.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace dem {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct KeyDoc {
  std::string unit, allowed, default_value, doc;
};
// Every key declared so far, by path pattern (list indices written as []); filled as files are read.
std::map<std::string, KeyDoc>& key_docs();

// Sets the key `path` (a.b[2].c) of `root` to the YAML `value`, creating missing mapping keys;
// throws ConfigError naming `file` if the path does not fit the document. Returns the node set.
YAML::Node apply_override(YAML::Node root, const std::string& file, const std::string& path, const std::string& value);

// Numbers are read one way everywhere (scene keys, --set, study files, seeds): decimal. A number
// is [+-]digits[.digits][e[+-]digits] (or .digits, or YAML's .inf / .nan, which the ranges then
// refuse); an integer is [+-]digits. Refused, with `why` saying so: a leading zero before a digit
// (YAML 1.1 reads 010 as octal 8, a decimal reader as 10: neither is assumed), hexadecimal or any
// other form, a value that overflows (1e400) or a non-zero value that underflows to 0 (1e-400;
// a subnormal such as 4.9e-324 is kept). Both return false when `text` is not such a number.
bool parse_decimal(const std::string& text, double& x, std::string& why);
bool parse_decimal_integer(const std::string& text, long long& x, std::string& why);

// What a scene or study file may be (checked before YAML reads it, config/yaml_section.cpp): at
// most this many bytes, mappings and sequences nested at most this deep, and at most this many
// nodes (scalars, mappings, sequences) in its tree as a reader walks it, every alias expanded.
// yaml-cpp shares an aliased node instead of copying it, so a 1 KB file of nine anchors, each a
// list of ten aliases of the one before, reads at once and holds 10^9 nodes when walked.
inline constexpr std::size_t max_yaml_bytes = 16u << 20;  // 16 MiB
inline constexpr std::size_t max_yaml_depth = 32;
inline constexpr std::uint64_t max_yaml_nodes = 1'000'000;

// The one way the project turns YAML into a tree: scenes, studies, calibration and reference files,
// --set values, the scene a result records, the pipeline's own records. The text is checked before
// yaml-cpp builds a tree (size, control characters, one document, the nesting and the node count
// above with every alias expanded, an alias inside the node it names); ConfigError names `file`
// and the line. An empty text gives a null node.
YAML::Node parse_yaml(const std::string& text, const std::string& file);
// The same from a file, read whole (throws ConfigError if it is missing, a folder or unreadable).
YAML::Node load_yaml(const std::string& file);

struct Range {
  double min, max;
  bool min_open = false;  // true: value must be > min rather than >= min
  bool max_open = false;  // true: value must be < max rather than <= max
};

class Section {
 public:
  Section(YAML::Node node, std::string file, std::string path);

  // Parses a whole file; throws ConfigError if it is missing, unreadable, empty or not a mapping.
  // `overrides` are (key path, YAML value) pairs applied before validation, e.g.
  // ("particles.lattice.seed", "2") or ("stages[0].hold.max_duration", "5"). They come from the
  // command line, so a file path in one is relative to the current folder (file_path).
  using Overrides = std::vector<std::pair<std::string, std::string>>;
  static Section load_file(const std::string& file, const Overrides& overrides = {});
  static Section from_text(const std::string& text, const std::string& file, const Overrides& overrides = {});

  bool has(const std::string& key) const;
  double number(const std::string& key, const std::string& unit, Range range, std::optional<double> def,
                const std::string& doc);
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max, std::optional<std::int64_t> def,
                       const std::string& doc);
  bool boolean(const std::string& key, bool def, const std::string& doc);
  std::string choice(const std::string& key, const std::vector<std::string>& allowed, std::optional<std::string> def,
                     const std::string& doc);
  std::string text(const std::string& key, std::optional<std::string> def, const std::string& doc);
  // A required key naming a file: returned resolved against the folder of the scene file when
  // relative, or against the current folder when an override (the command line) gave it. `dem keys` shows its type as file_path_allowed; every such key is an input of the
  // run (SceneConfig::input_files), which `dem run --out` may never name.
  std::string file_path(const std::string& key, const std::string& doc);
  static constexpr const char* file_path_allowed =
      "path of a file (relative: to the scene's folder; given with --set: to the current folder)";
  std::vector<double> numbers(const std::string& key, const std::string& unit, Range range, std::size_t min_count,
                              std::size_t max_count, const std::string& doc);
  Section child(const std::string& key, const std::string& doc);
  // A mapping that may be left out: then every key in it takes its default.
  // `absent` is what `dem keys` says of the mapping when it is left out.
  Section optional_child(const std::string& key, const std::string& doc,
                         const std::string& absent = "optional (every key at its default)");
  // The node of a required key whose structure the caller checks itself (e.g. a stress path).
  YAML::Node raw(const std::string& key, const std::string& allowed, const std::string& doc);
  std::vector<Section> list(const std::string& key, const std::string& doc);

  // Throws if the mapping has a key that was never read (with a did-you-mean suggestion).
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  YAML::Node get(const std::string& key) const;
  [[noreturn]] void fail_missing(const std::string& key, const std::string& what) const;
  void declare(const std::string& key, const std::string& unit, const std::string& allowed, const std::string& def,
               const std::string& doc) const;
  std::string where(const YAML::Node& n) const;
  Section sub(YAML::Node node, std::string path) const;  // a child section, sharing overrides_
  static Section from_tree(YAML::Node root, const std::string& file, const Overrides& overrides);
  bool from_override(const YAML::Node& n) const;

  YAML::Node node_;
  std::shared_ptr<const std::vector<YAML::Node>> overrides_;  // the values the overrides set
  std::string file_, path_;
  mutable std::set<std::string> used_;
};

}  // namespace dem
