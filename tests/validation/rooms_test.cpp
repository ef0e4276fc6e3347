// validation/ in rooms (ARCHITECTURE.md, "Inside validation/"): a file includes only its own room
// and the rooms below it, no file name is in two rooms, and no file is over 500 lines. Read from
// the sources, so that a new include that runs back up fails here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The rooms from the ground floor up; tools/ may include every room.
const std::vector<std::string> floors = {"study", "judge", "figures", "sections", "report", "tools"};
// What each room may include besides itself (ARCHITECTURE.md's table).
const std::map<std::string, std::set<std::string>> allowed = {
    {"study", {}},
    {"judge", {"study"}},
    {"figures", {"study", "judge"}},
    {"sections", {"study", "judge"}},
    {"report", {"study", "judge", "figures", "sections"}},
    {"tools", {"study", "judge", "figures", "sections", "report"}},
};

// The room an include names ("judge/rows.hpp" -> "judge"), "" for another library's header (the
// engine's, or a header the build generates: "version.hpp"), "?" for a bare name of a file of
// validation/ (its room unsaid).
std::string room_of(const std::string& include, const std::set<std::string>& own_names) {
  const auto slash = include.find('/');
  if (slash == std::string::npos) return own_names.count(include) ? "?" : "";
  const std::string room = include.substr(0, slash);
  return std::find(floors.begin(), floors.end(), room) != floors.end() ? room : "";
}

std::vector<std::string> violations(const fs::path& root) {
  std::vector<std::string> found;
  std::set<std::string> own_names;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) own_names.insert(e.path().filename().string());
  std::map<std::string, std::string> names;  // file name -> room
  const std::regex include(R"re(^\s*#include "([^"]+)")re");
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
    const std::string room = e.path().parent_path().lexically_relative(root).string();
    const std::string file = e.path().lexically_relative(root).string();
    if (!allowed.count(room)) {
      found.push_back(file + ": not in a room");
      continue;
    }
    const std::string name = e.path().filename().string();
    if (names.count(name)) found.push_back(file + ": the name is also in " + names[name] + "/");
    names[name] = room;
    std::ifstream in(e.path());
    int lines = 0;
    for (std::string line; std::getline(in, line); ++lines) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string target = room_of(m[1].str(), own_names);
      if (target == "?") found.push_back(file + ": includes \"" + m[1].str() + "\" without its room");
      else if (!target.empty() && target != room && !allowed.at(room).count(target))
        found.push_back(file + ": includes " + m[1].str() + ", a room above " + room + "/");
    }
    if (lines > 500) found.push_back(file + ": " + std::to_string(lines) + " lines (more than 500)");
  }
  return found;
}

}  // namespace

TEST_CASE("validation/ keeps its rooms: no include runs back up, no name twice, no file over 500 lines", "[validation][rooms]") {
  const std::vector<std::string> found = violations(fs::path(DEM_SOURCE_DIR) / "validation");
  for (const std::string& f : found) UNSCOPED_INFO(f);
  CHECK(found.empty());
}

TEST_CASE("the rooms check finds an include that runs back up", "[validation][rooms]") {
  const fs::path root = fs::temp_directory_path() / "rooms_test_fixture";
  fs::remove_all(root);
  fs::create_directories(root / "study");
  fs::create_directories(root / "report");
  std::ofstream(root / "study" / "a.hpp") << "#include \"report/b.hpp\"\n";
  std::ofstream(root / "report" / "b.hpp") << "#include \"study/a.hpp\"\n";
  std::ofstream(root / "report" / "a.hpp") << "#include \"b.hpp\"\n#include \"version.hpp\"\n";
  const std::vector<std::string> found = violations(root);
  REQUIRE(found.size() == 3);  // the include running up, the name twice, the bare name of a file of its own
  CHECK(std::any_of(found.begin(), found.end(), [](const std::string& f) { return f.find("without its room") != std::string::npos; }));
  CHECK(std::any_of(found.begin(), found.end(), [](const std::string& f) { return f.find("a room above study/") != std::string::npos; }));
  CHECK(std::any_of(found.begin(), found.end(), [](const std::string& f) { return f.find("also in") != std::string::npos; }));
  fs::remove_all(root);
}
