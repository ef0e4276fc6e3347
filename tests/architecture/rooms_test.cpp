// validation/, pipeline/ and calibration/ in rooms (ARCHITECTURE.md, "Inside validation/", "Inside
// pipeline/"; calibration/ is one room): a file includes only its own room and the rooms below it, and
// no header of a layer it may not use (pipeline/ and validation/ are siblings over the engine,
// calibration/ sits on both); no file name is in two rooms; no file is over 500 lines and no
// function over 150. Read from the sources, so that a new include that runs back up, or a file or
// function that grows past the limit, fails here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int max_file_lines = 500, max_function_lines = 150;

// A folder of the repository and its rooms, each with the rooms it may include besides itself. "."
// is the folder's own top (pipeline/main.cpp; every file of calibration/, which has no rooms), where
// a bare file name is a file of that top.
struct Building {
  std::string folder;
  std::map<std::string, std::set<std::string>> allowed;
  std::vector<std::string> may_not_use;  // the folders whose headers it must not include
  std::map<std::string, std::string> may_use = {};  // a header of those folders -> the one room that includes it
};

const Building validation_rooms = {"validation",
                                   {{"study", {}},
                                    {"judge", {"study"}},
                                    {"figures", {"study", "judge"}},
                                    {"sections", {"study", "judge"}},
                                    {"report", {"study", "judge", "figures", "sections"}},
                                    {"tools", {"study", "judge", "figures", "sections", "report"}}},
                                   {"pipeline", "calibration"},
                                   {{"plan/runs_manifest.hpp", "study"}}};  // runs.tsv's one declaration
const Building pipeline_rooms = {"pipeline",
                                 {{"config", {}}, {"plan", {"config"}}, {"exec", {"config", "plan"}}, {".", {"config", "plan", "exec"}}},
                                 {"validation", "calibration"}};
const Building calibration_rooms = {"calibration", {{".", {}}}, {}};

// Every .cpp and .hpp under `root`, by its path from there.
std::vector<fs::path> sources(const fs::path& root) {
  std::vector<fs::path> out;
  if (!fs::is_directory(root)) return out;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) out.push_back(e.path().lexically_relative(root));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A function's body and where it starts (line of its opening brace), from a C++ source's text:
// braces counted outside comments, string and character literals (raw strings too) and
// preprocessor lines; a brace after a parenthesised header at namespace or class level opens a
// function (a lambda inside one belongs to it), a namespace's, class's or struct's brace is passed
// through, any other (an initialiser, an enum) is nobody's.
struct FunctionSpan {
  std::string header;  // its signature, blanks collapsed
  int first_line = 0, lines = 0;
};

std::vector<FunctionSpan> function_spans(const std::string& text) {
  enum class Kind { Through, Function, Other };
  struct Open {
    Kind kind;
    int line;
    std::string header;
  };
  std::vector<FunctionSpan> out;
  std::vector<Open> open;
  std::string header;
  int line = 1;
  bool line_start = true;
  const std::regex through(R"(^(namespace\b|extern ""|(template <.*> )?(class|struct|union)\b)[^()=]*$)");
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const char c = text[i];
    if (c == '\n') {
      ++line, ++i, header += ' ', line_start = true;
      continue;
    }
    if (line_start && (c == ' ' || c == '\t')) {
      ++i;
      continue;
    }
    if (line_start && c == '#') {  // a preprocessor line, with its continuations
      while (i < n && text[i] != '\n') {
        if (text[i] == '\\' && i + 1 < n && text[i + 1] == '\n') ++line, ++i;
        ++i;
      }
      continue;
    }
    line_start = false;
    if (text.compare(i, 2, "//") == 0) {
      while (i < n && text[i] != '\n') ++i;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = std::min(n, text.find("*/", i + 2) == std::string::npos ? n : text.find("*/", i + 2) + 2);
      line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(end), '\n'));
      i = end;
      continue;
    }
    const bool after_word = i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_');
    if (c == 'R' && !after_word && i + 1 < n && text[i + 1] == '"') {  // R"delim( ... )delim"
      const std::size_t paren = text.find('(', i + 2);
      const std::string close = ")" + text.substr(i + 2, paren - i - 2) + "\"";
      const std::size_t end = std::min(n, text.find(close, paren) == std::string::npos ? n : text.find(close, paren) + close.size());
      line += static_cast<int>(std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(end), '\n'));
      i = end, header += "\"\"";
      continue;
    }
    if (c == '"' || (c == '\'' && !after_word)) {  // a literal; a ' after a digit is a digit separator
      for (++i; i < n && text[i] != c && text[i] != '\n'; ++i)
        if (text[i] == '\\') ++i;
      ++i, header += "\"\"";
      continue;
    }
    if (c == '{') {
      std::string h = std::regex_replace(header, std::regex(R"(\s+)"), " ");
      h = std::regex_replace(h, std::regex(R"(^ | $)"), "");
      const bool in_function = std::any_of(open.begin(), open.end(), [](const Open& o) { return o.kind != Kind::Through; });
      const std::string before_paren = h.substr(0, h.find('('));
      const Kind kind = in_function                       ? Kind::Other
                        : std::regex_match(h, through)    ? Kind::Through
                        : h.find(')') != std::string::npos && before_paren.find('=') == std::string::npos &&
                                  h.rfind("enum", 0) != 0 ? Kind::Function
                                                          : Kind::Other;
      open.push_back({kind, line, h});
      header.clear(), ++i;
      continue;
    }
    if (c == '}') {
      if (!open.empty()) {
        if (open.back().kind == Kind::Function) out.push_back({open.back().header, open.back().line, line - open.back().line + 1});
        open.pop_back();
      }
      header.clear(), ++i;
      continue;
    }
    if (c == ';') header.clear();
    else header += c;
    ++i;
  }
  return out;
}

// What breaks the rules in `root` (a building's folder, or a fixture laid out like one), one line each.
std::vector<std::string> violations(const fs::path& root, const Building& b, const fs::path& repository) {
  std::vector<std::string> found;
  std::set<std::string> own_names, top_names, foreign;
  for (const fs::path& f : sources(root)) {
    own_names.insert(f.filename().string());
    if (f.parent_path().empty()) top_names.insert(f.filename().string());
  }
  for (const std::string& other : b.may_not_use)
    for (const fs::path& f : sources(repository / other)) foreign.insert(f.generic_string());
  std::map<std::string, std::string> names;  // file name -> room
  const std::regex include(R"re(^\s*#include "([^"]+)")re");
  for (const fs::path& f : sources(root)) {
    const std::string file = f.generic_string();
    const std::string room = f.parent_path().empty() ? "." : f.parent_path().generic_string();
    if (!b.allowed.count(room)) {
      found.push_back(file + ": not in a room");
      continue;
    }
    const std::string name = f.filename().string();
    if (names.count(name)) found.push_back(file + ": the name is also in " + names[name] + "/");
    names[name] = room;
    const std::string text = text_of(root / f);
    std::istringstream in(text);
    int lines = 0;
    for (std::string line; std::getline(in, line); ++lines) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string target = m[1].str();
      const std::size_t slash = target.find('/');
      if (const auto use = b.may_use.find(target); use != b.may_use.end() && use->second == room) {
        continue;
      } else if (foreign.count(target)) {
        found.push_back(file + ": includes " + target + ", a header of a layer " + b.folder + "/ may not use");
      } else if (slash == std::string::npos) {
        if (own_names.count(target) && !(room == "." && top_names.count(target)))
          found.push_back(file + ": includes \"" + target + "\" without its room");
      } else if (const std::string to = target.substr(0, slash); b.allowed.count(to) && to != room && !b.allowed.at(room).count(to)) {
        found.push_back(file + ": includes " + target + ", a room above " + room + "/");
      }
    }
    if (lines > max_file_lines) found.push_back(file + ": " + std::to_string(lines) + " lines (more than 500)");
    for (const FunctionSpan& s : function_spans(text))
      if (s.lines > max_function_lines)
        found.push_back(file + ":" + std::to_string(s.first_line) + ": a function of " + std::to_string(s.lines) +
                        " lines (more than 150): " + s.header.substr(0, 100));
  }
  return found;
}

std::vector<std::string> violations(const Building& b) {
  const fs::path repository = DEM_SOURCE_DIR;
  return violations(repository / b.folder, b, repository);
}

}  // namespace

TEST_CASE("validation/ keeps its rooms: no include runs back up, no name twice, no file over 500 lines or function over 150",
          "[validation][rooms]") {
  const std::vector<std::string> found = violations(validation_rooms);
  for (const std::string& f : found) UNSCOPED_INFO(f);
  CHECK(found.empty());
}

TEST_CASE("pipeline/ keeps its rooms (config, plan, exec, main.cpp) and includes no header of validation/ or calibration/",
          "[pipeline][rooms]") {
  const std::vector<std::string> found = violations(pipeline_rooms);
  for (const std::string& f : found) UNSCOPED_INFO(f);
  CHECK(found.empty());
}

TEST_CASE("calibration/ keeps the rules: no file over 500 lines or function over 150, no bare name out of place",
          "[calibration][rooms]") {
  const std::vector<std::string> found = violations(calibration_rooms);
  for (const std::string& f : found) UNSCOPED_INFO(f);
  CHECK(found.empty());
}

TEST_CASE("the rooms check finds an include that runs back up, a name twice, a foreign header, a long file or function",
          "[validation][rooms]") {
  const fs::path root = fs::temp_directory_path() / "rooms_test_fixture";
  fs::remove_all(root);
  for (const char* d : {"building/study", "building/report", "other/plan"}) fs::create_directories(root / d);
  const Building b = {"building", {{"study", {}}, {"report", {"study"}}}, {"other"}, {{"plan/m.hpp", "study"}}};
  std::ofstream(root / "other" / "plan" / "p.hpp") << "#pragma once\n";
  std::ofstream(root / "other" / "plan" / "m.hpp") << "#pragma once\n";
  std::ofstream(root / "building" / "study" / "a.hpp") << "#include \"report/b.hpp\"\n#include \"plan/m.hpp\"\n";
  std::ofstream(root / "building" / "report" / "b.hpp") << "#include \"study/a.hpp\"\n#include \"plan/p.hpp\"\n#include \"plan/m.hpp\"\n";
  std::ofstream(root / "building" / "report" / "a.hpp") << "#include \"b.hpp\"\n#include \"version.hpp\"\n";
  // A function of exactly 150 lines passes, one of 151 does not; braces in comments, strings, raw
  // strings and characters are not counted, nor is a namespace's or a struct's body.
  std::ofstream body(root / "building" / "study" / "long.cpp");
  body << "namespace n {\nstruct S {\n  int f() const {\n";
  for (int k = 0; k < 148; ++k) body << "    x += 1;  // {\n";
  body << "  }\n};\nint g(int x) {\n  const char* s = \"}}\"; auto r = R\"re(})re\"; char c = '}';\n";
  for (int k = 0; k < 148; ++k) body << "    x += 1;\n";
  body << "}\n}  // namespace n\n";
  for (int k = 0; k < 260; ++k) body << "// filler\n";
  body.close();
  const std::vector<std::string> found = violations(root / "building", b, root);
  for (const std::string& f : found) UNSCOPED_INFO(f);
  const auto has = [&](const std::string& what) {
    return std::count_if(found.begin(), found.end(), [&](const std::string& f) { return f.find(what) != std::string::npos; });
  };
  CHECK(has("without its room") == 1);                  // report/a.hpp: "b.hpp"
  CHECK(has("a room above study/") == 1);               // study/a.hpp includes report/
  CHECK(has("also in") == 1);                           // a.hpp in both rooms
  CHECK(has("a layer building/ may not use") == 2);     // plan/p.hpp of other/; plan/m.hpp, but from report/
  CHECK(has("lines (more than 500)") == 1);             // long.cpp, 565 lines
  CHECK(has("a function of 151 lines") == 1);           // g, not f (150 lines) nor S or n
  CHECK(found.size() == 7);                             // study/a.hpp's plan/m.hpp, which study/ may use, is not one
  fs::remove_all(root);
}
