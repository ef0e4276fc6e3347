// validate: compares a study's results with the stored references (reference_data/paper.yaml),
// writes validation.json and validation.md, and exits 1 if a must-pass row fails.
//   validate --results DIR --references FILE --out DIR
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "config/yaml_section.hpp"
#include "quantities.hpp"
#include "results.hpp"

namespace {

struct Row {
  std::string name, quantity, density, check, reason, source;
  double reference = 0, tolerance = 0;
  int cycle = 0, from_cycle = 0, to_cycle = 0;
  bool must_pass = false;
};

// Rows of the reference file; with profile "quick" only rows that have a `quick` entry, with its
// tolerance and must_pass (the quick profile's samples are smaller and its tests shorter).
std::vector<Row> load_references(const std::string& file, const std::string& profile) {
  dem::Section root = dem::Section::load_file(file);
  root.text("source", std::nullopt, "where the reference values come from");
  std::vector<Row> rows;
  for (dem::Section& s : root.list("rows", "the checked statements")) {
    Row r;
    r.name = s.text("name", std::nullopt, "row name");
    r.quantity = s.text("quantity", std::nullopt, "what is computed");
    if (!validation::known_quantity(r.quantity)) s.fail("quantity", "unknown quantity '" + r.quantity + "'");
    r.density = s.choice("density", {"loose", "medium", "dense"}, std::nullopt, "which sample");
    r.reference = s.number("reference", "", {-1e9, 1e9}, std::nullopt, "reference value");
    r.check = s.choice("check", {"within", "at_least", "at_most"}, std::nullopt, "how measured and reference compare");
    r.tolerance = s.number("tolerance", "", {0, 1e9}, 0.0, "allowed |measured - reference| for check: within");
    r.must_pass = s.boolean("must_pass", false, "a failure fails the validation");
    r.reason = s.text("reason", std::nullopt, "why this tolerance");
    r.source = s.text("source", std::nullopt, "table, figure or section of the paper");
    r.cycle = static_cast<int>(s.integer("cycle", 0, 1000, 0, "cycle for per-cycle quantities"));
    r.from_cycle = static_cast<int>(s.integer("from_cycle", 0, 1000, 0, "first cycle of a change"));
    r.to_cycle = static_cast<int>(s.integer("to_cycle", 0, 1000, 0, "last cycle of a change"));
    bool keep = profile == "paper";
    if (s.has("quick")) {
      dem::Section q = s.child("quick", "tolerance and must_pass of the row for the quick profile");
      const double tol = q.number("tolerance", "", {0, 1e9}, r.tolerance, "tolerance at the quick size");
      const bool must = q.boolean("must_pass", false, "must pass at the quick size");
      const std::string why = q.text("reason", std::nullopt, "why the quick tolerance differs");
      q.finish();
      if (profile == "quick") r.tolerance = tol, r.must_pass = must, r.reason = why, keep = true;
    }
    s.finish();
    if (keep) rows.push_back(r);
  }
  root.finish();
  return rows;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

// A Markdown table cell: '|' would end the cell.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::string results, references, out, profile = "paper";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--results") results = argv[i + 1];
    else if (a == "--references") references = argv[i + 1];
    else if (a == "--out") out = argv[i + 1];
    else if (a == "--profile") profile = argv[i + 1];
    else { std::fprintf(stderr, "validate: unknown option '%s'\n", a.c_str()); return 2; }
  }
  if (results.empty() || references.empty() || out.empty()) {
    std::fprintf(stderr, "usage: validate --results DIR --references reference_data/paper.yaml --out DIR [--profile paper|quick]\n");
    return 2;
  }
  std::vector<Row> rows;
  try {
    if (profile != "paper" && profile != "quick") throw std::runtime_error("--profile must be paper or quick");
    rows = load_references(references, profile);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::vector<std::string> missing;
  const auto all = validation::load_results(results, {"loose", "medium", "dense"}, missing);
  fs::create_directories(out);
  std::ofstream json(fs::path(out) / "validation.json"), md(fs::path(out) / "validation.md");
  json << "{\n  \"profile\": " << json_string(profile) << ",\n  \"results\": " << json_string(fs::absolute(results).string()) << ",\n  \"references\": "
       << json_string(references) << ",\n  \"missing_results\": [";
  for (std::size_t i = 0; i < missing.size(); ++i) json << (i ? ", " : "") << json_string(missing[i]);
  json << "],\n  \"rows\": [\n";
  md << "| check | measured | reference | tolerance | difference | pass | must pass | source | reason | note |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  int failed_must = 0, passed = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    const validation::Measured m =
        validation::compute({r.quantity, r.density, r.cycle, r.from_cycle, r.to_cycle}, all.at(r.density));
    bool pass = false;
    if (m.value) {
      const double v = *m.value;
      pass = r.check == "within" ? std::abs(v - r.reference) <= r.tolerance + 1e-12
             : r.check == "at_least" ? v >= r.reference
                                     : v <= r.reference;
    }
    passed += pass;
    if (!pass && r.must_pass) ++failed_must;
    const std::string tol = r.check == "within" ? "± " + number(r.tolerance) : (r.check == "at_least" ? "≥ reference" : "≤ reference");
    json << "    {\"name\": " << json_string(r.name) << ", \"quantity\": " << json_string(r.quantity)
         << ", \"density\": " << json_string(r.density) << ", \"measured\": " << (m.value ? number(*m.value) : "null")
         << ", \"reference\": " << number(r.reference) << ", \"check\": " << json_string(r.check)
         << ", \"tolerance\": " << number(r.tolerance) << ", \"pass\": " << (pass ? "true" : "false")
         << ", \"must_pass\": " << (r.must_pass ? "true" : "false") << ", \"source\": " << json_string(r.source)
         << ", \"reason\": " << json_string(r.reason) << ", \"note\": " << json_string(m.note) << "}"
         << (i + 1 < rows.size() ? "," : "") << "\n";
    md << "| " << cell(r.name) << " | " << (m.value ? number(*m.value) : "—") << " | " << number(r.reference) << " | " << tol
       << " | " << (m.value && r.check == "within" ? number(*m.value - r.reference) : "") << " | "
       << (pass ? "✅ pass" : "❌ fail") << " | " << (r.must_pass ? "yes" : "no") << " | " << cell(r.source) << " | "
       << cell(r.reason) << " | " << cell(m.note) << " |\n";
  }
  json << "  ],\n  \"passed\": " << passed << ",\n  \"total\": " << rows.size() << ",\n  \"must_pass_failed\": "
       << failed_must << "\n}\n";
  std::printf("validation: %d of %zu rows pass, %d must-pass rows fail; %zu result files missing -> %s\n", passed,
              rows.size(), failed_must, missing.size(), (fs::path(out) / "validation.json").c_str());
  return failed_must > 0 ? 1 : 0;
}
