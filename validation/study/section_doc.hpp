#pragma once
// A section another tool writes for the report (compare-runs decisions, critical-state,
// liquefaction): its parts as data, so that the report places it (its headings under the report's
// own, its figures' paths from the report's folder, a figure not drawn said so) without reading
// Markdown back. Declared once: the modes write FOLDER/section.json beside the table.md rendered
// from the same parts (render with the section's own place), and the report reads section.json.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace validation {

inline constexpr const char* section_doc_file = "section.json";

struct SectionPart {
  enum class Kind { text, heading, figure };
  Kind kind = Kind::text;
  std::string text;  // text: Markdown without a heading line or a figure of its own; heading: its words; figure: its caption
  int depth = 0;     // heading: 1 = one level below the heading the section sits under
  std::string file;  // figure: its PNG, a file name in the section's folder
};

struct SectionDoc {
  std::vector<SectionPart> parts;
  // The densities the section's study ran, in its order (empty: not recorded).
  std::vector<std::string> densities;

  // Each appends a part (text right after text joins it) and returns the document.
  SectionDoc& text(const std::string& markdown);
  SectionDoc& heading(int depth, const std::string& words);  // a line "### words" at depth 1 under a "##"
  SectionDoc& figure(const std::string& file, const std::string& caption);  // a line "![caption](file)"
  SectionDoc& append(const SectionDoc& other);                              // other's parts after these
};

// Where a section is shown.
struct SectionPlace {
  int level = 2;       // the level of the heading it sits under: a heading of depth d gets level + d '#'s
  std::string folder;  // its folder as the holding document sees it: "" in table.md, "readings/loose" in reports/index.md
  // Where its figures are looked for: a figure not there is said not drawn ("": not looked for, as in
  // table.md, whose figures gnuplot draws after it is written).
  std::filesystem::path figures_in;
};

// The Markdown of `doc` at `place`: each part as written, a heading on its own line with its '#'s, a
// figure as "![caption](folder/file)" on its own line, or "*Figure `folder/file` not drawn.*".
std::string render(const SectionDoc& doc, const SectionPlace& place);

// The section's own place: table.md in its folder, under no heading of its own (depth 1 is "###").
inline const SectionPlace own_place{2, "", {}};

// FOLDER/section.json ({"schema": 1, "densities": [...], "parts": [{"text": ...} | {"heading": ...,
// "depth": d} | {"figure": file, "caption": ...}]}), then FOLDER/table.md, `doc` at its own place;
// each written atomically.
void write_section(const std::filesystem::path& folder, const SectionDoc& doc);

// FOLDER/section.json, or nothing when the folder has none. A file there that is not JSON or not of
// that shape (a part of no known kind, a depth below 1, a figure's file with a '/') throws
// std::runtime_error naming the file and the part.
std::optional<SectionDoc> read_section_doc(const std::filesystem::path& folder);

}  // namespace validation
