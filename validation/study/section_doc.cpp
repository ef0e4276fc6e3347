#include "study/section_doc.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "study/json_file.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

constexpr int section_doc_schema = 1;

}  // namespace

SectionDoc& SectionDoc::text(const std::string& markdown) {
  if (markdown.empty()) return *this;
  if (!parts.empty() && parts.back().kind == SectionPart::Kind::text)
    parts.back().text += markdown;
  else
    parts.push_back({SectionPart::Kind::text, markdown, 0, ""});
  return *this;
}

SectionDoc& SectionDoc::heading(int depth, const std::string& words) {
  parts.push_back({SectionPart::Kind::heading, words, depth, ""});
  return *this;
}

SectionDoc& SectionDoc::figure(const std::string& file, const std::string& caption) {
  parts.push_back({SectionPart::Kind::figure, caption, 0, file});
  return *this;
}

SectionDoc& SectionDoc::append(const SectionDoc& other) {
  for (const SectionPart& p : other.parts) {
    if (p.kind == SectionPart::Kind::text) text(p.text);
    else parts.push_back(p);
  }
  return *this;
}

std::string render(const SectionDoc& doc, const SectionPlace& place) {
  std::string out;
  const std::string folder = place.folder.empty() ? "" : place.folder + "/";
  for (const SectionPart& p : doc.parts) {
    switch (p.kind) {
      case SectionPart::Kind::text:
        out += p.text;
        break;
      case SectionPart::Kind::heading:
        out += std::string(static_cast<std::size_t>(place.level + p.depth), '#') + " " + p.text + "\n";
        break;
      case SectionPart::Kind::figure: {
        std::error_code ec;
        const bool drawn = place.figures_in.empty() || fs::exists(place.figures_in / p.file, ec);
        out += drawn ? "![" + p.text + "](" + folder + p.file + ")\n" : "*Figure `" + folder + p.file + "` not drawn.*\n";
        break;
      }
    }
  }
  return out;
}

void write_section(const fs::path& folder, const SectionDoc& doc) {
  nlohmann::ordered_json j;
  j["schema"] = section_doc_schema;
  j["densities"] = doc.densities;
  nlohmann::ordered_json parts = nlohmann::ordered_json::array();
  for (const SectionPart& p : doc.parts) {
    nlohmann::ordered_json part;
    switch (p.kind) {
      case SectionPart::Kind::text: part["text"] = p.text; break;
      case SectionPart::Kind::heading: part["heading"] = p.text, part["depth"] = p.depth; break;
      case SectionPart::Kind::figure: part["figure"] = p.file, part["caption"] = p.text; break;
    }
    parts.push_back(std::move(part));
  }
  j["parts"] = std::move(parts);
  dem::write_file_atomically((folder / section_doc_file).string(), j.dump(1) + "\n");
  dem::write_file_atomically((folder / "table.md").string(), render(doc, own_place));
}

std::optional<SectionDoc> read_section_doc(const fs::path& folder) {
  const fs::path file = folder / section_doc_file;
  std::error_code ec;
  if (!fs::exists(file, ec)) return std::nullopt;
  const nlohmann::json j = read_json_file(file.string());  // not JSON: an error naming the file
  const auto bad = [&](const std::string& why) {
    return std::runtime_error(file.string() + ": " + why + " (written by build/bin/compare-runs; write the section again)");
  };
  if (!j.is_object()) throw bad("not an object");
  if (!j.contains("schema") || !j.at("schema").is_number_integer() || j.at("schema").get<int>() != section_doc_schema)
    throw bad("schema must be " + std::to_string(section_doc_schema));
  if (!j.contains("parts") || !j.at("parts").is_array()) throw bad("no \"parts\" list");
  SectionDoc doc;
  if (j.contains("densities")) {
    if (!j.at("densities").is_array()) throw bad("\"densities\" is not a list");
    for (const auto& d : j.at("densities")) {
      if (!d.is_string()) throw bad("a density is not text");
      doc.densities.push_back(d.get<std::string>());
    }
  }
  std::size_t index = 0;
  for (const auto& p : j.at("parts")) {
    const std::string at = "parts[" + std::to_string(index++) + "]";
    const auto text_of = [&](const char* key) {
      if (!p.contains(key) || !p.at(key).is_string()) throw bad(at + "." + key + ": missing or not text");
      return p.at(key).get<std::string>();
    };
    if (!p.is_object()) throw bad(at + ": not an object");
    if (p.contains("text")) {
      doc.parts.push_back({SectionPart::Kind::text, text_of("text"), 0, ""});
    } else if (p.contains("heading")) {
      if (!p.contains("depth") || !p.at("depth").is_number_integer() || p.at("depth").get<int>() < 1 || p.at("depth").get<int>() > 4)
        throw bad(at + ".depth: must be an integer in [1, 4]");
      doc.parts.push_back({SectionPart::Kind::heading, text_of("heading"), p.at("depth").get<int>(), ""});
    } else if (p.contains("figure")) {
      const std::string figure = text_of("figure");
      if (figure.empty() || figure.find('/') != std::string::npos) throw bad(at + ".figure: must be a file name in the section's folder, got '" + figure + "'");
      doc.parts.push_back({SectionPart::Kind::figure, text_of("caption"), 0, figure});
    } else {
      throw bad(at + ": neither \"text\", \"heading\" nor \"figure\"");
    }
  }
  return doc;
}

}  // namespace validation
