// validate: judges a study's results against the stored references (reference_data/paper.yaml),
// writes validation.json and validation.md, and exits 1 if a must-pass row is inconsistent.
//   validate --results DIR --references FILE --out DIR [--profile paper|quick]
// DIR is a study's results: an ensemble (DIR/seed<N>/, one folder per sample) or one sample.
// Every row is computed per sample; its verdict compares the paper's value, widened by the row's
// tolerance, with the 95 % prediction interval of a single sample of the ensemble (rows.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <yaml-cpp/yaml.h>

#include "io/atomic_file.hpp"
#include "format.hpp"
#include "rows.hpp"

namespace {

using validation::cell;
using validation::json_string;
using validation::number;

std::string number_or_dash(const std::optional<double>& x) { return x ? number(*x) : "—"; }

// The paper's statement as a region: "0.73 ± 0.02", "≥ 0.05", "≤ 0".
std::string statement(const validation::Row& r) {
  if (r.check == "within") return number(r.reference) + (r.tolerance > 0 ? " ± " + number(r.tolerance) : "");
  return (r.check == "at_least" ? "≥ " : "≤ ") + number(r.reference);
}

std::string json_number(const std::optional<double>& x) { return x ? number(*x) : "null"; }

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  using validation::Verdict;
  std::string results, references, out, profile = "paper", decisions_file;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--results") results = argv[i + 1];
    else if (a == "--references") references = argv[i + 1];
    else if (a == "--out") out = argv[i + 1];
    else if (a == "--profile") profile = argv[i + 1];
    else if (a == "--decisions") decisions_file = argv[i + 1];
    else { std::fprintf(stderr, "validate: unknown option '%s'\n", a.c_str()); return 2; }
  }
  if (results.empty() || references.empty() || out.empty()) {
    std::fprintf(stderr, "usage: validate --results DIR --references reference_data/paper.yaml --out DIR [--profile paper|quick] [--decisions decisions.json]\n");
    return 2;
  }
  std::vector<validation::Row> rows;
  try {
    if (profile != "paper" && profile != "quick") throw std::runtime_error("--profile must be paper or quick");
    rows = validation::load_references(references, profile);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  // The decisions study's explanation of each row (compare-runs decisions), if it has run.
  std::map<std::string, std::string> cause;
  if (!decisions_file.empty() && fs::exists(decisions_file)) {
    try {
      for (const YAML::Node& row : YAML::LoadFile(decisions_file)["rows"])
        cause[row["name"].as<std::string>()] = row["explanation"].as<std::string>();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s: %s\n", decisions_file.c_str(), e.what());
      return 2;
    }
  }
  std::vector<std::string> missing;
  const auto samples = validation::load_samples(results, {"loose", "medium", "dense"}, missing);
  fs::create_directories(out);
  std::ostringstream json, md;
  json << "{\n  \"profile\": " << json_string(profile) << ",\n  \"references\": " << json_string(references)
       << ",\n  \"rules\": {\"interval\": " << json_string("consistent: the paper's value, widened by the row's tolerance, overlaps the 95 % prediction interval of one sample (mean -/+ t(0.975, n-1) sd sqrt(1 + 1/n))")
       << ", \"majority\": " << json_string("consistent: the paper's statement holds in more than half of the samples")
       << ", \"both\": " << json_string("not judged with fewer than 2 samples with a value") << "}"
       << ",\n  \"samples\": [";
  for (std::size_t i = 0; i < samples.size(); ++i) json << (i ? ", " : "") << json_string(samples[i].name);
  json << "],\n  \"missing_results\": [";
  for (std::size_t i = 0; i < missing.size(); ++i) json << (i ? ", " : "") << json_string(fs::relative(missing[i], results).string());
  json << "],\n  \"rows\": [\n";
  md << "| check | paper | per sample | mean ± sd (n) | 95 % interval of one sample | holds in | rule | verdict | must pass | source | reason |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::map<Verdict, int> count;
  int failed_must = 0;
  std::ostringstream misses;  // the rows not consistent, with what the decisions study says of them
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const validation::Row& r = rows[i];
    const validation::RowResult e = validation::evaluate(r, samples);
    ++count[e.verdict];
    if (e.verdict == Verdict::Inconsistent && r.must_pass) ++failed_must;
    std::string values;
    json << "    {\"name\": " << json_string(r.name) << ", \"group\": " << json_string(r.group) << ", \"quantity\": "
         << json_string(r.quantity) << ", \"density\": " << json_string(r.density) << ", \"reference\": " << number(r.reference)
         << ", \"check\": " << json_string(r.check) << ", \"tolerance\": " << number(r.tolerance) << ",\n     \"per_sample\": [";
    for (std::size_t k = 0; k < e.samples.size(); ++k) {
      const auto& ps = e.samples[k];
      json << (k ? ", " : "") << "{\"sample\": " << json_string(ps.sample) << ", \"value\": " << json_number(ps.measured.value)
           << ", \"note\": " << json_string(ps.measured.note) << "}";
      if (k) values += ", ";
      values += number_or_dash(ps.measured.value);
    }
    json << "],\n     \"n\": " << e.valued << ", \"mean\": " << (e.valued ? number(e.spread.mean) : "null")
         << ", \"sd\": " << (e.valued > 1 ? number(e.spread.sd) : "null") << ", \"prediction_interval\": ["
         << json_number(e.spread.low) << ", " << json_number(e.spread.high) << "], \"holds_in\": " << e.holds
         << ", \"rule\": " << json_string(r.rule) << ", \"verdict\": " << json_string(validation::to_string(e.verdict))
         << ", \"must_pass\": " << (r.must_pass ? "true" : "false") << ", \"source\": " << json_string(r.source)
         << ", \"reason\": " << json_string(r.reason) << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
    const char* mark = e.verdict == Verdict::Consistent ? "✅ consistent" : e.verdict == Verdict::Inconsistent ? "❌ inconsistent" : "— not judged";
    md << "| " << cell(r.name) << " | " << statement(r) << " | " << values << " | "
       << (e.valued ? number(e.spread.mean) + (e.valued > 1 ? " ± " + number(e.spread.sd) : "") + " (" + std::to_string(e.valued) + ")" : "—")
       << " | " << (e.spread.low ? "[" + number(*e.spread.low) + ", " + number(*e.spread.high) + "]" : "—") << " | "
       << e.holds << " of " << e.valued << " | " << (r.rule == "majority" ? "holds in > half" : "interval") << " | " << mark
       << " | " << (r.must_pass ? "yes" : "no") << " | " << cell(r.source)
       << " | " << cell(r.reason) << " |\n";
    if (e.verdict != Verdict::Consistent) {
      const auto c = cause.find(r.name);
      misses << "| " << cell(r.name) << " | " << mark << " | " << statement(r) << " | "
             << (e.spread.low ? "[" + number(*e.spread.low) + ", " + number(*e.spread.high) + "]" : "—") << " | " << e.holds
             << " of " << e.valued << " | "
             << cell(c != cause.end() ? c->second : decisions_file.empty() ? "—" : "the decisions study has not judged this row")
             << " |\n";
    }
  }
  json << "  ],\n  \"consistent\": " << count[Verdict::Consistent] << ",\n  \"inconsistent\": " << count[Verdict::Inconsistent]
       << ",\n  \"not_judged\": " << count[Verdict::NotJudged] << ",\n  \"total\": " << rows.size()
       << ",\n  \"must_pass_inconsistent\": " << failed_must << "\n}\n";
  std::ostringstream verdicts;
  verdicts << "Of " << rows.size() << " rows, **" << count[Verdict::Consistent] << " consistent**, **" << count[Verdict::Inconsistent]
           << " inconsistent**, " << count[Verdict::NotJudged] << " not judged, over " << samples.size() << " sample"
           << (samples.size() == 1 ? "" : "s") << " per density. A value read from the paper (rule *interval*) is consistent "
           << "when it, widened by the row's reading tolerance, overlaps the 95 % prediction interval of one sample of ours (mean "
              "± t(0.975, n−1) · sd · √(1 + 1/n)); a trend or an ordering (rule *holds in > half*) is consistent when it holds in "
              "more than half of our samples. With fewer than two samples a row is not judged.\n";
  if (!misses.str().empty())
    verdicts << "\nThe rows that are not consistent, and what the decisions study found for each (its own ensemble, "
                "`make decisions`):\n\n| row | verdict | paper | interval of one sample | holds in | cause |\n|---|---|---|---|---|---|\n"
             << misses.str();
  try {
    dem::write_file_atomically((fs::path(out) / "verdicts.md").string(), verdicts.str());
    dem::write_file_atomically((fs::path(out) / "validation.json").string(), json.str());
    dem::write_file_atomically((fs::path(out) / "validation.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("validation of %zu sample%s: %d consistent, %d inconsistent, %d not judged of %zu rows; %d must-pass rows inconsistent; %zu result files missing -> %s\n",
              samples.size(), samples.size() == 1 ? "" : "s", count[Verdict::Consistent], count[Verdict::Inconsistent],
              count[Verdict::NotJudged], rows.size(), failed_must, missing.size(), (fs::path(out) / "validation.json").c_str());
  return failed_must > 0 ? 1 : 0;
}
