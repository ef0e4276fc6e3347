// validate: judges a study's results against the stored references (reference_data/paper.yaml),
// writes validation.json and validation.md.
//   validate --results DIR --references FILE --out DIR [--profile paper|quick]
// Exit status: 0 only when everything asked for was done and judged: every result of every sample
// (the samples runs.tsv lists) read, every row judged, no must-pass row inconsistent; 1 otherwise
// (the tables are still written, and stderr says why); 2 for bad arguments, a references file that
// cannot be read, a results folder that does not exist or an --out that is not a folder.
// DIR is a study's results: an ensemble (DIR/seed<N>/, one folder per sample) or one sample.
// Every row is computed per sample; its verdict compares the paper's value, widened by the row's
// tolerance, with the 95 % prediction interval of a single sample of the ensemble (rows.hpp).
#include <algorithm>
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

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "io/atomic_file.hpp"
#include "format.hpp"
#include "rows.hpp"

namespace {

using validation::cell;
using validation::number;

std::string number_or_dash(const std::optional<double>& x) { return x ? number(*x) : "—"; }

// The paper's statement as a region: "0.73 ± 0.02", "≥ 0.05", "≤ 0".
std::string statement(const validation::Row& r) {
  if (r.check == "within") return number(r.reference) + (r.tolerance > 0 ? " ± " + number(r.tolerance) : "");
  return (r.check == "at_least" ? "≥ " : "≤ ") + number(r.reference);
}

nlohmann::json json_number(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(nullptr); }

// "mean ± sd (n)", the digits from the scatter (format.hpp).
std::string mean_sd_n(const validation::RowResult& e) {
  if (!e.valued) return "—";
  return (e.valued > 1 ? validation::mean_pm_sd(e.spread.mean, e.spread.sd) : number(e.spread.mean)) + " (" + std::to_string(e.valued) + ")";
}

// The prediction interval to the digits of the scatter.
std::string interval(const validation::RowResult& e) {
  if (!e.spread.low) return "—";
  return "[" + validation::to_scatter(*e.spread.low, e.spread.sd) + ", " + validation::to_scatter(*e.spread.high, e.spread.sd) + "]";
}

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
  std::error_code ec;
  if (!fs::is_directory(results, ec)) {
    std::fprintf(stderr, "error: --results '%s' %s (a study's results folder: seed<N>/ folders or one sample's results)\n",
                 results.c_str(), fs::exists(results, ec) ? "is not a folder" : "does not exist");
    return 2;
  }
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    std::fprintf(stderr, "error: --out '%s' is not a folder (validate writes validation.json, validation.md and verdicts.md into it)\n", out.c_str());
    return 2;
  }
  try {
    fs::create_directories(out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --out '%s': cannot create the folder: %s\n", out.c_str(), e.what());
    return 2;
  }
  std::vector<std::string> missing;
  const auto samples = validation::load_samples(results, {"loose", "medium", "dense"}, missing);
  // A sample the study lists (runs.tsv) whose folder is gone counts as missing too.
  std::vector<std::string> missing_samples;
  for (const std::string& name : validation::listed_samples(results))
    if (std::none_of(samples.begin(), samples.end(), [&](const validation::Sample& s) { return s.name == name; }))
      missing_samples.push_back(name);
  std::ostringstream md;
  nlohmann::ordered_json json;
  json["profile"] = profile;
  json["references"] = references;
  json["rules"] = {
      {"interval", "consistent: the paper's value, widened by the row's tolerance, overlaps the 95 % prediction interval of one sample (mean -/+ t(0.975, n-1) sd sqrt(1 + 1/n))"},
      {"majority", "consistent: the paper's statement holds in more than half of the samples"},
      {"both", "not judged with fewer than 2 samples with a value"}};
  json["samples"] = nlohmann::json::array();
  for (const validation::Sample& s : samples) json["samples"].push_back(s.name);
  json["missing_samples"] = missing_samples;
  json["missing_results"] = nlohmann::json::array();
  for (const std::string& m : missing) json["missing_results"].push_back(fs::relative(m, results).string());
  json["rows"] = nlohmann::json::array();
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
    nlohmann::ordered_json row = {{"name", r.name}, {"group", r.group}, {"quantity", r.quantity}, {"density", r.density},
                                  {"reference", r.reference}, {"check", r.check}, {"tolerance", r.tolerance},
                                  {"resolution", r.resolution}};
    row["per_sample"] = nlohmann::json::array();
    for (std::size_t k = 0; k < e.samples.size(); ++k) {
      const auto& ps = e.samples[k];
      row["per_sample"].push_back({{"sample", ps.sample}, {"value", json_number(ps.measured.value)}, {"note", ps.measured.note}});
      if (k) values += ", ";
      values += e.valued > 1 && ps.measured.value ? validation::to_scatter(*ps.measured.value, e.spread.sd) : number_or_dash(ps.measured.value);
    }
    row["n"] = e.valued;
    row["mean"] = e.valued ? nlohmann::json(e.spread.mean) : nlohmann::json(nullptr);
    row["sd"] = e.valued > 1 ? nlohmann::json(e.spread.sd) : nlohmann::json(nullptr);
    row["prediction_interval"] = {json_number(e.spread.low), json_number(e.spread.high)};
    row["holds_in"] = e.holds;
    row["rule"] = r.rule;
    row["verdict"] = validation::to_string(e.verdict);
    row["must_pass"] = r.must_pass;
    row["source"] = r.source;
    row["reason"] = r.reason;
    json["rows"].push_back(row);
    const char* mark = e.verdict == Verdict::Consistent ? "✅ consistent" : e.verdict == Verdict::Inconsistent ? "❌ inconsistent" : "— not judged";
    md << "| " << cell(r.name) << " | " << statement(r) << " | " << values << " | "
       << mean_sd_n(e) << " | " << interval(e) << " | "
       << e.holds << " of " << e.valued << " | " << (r.rule == "majority" ? "holds in > half" : "interval") << " | " << mark
       << " | " << (r.must_pass ? "yes" : "no") << " | " << cell(r.source)
       << " | " << cell(r.reason) << " |\n";
    if (e.verdict != Verdict::Consistent) {
      const auto c = cause.find(r.name);
      misses << "| " << cell(r.name) << " | " << mark << " | " << statement(r) << " | "
             << interval(e) << " | " << e.holds
             << " of " << e.valued << " | "
             << cell(c != cause.end() ? c->second : decisions_file.empty() ? "—" : "the decisions study has not judged this row")
             << " |\n";
    }
  }
  json["consistent"] = count[Verdict::Consistent];
  json["inconsistent"] = count[Verdict::Inconsistent];
  json["not_judged"] = count[Verdict::NotJudged];
  json["total"] = rows.size();
  json["must_pass_inconsistent"] = failed_must;
  // Everything asked for done and judged (the exit status 0).
  json["complete"] = missing.empty() && missing_samples.empty() && count[Verdict::NotJudged] == 0;
  std::ostringstream verdicts;
  verdicts << "Of " << rows.size() << " rows, **" << count[Verdict::Consistent] << " consistent**, **" << count[Verdict::Inconsistent]
           << " inconsistent**, " << count[Verdict::NotJudged] << " not judged, over " << samples.size() << " sample"
           << (samples.size() == 1 ? "" : "s") << " per density. A value read from the paper (rule *interval*) is consistent "
           << "when it, widened by the row's reading tolerance, overlaps the 95 % prediction interval of one sample of ours (mean "
              "± t(0.975, n−1) · sd · √(1 + 1/n)); a trend or an ordering (rule *holds in > half*) is consistent when it holds in "
              "more than half of our samples. With fewer than two samples a row is not judged.\n";
  if (!missing.empty() || !missing_samples.empty())
    verdicts << "\n**Incomplete:** " << missing.size() << " result file(s) missing or not complete"
             << (missing_samples.empty() ? std::string() : ", and " + std::to_string(missing_samples.size()) + " sample(s) that `runs.tsv` lists have no folder")
             << "; the rows are judged on what is there.\n";
  if (!misses.str().empty())
    verdicts << "\nThe rows that are not consistent, and what the decisions study found for each (its own ensemble, "
                "`make decisions`):\n\n| row | verdict | paper | interval of one sample | holds in | cause |\n|---|---|---|---|---|---|\n"
             << misses.str();
  try {
    dem::write_file_atomically((fs::path(out) / "verdicts.md").string(), verdicts.str());
    dem::write_file_atomically((fs::path(out) / "validation.json").string(), json.dump(2) + "\n");
    dem::write_file_atomically((fs::path(out) / "validation.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("validation of %zu sample%s: %d consistent, %d inconsistent, %d not judged of %zu rows; %d must-pass rows inconsistent; %zu result files missing, %zu samples missing -> %s\n",
              samples.size(), samples.size() == 1 ? "" : "s", count[Verdict::Consistent], count[Verdict::Inconsistent],
              count[Verdict::NotJudged], rows.size(), failed_must, missing.size(), missing_samples.size(),
              (fs::path(out) / "validation.json").c_str());
  int status = 0;
  if (!missing_samples.empty()) {
    std::string names;
    for (const std::string& m : missing_samples) names += (names.empty() ? "" : ", ") + m;
    std::fprintf(stderr, "error: %s/runs.tsv lists %zu sample(s) whose folder is gone: %s\n", results.c_str(), missing_samples.size(), names.c_str());
    status = 1;
  }
  if (!missing.empty()) {
    std::fprintf(stderr, "error: %zu result file(s) missing or not complete, e.g. %s\n", missing.size(), missing.front().c_str());
    status = 1;
  }
  if (count[Verdict::NotJudged] > 0) {
    std::fprintf(stderr, "error: %d row(s) not judged (fewer than 2 samples with a value)\n", count[Verdict::NotJudged]);
    status = 1;
  }
  if (failed_must > 0) {
    std::fprintf(stderr, "error: %d must-pass row(s) inconsistent with the paper\n", failed_must);
    status = 1;
  }
  return status;
}
