// A section's parts as data (validation/study/section_doc.hpp): placed under any heading, its
// figures' paths from any folder, without its Markdown read back; section.json and table.md agree.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "study/section_doc.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

validation::SectionDoc planted() {
  validation::SectionDoc doc;
  doc.text("Measured at 8,000 spheres.\n\n").heading(1, "fabric").text("\n").figure("tornado_fabric.png", "tornado chart: fabric");
  doc.text("\n| row | shift |\n|---|---|\n").text("| a | +1.0 |\n").heading(2, "inside");
  doc.densities = {"medium", "dense"};
  return doc;
}

}  // namespace

TEST_CASE("section parts: placed at their own place and under a report's heading", "[section_doc]") {
  const validation::SectionDoc doc = planted();
  REQUIRE(doc.parts.size() == 6);  // text after text is one part
  CHECK(validation::render(doc, validation::own_place) ==
        "Measured at 8,000 spheres.\n\n### fabric\n\n![tornado chart: fabric](tornado_fabric.png)\n\n| row | shift |\n|---|---|\n"
        "| a | +1.0 |\n#### inside\n");
  // Under a level-3 heading of the report, from the report's folder: headings one level down, the
  // figure's path from there, and said not drawn when it is not in the folder looked at.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "section_doc" / "readings" / "medium_dense";
  fs::remove_all(dir.parent_path().parent_path());
  fs::create_directories(dir);
  const std::string missing = validation::render(doc, {3, "readings/medium_dense", dir});
  CHECK(missing.find("#### fabric\n") != std::string::npos);
  CHECK(missing.find("##### inside\n") != std::string::npos);
  CHECK(missing.find("*Figure `readings/medium_dense/tornado_fabric.png` not drawn.*\n") != std::string::npos);
  std::ofstream(dir / "tornado_fabric.png") << "png";
  CHECK(validation::render(doc, {3, "readings/medium_dense", dir}).find("![tornado chart: fabric](readings/medium_dense/tornado_fabric.png)\n") !=
        std::string::npos);
}

TEST_CASE("section.json: written with its table.md, read back whole; a bad one refused naming the part", "[section_doc]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "section_doc_file";
  fs::remove_all(dir);
  fs::create_directories(dir);
  CHECK_FALSE(validation::read_section_doc(dir).has_value());  // none written: none read
  const validation::SectionDoc doc = planted();
  validation::write_section(dir, doc);
  const std::optional<validation::SectionDoc> back = validation::read_section_doc(dir);
  REQUIRE(back.has_value());
  CHECK(back->densities == doc.densities);
  CHECK(validation::render(*back, validation::own_place) == read_all(dir / "table.md"));
  CHECK(validation::render(*back, {4, "x", {}}) == validation::render(doc, {4, "x", {}}));

  const auto refused = [&](const std::string& json, const std::string& message) {
    std::ofstream(dir / "section.json") << json;
    CHECK_THROWS_WITH(validation::read_section_doc(dir), Catch::Contains("section.json: " + message));
  };
  refused(R"({"schema": 2, "parts": []})", "schema must be 1");
  refused(R"({"schema": 1})", "no \"parts\" list");
  refused(R"({"schema": 1, "parts": [{"text": "a"}, {"heading": "h", "depth": 0}]})", "parts[1].depth: must be an integer in [1, 4]");
  refused(R"({"schema": 1, "parts": [{"figure": "../x.png", "caption": "c"}]})", "parts[0].figure: must be a file name");
  refused(R"({"schema": 1, "parts": [{"image": "x.png"}]})", "parts[0]: neither");
  refused(R"({"schema": 1, "parts": [{"figure": "x.png"}]})", "parts[0].caption: missing or not text");
}

TEST_CASE("the committed sections: each section.json renders its table.md byte for byte", "[section_doc]") {
  // What the report shows of a section (section.json) and what its folder shows (table.md) are one
  // text: a section.json edited or migrated apart from its table.md fails here.
  const fs::path reports = fs::path(DEM_SOURCE_DIR) / "reports";
  int compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(reports)) {
    if (e.path().filename() != validation::section_doc_file) continue;
    INFO(e.path().string());
    const std::optional<validation::SectionDoc> doc = validation::read_section_doc(e.path().parent_path());
    REQUIRE(doc.has_value());
    CHECK(validation::render(*doc, validation::own_place) == read_all(e.path().parent_path() / "table.md"));
    ++compared;
  }
  CHECK(compared == 6);  // decisions, three readings, critical state, liquefaction
}
