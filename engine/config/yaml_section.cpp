#include "config/yaml_section.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <unordered_map>

namespace dem {

std::map<std::string, KeyDoc>& key_docs() {
  static std::map<std::string, KeyDoc> docs;
  return docs;
}

namespace {

std::string fmt(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string range_text(Range r) {
  std::string lo = r.min_open ? "(" : "[";
  return lo + fmt(r.min) + ", " + fmt(r.max) + (r.max_open ? ")" : "]");
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string pattern_of(const std::string& path) { return std::regex_replace(path, std::regex("\\[[0-9]+\\]"), "[]"); }

std::string scalar_text(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}

// The text of a failed number: ", got 'x' (line n)" and why, if known.
std::string got_number(const YAML::Node& n, const std::string& why, const std::string& where_text) {
  return ", got " + scalar_text(n) + where_text + (why.empty() ? "" : ": " + why);
}

}  // namespace

namespace {
// Splits a decimal numeral: sign, digits before the point, digits after, exponent digits.
// False if `t` is not [+-]digits[.digits][e[+-]digits] / [+-].digits[e...] / [+-]digits.[e...].
bool decimal_form(const std::string& t, bool integer_only, std::string& int_digits, std::string& frac_digits) {
  std::size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const auto digits = [&](std::string& into) {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    into = t.substr(from, i - from);
  };
  digits(int_digits);
  if (integer_only) return !int_digits.empty() && i == t.size();
  if (i < t.size() && t[i] == '.') ++i, digits(frac_digits);
  if (int_digits.empty() && frac_digits.empty()) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    std::string exponent;
    digits(exponent);
    if (exponent.empty()) return false;
  }
  return i == t.size();
}

std::string leading_zero(const std::string& t, const std::string& int_digits) {
  if (int_digits.size() < 2 || int_digits[0] != '0') return "";
  std::string plain = t;  // the same number without its leading zeros
  const std::size_t at = plain.find(int_digits), zeros = int_digits.find_first_not_of('0');
  plain.erase(at, (zeros == std::string::npos ? int_digits.size() - 1 : zeros));
  return "a leading zero is refused (YAML 1.1 reads it as octal, other readers as decimal; numbers here are decimal): write " + plain;
}
}  // namespace

bool parse_decimal(const std::string& t, double& x, std::string& why) {
  why.clear();
  static const std::set<std::string> nan = {".nan", ".NaN", ".NAN"};
  static const std::set<std::string> inf = {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"};
  static const std::set<std::string> minus_inf = {"-.inf", "-.Inf", "-.INF"};
  if (nan.count(t)) return x = std::numeric_limits<double>::quiet_NaN(), true;
  if (inf.count(t)) return x = std::numeric_limits<double>::infinity(), true;
  if (minus_inf.count(t)) return x = -std::numeric_limits<double>::infinity(), true;
  std::string int_digits, frac_digits;
  if (!decimal_form(t, false, int_digits, frac_digits)) {
    if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X' || t[1] == 'o')) why = "hexadecimal and octal forms are refused; numbers are decimal";
    return false;
  }
  if (!(why = leading_zero(t, int_digits)).empty()) return false;
  errno = 0;
  char* end = nullptr;
  x = std::strtod(t.c_str(), &end);
  if (errno == ERANGE && std::isinf(x)) {
    why = "beyond the largest double (1.8e308)";
    return false;
  }
  const bool nonzero = (int_digits + frac_digits).find_first_not_of('0') != std::string::npos;
  if (x == 0 && nonzero) {
    why = "below the smallest positive double (4.9e-324): it would read as 0; write 0 if 0 is meant";
    return false;
  }
  return true;
}

bool parse_decimal_integer(const std::string& t, long long& x, std::string& why) {
  why.clear();
  std::string int_digits, unused;
  if (!decimal_form(t, true, int_digits, unused)) {
    if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X' || t[1] == 'o')) why = "hexadecimal and octal forms are refused; numbers are decimal";
    return false;
  }
  if (!(why = leading_zero(t, int_digits)).empty()) return false;
  errno = 0;
  x = std::strtoll(t.c_str(), nullptr, 10);
  if (errno == ERANGE) {
    why = "beyond the largest integer";
    return false;
  }
  return true;
}

Section::Section(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {
  if (!node_.IsMap()) {
    std::ostringstream msg;
    msg << file_ << ": " << (path_.empty() ? "the file" : path_) << " must be a mapping of keys, got "
        << scalar_text(node_);
    throw ConfigError(msg.str());
  }
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) {  // e.g. `? [a, b]` or `? ?`: YAML allows it, a scene never means it
      std::ostringstream msg;
      msg << file_ << ": " << (path_.empty() ? "top level" : path_) << ": a key must be a plain name, got "
          << scalar_text(kv.first) << where(kv.first);
      throw ConfigError(msg.str());
    }
    const std::string key = kv.first.Scalar();
    if (key == "<<")  // YAML 1.1's merge key: yaml-cpp reads it as a key named "<<"
      fail("", "a merge key '<<'" + where(kv.first) + " is not supported: write the keys it would merge out in full");
    if (!seen.insert(key).second) fail(key, "duplicate key" + where(kv.first));
  }
}

Section Section::load_file(const std::string& file, const Overrides& overrides) {
  return from_tree(load_yaml(file), file, overrides);
}

namespace {
// The YAML value of an override, read as every YAML text is (parse_yaml): an error names
// "FILE: --set KEY" and the line in the value.
YAML::Node override_value(const std::string& file, const std::string& path, const std::string& value) {
  return parse_yaml(value, file + ": --set " + path);
}
}  // namespace

// Sets `path` (a.b[2].c) in `root` to the YAML value `value`, creating missing mapping keys.
YAML::Node apply_override(YAML::Node root, const std::string& file, const std::string& path, const std::string& value) {
  const std::regex segment_re(R"(^([A-Za-z_][A-Za-z0-9_]*)(?:\[([0-9]+)\])?$)");
  YAML::Node node = root;
  std::stringstream ss(path);
  std::string segment, done;
  std::vector<std::string> segments;
  while (std::getline(ss, segment, '.')) segments.push_back(segment);
  if (segments.empty()) throw ConfigError(file + ": --set: empty key path");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    std::smatch m;
    if (!std::regex_match(segments[i], m, segment_re))
      throw ConfigError(file + ": --set " + path + ": '" + segments[i] + "' is not a key (letters, digits, _, optional [index])");
    if (!done.empty()) done += '.';
    done += m[1].str();
    if (node.IsDefined() && !node.IsMap() && !node.IsNull())
      throw ConfigError(file + ": --set " + path + ": '" + done + "' is inside a non-mapping");
    const bool last = i + 1 == segments.size();
    if (last && !m[2].matched) {
      const YAML::Node v = override_value(file, path, value);
      node[m[1].str()] = v;
      return v;
    }
    YAML::Node next = node[m[1].str()];
    if (m[2].matched) {
      const std::size_t index = std::stoul(m[2].str());
      if (!next.IsSequence() || index >= next.size())
        throw ConfigError(file + ": --set " + path + ": '" + done + "' has no item [" + m[2].str() + "]");
      done.append(1, '[').append(m[2].str()).append(1, ']');
      if (last) {
        next[index] = override_value(file, path, value);
        return next[index];
      }
      next.reset(next[index]);
    }
    node.reset(next);
  }
  return node;  // not reached: the last segment returns above
}

namespace {

// What a scene or study file must be before YAML reads it: at most max_yaml_bytes of UTF-8 text
// without NUL or control characters (a binary file, a name with an escape sequence in it).
void check_yaml_text(const std::string& text, const std::string& file) {
  if (text.size() > max_yaml_bytes)
    throw ConfigError(file + ": " + std::to_string(text.size() >> 20) + " MiB, more than the " + std::to_string(max_yaml_bytes >> 20) +
                      " MiB a scene or study file may hold");
  const std::size_t at = first_non_text(text, true);
  if (at == std::string::npos) return;
  const auto c = static_cast<unsigned char>(text[at]);
  char code[8];
  std::snprintf(code, sizeof code, "0x%02x", c);
  const std::string what = c == 0 ? "a NUL byte (a binary file?)"
                           : c < 0x80 ? std::string("the control character ") + code + " (not allowed in a scene or study)"
                                      : std::string("the byte ") + code + ", not UTF-8 text (save the file as UTF-8)";
  throw ConfigError(file + ": line " + std::to_string(line_of(text, at)) + ": " + what);
}

// The tree a reader would walk, measured from the parser's events before yaml-cpp builds it: its
// nodes and nesting with every alias expanded (an anchored node's size and height are known at
// its end; an alias adds them where it stands). Throws ConfigError naming the line where the tree
// passes max_yaml_nodes or max_yaml_depth, or where an alias names a node still open around it
// (yaml-cpp would build a cycle, and any walk of it would never end).
class TreeMeasure : public YAML::EventHandler {
 public:
  explicit TreeMeasure(const std::string& file) : file_(file) {}
  std::size_t documents = 0;

  void OnDocumentStart(const YAML::Mark&) override {
    ++documents;
    nodes_ = 0;
    anchors_.clear();
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string&) override { leaf(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto it = anchors_.find(anchor);
    if (it == anchors_.end())
      throw ConfigError(file_ + ": line " + std::to_string(mark.line + 1) +
                        ": an alias inside the node its anchor names: the tree would contain itself without end");
    add(mark, it->second.nodes, it->second.height);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Size {
    std::uint64_t nodes;  // in the node's tree, itself included
    std::size_t height;   // mappings and sequences nested in it, itself included (0: a scalar)
  };
  struct Open {
    YAML::anchor_t anchor;
    std::uint64_t nodes_before;  // nodes_ when it opened
    std::size_t height;          // the highest of its children so far
  };

  // A node of `size` nodes and `height` levels at the current place of the tree.
  void add(const YAML::Mark& mark, std::uint64_t size, std::size_t height) {
    nodes_ += size;  // size <= max_yaml_nodes and nodes_ <= max_yaml_nodes before: no overflow
    if (nodes_ > max_yaml_nodes)
      throw ConfigError(file_ + ": line " + std::to_string(mark.line + 1) + ": more than " + std::to_string(max_yaml_nodes) +
                        " YAML nodes once its aliases (*name) are expanded, as a reader walks them (an alias bomb?)");
    if (open_.size() + height > max_yaml_depth)
      throw ConfigError(file_ + ": nested more than " + std::to_string(max_yaml_depth) + " levels deep (line " +
                        std::to_string(mark.line + 1) + "; a scene or study nests a few)");
    if (!open_.empty()) open_.back().height = std::max(open_.back().height, height);
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1, 0);
    if (anchor != YAML::NullAnchor) anchors_[anchor] = Size{1, 0};
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1, 1);
    open_.push_back(Open{anchor, nodes_ - 1, 0});
  }
  void close() {
    const Open o = open_.back();
    open_.pop_back();
    const Size size{nodes_ - o.nodes_before, 1 + o.height};
    if (!open_.empty()) open_.back().height = std::max(open_.back().height, size.height);
    if (o.anchor != YAML::NullAnchor) anchors_[o.anchor] = size;
  }

  const std::string& file_;
  std::uint64_t nodes_ = 0;
  std::vector<Open> open_;
  std::unordered_map<YAML::anchor_t, Size> anchors_;  // the anchored nodes that have ended
};

}  // namespace

YAML::Node parse_yaml(const std::string& text, const std::string& file) {
  check_yaml_text(text, file);
  try {
    TreeMeasure measure(file);
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (parser.HandleNextDocument(measure)) {
    }
    if (measure.documents > 1)
      throw ConfigError(file + ": holds " + std::to_string(measure.documents) +
                        " YAML documents (separated by '---'); a scene or study is one: remove the others");
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw ConfigError(file + ": line " + std::to_string(e.mark.line + 1) + ": nested too deeply for YAML to read (a scene or study " +
                      "nests a few levels: a stray run of '[' or '{'?)");
  } catch (const YAML::Exception& e) {
    throw ConfigError(file + ": not valid YAML: " + e.what());
  }
}

YAML::Node load_yaml(const std::string& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(file, ec)) throw ConfigError(file + ": no such file");
  if (fs::is_directory(file, ec)) throw ConfigError(file + ": is a directory, expected a YAML file");
  std::ifstream in(file);
  std::stringstream text;
  if (!in || !(text << in.rdbuf())) {
    if (fs::file_size(file, ec) == 0 && !ec) throw ConfigError(file + ": the file is empty");
    throw ConfigError(file + ": cannot be read");
  }
  return parse_yaml(text.str(), file);
}

Section Section::from_text(const std::string& text, const std::string& file, const Overrides& overrides) {
  return from_tree(parse_yaml(text, file), file, overrides);
}

Section Section::from_tree(YAML::Node root, const std::string& file, const Overrides& overrides) {
  if (!root || root.IsNull()) throw ConfigError(file + ": the file is empty");
  if (!root.IsMap()) throw ConfigError(file + ": the file must be a mapping of keys, got " + scalar_text(root));
  auto set = std::make_shared<std::vector<YAML::Node>>();
  for (const auto& [path, value] : overrides) set->push_back(apply_override(root, file, path, value));
  Section s(root, file, "");
  s.overrides_ = std::move(set);
  return s;
}

Section Section::sub(YAML::Node node, std::string path) const {
  Section s(std::move(node), file_, std::move(path));
  s.overrides_ = overrides_;
  return s;
}

// Whether `n` is (inside) a value an override set: the same node, not an equal one.
bool Section::from_override(const YAML::Node& n) const {
  if (!overrides_) return false;
  const std::function<bool(const YAML::Node&)> within = [&](const YAML::Node& v) {
    if (v.is(n)) return true;
    if (v.IsMap())
      for (const auto& kv : v)
        if (within(kv.second)) return true;
    if (v.IsSequence())
      for (const auto& item : v)
        if (within(item)) return true;
    return false;
  };
  for (const YAML::Node& v : *overrides_)
    if (within(v)) return true;
  return false;
}

std::string Section::where(const YAML::Node& n) const {
  const YAML::Mark m = n.Mark();
  return m.line >= 0 ? " (line " + std::to_string(m.line + 1) + ")" : "";
}

void Section::fail(const std::string& key, const std::string& what) const {
  const std::string at = key.empty() ? (path_.empty() ? "top level" : path_) : key_path(key);
  throw ConfigError(file_ + ": " + at + ": " + what);
}

void Section::fail_missing(const std::string& key, const std::string& what) const {
  std::string msg = "missing (" + what + ")";
  for (const auto& kv : node_) {  // a present key that nobody reads and that looks like this one
    const std::string k = kv.first.Scalar();
    if (!used_.count(k) && k != key && edit_distance(k, key) <= 2) {
      msg += "; found '" + k + "'" + where(kv.first) + ": did you mean '" + key + "'?";
      break;
    }
  }
  fail(key, msg);
}

void Section::declare(const std::string& key, const std::string& unit, const std::string& allowed,
                      const std::string& def, const std::string& doc) const {
  used_.insert(key);
  key_docs()[pattern_of(key_path(key))] = KeyDoc{unit, allowed, def, doc};
}

bool Section::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

YAML::Node Section::get(const std::string& key) const { return node_[key]; }

double Section::number(const std::string& key, const std::string& unit, Range range, std::optional<double> def,
                       const std::string& doc) {
  declare(key, unit, range_text(range), def ? fmt(*def) : "required", doc);
  const YAML::Node n = get(key);
  if (!n) {
    if (def) return *def;
    fail_missing(key, "a number in " + range_text(range) + (unit.empty() ? "" : " " + unit));
  }
  double x = 0;
  std::string why;
  if (!n.IsScalar() || !parse_decimal(n.Scalar(), x, why))
    fail(key, "must be a number" + (unit.empty() ? "" : " [" + unit + "]") + got_number(n, why, where(n)));
  const bool below = range.min_open ? !(x > range.min) : !(x >= range.min);
  const bool above = range.max_open ? !(x < range.max) : !(x <= range.max);
  if (!std::isfinite(x) || below || above)
    fail(key, "must be in " + range_text(range) + (unit.empty() ? "" : " " + unit) + ", got " + n.Scalar() + where(n));
  return x;
}

std::int64_t Section::integer(const std::string& key, std::int64_t min, std::int64_t max,
                              std::optional<std::int64_t> def, const std::string& doc) {
  const std::string allowed = "integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  declare(key, "", allowed, def ? std::to_string(*def) : "required", doc);
  const YAML::Node n = get(key);
  if (!n) {
    if (def) return *def;
    fail_missing(key, "an " + allowed);
  }
  long long x = 0;
  std::string why;
  if (!n.IsScalar() || !parse_decimal_integer(n.Scalar(), x, why))
    fail(key, "must be an " + allowed + got_number(n, why, where(n)));
  if (x < min || x > max) fail(key, "must be an " + allowed + ", got " + n.Scalar() + where(n));
  return x;
}

bool Section::boolean(const std::string& key, bool def, const std::string& doc) {
  declare(key, "", "true or false", def ? "true" : "false", doc);
  const YAML::Node n = get(key);
  if (!n) return def;
  bool b = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, b))
    fail(key, "must be true or false, got " + scalar_text(n) + where(n));
  return b;
}

std::string Section::choice(const std::string& key, const std::vector<std::string>& allowed,
                            std::optional<std::string> def, const std::string& doc) {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  declare(key, "", "one of: " + list, def ? *def : "required", doc);
  const YAML::Node n = get(key);
  if (!n) {
    if (def) return *def;
    fail_missing(key, "one of: " + list);
  }
  if (!n.IsScalar() || std::find(allowed.begin(), allowed.end(), n.Scalar()) == allowed.end())
    fail(key, "must be one of: " + list + ", got " + scalar_text(n) + where(n));
  return n.Scalar();
}

std::string Section::text(const std::string& key, std::optional<std::string> def, const std::string& doc) {
  declare(key, "", "text", def ? "'" + *def + "'" : "required", doc);
  const YAML::Node n = get(key);
  if (!n) {
    if (def) return *def;
    fail_missing(key, "text");
  }
  if (!n.IsScalar() || n.Scalar().empty()) fail(key, "must be non-empty text, got " + scalar_text(n) + where(n));
  return n.Scalar();
}

std::string Section::file_path(const std::string& key, const std::string& doc) {
  declare(key, "", file_path_allowed, "required", doc);
  const YAML::Node n = get(key);
  if (!n) fail_missing(key, file_path_allowed);
  if (!n.IsScalar() || n.Scalar().empty()) fail(key, "must be a file path, got " + scalar_text(n) + where(n));
  const std::filesystem::path p(n.Scalar());
  if (p.is_absolute()) return p.string();
  if (from_override(n)) return std::filesystem::absolute(p).lexically_normal().string();  // typed in this folder
  return (std::filesystem::path(file_).parent_path() / p).lexically_normal().string();
}

std::vector<double> Section::numbers(const std::string& key, const std::string& unit, Range range,
                                     std::size_t min_count, std::size_t max_count, const std::string& doc) {
  const std::string count = min_count == max_count ? std::to_string(min_count)
                                                   : std::to_string(min_count) + " to " + std::to_string(max_count);
  const std::string allowed = "list of " + count + " numbers in " + range_text(range);
  declare(key, unit, allowed, "required", doc);
  const YAML::Node n = get(key);
  if (!n) fail_missing(key, "a " + allowed + (unit.empty() ? "" : " " + unit));
  if (!n.IsSequence() || n.size() < min_count || n.size() > max_count)
    fail(key, "must be a " + allowed + ", got " + (n.IsSequence() ? std::to_string(n.size()) + " items" : scalar_text(n)) +
                  where(n));
  std::vector<double> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    double x = 0;
    const YAML::Node item = n[i];
    const std::string item_key = key + "[" + std::to_string(i) + "]";
    std::string why;
    if (!item.IsScalar() || !parse_decimal(item.Scalar(), x, why))
      fail(item_key, "must be a number" + got_number(item, why, where(item)));
    const bool below = range.min_open ? !(x > range.min) : !(x >= range.min);
    const bool above = range.max_open ? !(x < range.max) : !(x <= range.max);
    if (!std::isfinite(x) || below || above)
      fail(item_key, "must be in " + range_text(range) + (unit.empty() ? "" : " " + unit) + ", got " + item.Scalar() +
                         where(item));
    out.push_back(x);
  }
  return out;
}

YAML::Node Section::raw(const std::string& key, const std::string& allowed, const std::string& doc) {
  declare(key, "", allowed, "required", doc);
  const YAML::Node n = get(key);
  if (!n) fail_missing(key, allowed);
  return n;
}

Section Section::optional_child(const std::string& key, const std::string& doc, const std::string& absent) {
  declare(key, "", "mapping", absent, doc);
  const YAML::Node n = get(key);
  return sub(n ? n : YAML::Node(YAML::NodeType::Map), key_path(key));
}

Section Section::child(const std::string& key, const std::string& doc) {
  declare(key, "", "mapping", "required", doc);
  const YAML::Node n = get(key);
  if (!n) fail_missing(key, "a mapping");
  return sub(n, key_path(key));
}

std::vector<Section> Section::list(const std::string& key, const std::string& doc) {
  declare(key, "", "list of mappings", "required", doc);
  const YAML::Node n = get(key);
  if (!n || !n.IsSequence() || n.size() == 0)
    fail(key, "must be a non-empty list of mappings, got " + (n ? scalar_text(n) : std::string("nothing")));
  std::vector<Section> out;
  for (std::size_t i = 0; i < n.size(); ++i) out.push_back(sub(n[i], key_path(key) + "[" + std::to_string(i) + "]"));
  return out;
}

void Section::finish() const {
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) {  // e.g. `? [a, b]` or `? ?`: YAML allows it, a scene never means it
      std::ostringstream msg;
      msg << file_ << ": " << (path_.empty() ? "top level" : path_) << ": a key must be a plain name, got "
          << scalar_text(kv.first) << where(kv.first);
      throw ConfigError(msg.str());
    }
    const std::string key = kv.first.Scalar();
    if (used_.count(key)) continue;
    std::string best;
    std::size_t best_d = 3;  // suggest only close matches
    for (const auto& u : used_) {
      const std::size_t d = edit_distance(key, u);
      if (d < best_d) best_d = d, best = u;
    }
    std::string msg = "unknown key '" + key + "'" + where(kv.first);
    if (!best.empty()) msg += " (did you mean '" + best + "'?)";
    throw ConfigError(file_ + ": " + (path_.empty() ? "top level" : path_) + ": " + msg);
  }
}

}  // namespace dem
