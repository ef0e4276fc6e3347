// validate: judges a study's results against a reference file (reference_data/paper.yaml, or a
// user's own: validation/README.md), writes validation.json, validation.md and verdicts.md.
// validation.json records the stamp of the numbers (study/stamp.hpp: engine, baseline, spheres,
// samples, date); --from-json keeps the stamp the record has (none: "not recorded"). For a study of
// variants, judged_from names the variants its rows read (a calibration's best set: which one).
//   validate --results DIR --references FILE --out DIR [--profile NAME] [--decisions decisions.json]...
//   validate --from-json validation.json --references FILE --out DIR [--profile NAME] [--decisions ...]...
// DIR is a study's results folder, with the manifest the pipeline writes (DIR/runs.tsv): an
// ensemble (DIR/seed<N>/, one folder per sample) or one sample. Each row names the runs it reads by
// the study's names (variant, density, test; row_runs.hpp), and only those runs are read.
// Exit status: 0 only when everything asked for was done and judged: every result the rows need
// read (of every sample runs.tsv lists), every row judged, no must-pass row inconsistent, no two
// samples identical in every row (judge/verdicts.hpp: identical_samples); 1
// otherwise (the tables are still written, and stderr says why); 2 for bad arguments, a reference
// file that cannot be read or has a bad row (an unknown key or quantity, a selector naming what the
// study does not have), a results folder that does not exist or has no runs.tsv, or an --out that
// is not a folder.
// --decisions may be given several times (the decisions study, the readings at the paper's size):
// each row's cause is what the files of the largest size that judged it found, said with that size,
// and what a reading that explains it does to the rows consistent here (decisions_file.hpp).
// --from-json judges every row again from the per-sample values an earlier validate recorded in its
// validation.json (the study's results need not be here: validation_file.hpp), with the same
// function as from the results (judge_values) and writes the same tables; their first line says so.
// A FILE that cannot be read, is not JSON or not a validation.json, or lacks a row of the reference
// file (or has one it does not): exit 2, naming FILE.
// --without-results keep|redraw: a --results DIR without runs.tsv (its study has not run here) is
// no error: redraw judges every row again from the committed record --out/validation.json, as
// --from-json does (its stamp kept, its tables' first line saying so); without a record, and with
// keep, --out is left as it is. Either way validate says which and, with nothing judged, exits 0.
// Every row is computed per sample; its verdict compares the reference's value, widened by the
// row's tolerance, with the 95 % prediction interval of a single sample of the ensemble (rows.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "judge/decisions_file.hpp"
#include "judge/judge_study.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/markdown_table.hpp"
#include "study/results.hpp"
#include "study/json_file.hpp"
#include "study/stamp.hpp"
#include "judge/row_runs.hpp"
#include "judge/rows.hpp"
#include "judge/study_results.hpp"
#include "judge/validation_file.hpp"
#include "judge/verdicts.hpp"
#include "io/failure.hpp"

namespace fs = std::filesystem;

namespace {

using validation::Judged;
using validation::number;
using validation::Verdict;

struct Options {
  std::string results, from_json, references, out, profile = "paper";
  bool profile_given = false;
  std::vector<std::string> decisions;  // decisions.json files, in the order given
  std::string without_results;         // "", "keep" or "redraw"
  std::vector<std::string> densities;  // only the rows of these densities (empty: every row)
  std::vector<std::string> borrow;     // --borrow DENSITY:READING:FILE, as given
  // Read from --borrow (or a record's judged_from.borrowed), and a record's variants: carried into
  // the new record.
  std::vector<validation::RecordedValidation::Borrowed> borrowed;
  std::vector<std::string> record_variants;
};

// The options, or nothing when they are wrong or --help was asked (`code`: the exit status, 0 for
// --help, 2 for bad arguments; CLI11 has printed the help, or the error naming the option).
std::optional<Options> parse_options(int argc, char** argv, int& code) {
  Options o;
  CLI::App app{"validate: judges a study's results against a reference file (the paper's, reference_data/paper.yaml, or "
               "your own: validation/README.md); writes validation.json, validation.md and verdicts.md into --out"};
  app.name("validate");
  auto* results = app.add_option("--results", o.results, "the study's results folder (its runs.tsv, written by build/bin/pipeline)");
  auto* from_json = app.add_option("--from-json", o.from_json,
                                   "an earlier validate's validation.json: every row judged again from the per-sample values it "
                                   "records, without the results");
  results->excludes(from_json);
  from_json->excludes(results);
  app.add_option("--references", o.references, "the reference file: the rows to judge")->required();
  app.add_option("--out", o.out, "the folder the tables go to (made if missing)")->required();
  auto* profile = app.add_option("--profile", o.profile, "the reference file's profile (its rows' `profiles` entries; with --from-json, "
                                                        "default: the file's)")->capture_default_str();
  app.add_option("--decisions", o.decisions,
                 "a decisions study's decisions.json (compare-runs decisions); may be given several times, each row's cause "
                 "is what the files of the largest size that judged it found")
      ->allow_extra_args(false);
  app.add_option("--densities", o.densities,
                 "judge only the rows of these densities, for a study that runs some of the reference file's densities; "
                 "validation.json records them (judged_from.densities)");
  app.add_option("--borrow", o.borrow,
                 "DENSITY:READING:FILE: a density the study does not run because its runs would be those of READING in "
                 "another study, whose decisions.json is FILE; validation.json records it (judged_from.borrowed) and the "
                 "report takes that density's verdicts from FILE")
      ->allow_extra_args(false);
  app.add_option("--without-results", o.without_results,
                 "a --results folder without runs.tsv (its study has not run here) is no error: redraw = judged again from the "
                 "committed --out/validation.json, else --out kept; keep = --out kept; says which (exit 0 when nothing is judged)")
      ->check(CLI::IsMember({"keep", "redraw"}))
      ->needs(results);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    code = rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
    return std::nullopt;
  }
  o.profile_given = profile->count() > 0;
  if (o.results.empty() == o.from_json.empty()) {
    std::fprintf(stderr, "validate: one of --results (a study's results folder) and --from-json (a validation.json) is required\n");
    code = 2;
    return std::nullopt;
  }
  if (o.profile.empty()) {
    std::fprintf(stderr, "validate: --profile: must not be empty\n");
    code = 2;
    return std::nullopt;
  }
  if (!o.without_results.empty() && !fs::exists(fs::path(o.results) / "runs.tsv")) {
    const fs::path record = fs::path(o.out) / "validation.json";
    if (o.without_results == "redraw" && fs::is_regular_file(record)) {
      std::fprintf(stderr, "validate: no results in %s; every row judged again from the committed %s (its stamp kept)\n",
                   o.results.c_str(), record.c_str());
      o.from_json = record.string(), o.results.clear();
      return o;
    }
    std::fprintf(stderr, "validate: no results in %s yet (its study has not run here); %s left as it is\n", o.results.c_str(),
                 o.out.c_str());
    code = 0;
    return std::nullopt;
  }
  return o;
}

// The decisions studies' findings (compare-runs decisions), of the files that are there (a study
// not run yet has none).
std::vector<validation::DecisionsFile> read_findings(const std::vector<std::string>& files) {
  std::vector<validation::DecisionsFile> out;
  for (const std::string& file : files) {
    if (!fs::exists(file)) continue;
    try {
      out.push_back(validation::read_decisions_file(file));
    } catch (const std::exception& e) {
      throw std::runtime_error(file + ": " + e.what());
    }
  }
  return out;
}

// An error message about --results or --out, or "" when both can be used.
std::string check_folders(const Options& o) {
  std::error_code ec;
  if (!o.results.empty() && !fs::is_directory(o.results, ec))
    return "--results '" + o.results + "' " + (fs::exists(o.results, ec) ? "is not a folder" : "does not exist") +
           " (a study's results folder: seed<N>/ folders or one sample's results)";
  if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
    return "--out '" + o.out + "' is not a folder (validate writes validation.json, validation.md and verdicts.md into it)";
  return "";
}

// Each value of a row that is not a finite number (a NaN or an infinity in a result), named with its
// row, its sample and the runs it read.
std::vector<std::string> non_finite_values(const std::vector<Judged>& judged, const std::string& results) {
  std::vector<std::string> out;
  for (const Judged& j : judged)
    for (const auto& ps : j.result.samples)
      if (ps.measured.value && !std::isfinite(*ps.measured.value)) {
        std::string runs = j.runs.preparation ? j.runs.density + "_prepare" : "";
        for (const std::string& t : j.runs.tests) runs += (runs.empty() ? "" : ", ") + j.runs.density + "_" + t;
        out.push_back("row '" + j.row.name + "': " + (ps.sample.empty() ? "the sample" : "sample " + ps.sample) + " gives " +
                      number(*ps.measured.value) + ", from " + (fs::path(results) / ps.sample).string() + " (" + runs +
                      "): a non-finite number in its results");
      }
  return out;
}

// Pairs of samples whose runs a row read are the same to the last digit (every value of the last
// rows of the preparation): a copied sample folder would count one sample twice.
std::vector<std::string> copied_samples(const std::vector<Judged>& judged, const validation::StudyResults& results) {
  std::vector<std::string> out;
  std::set<std::string> said;
  const std::vector<std::string>& samples = results.samples();
  for (const Judged& j : judged)
    for (std::size_t a = 0; a < samples.size(); ++a)
      for (std::size_t b = a + 1; b < samples.size(); ++b) {
        const validation::DensityResults* x = results.of(j.runs, samples[a]);
        const validation::DensityResults* y = results.of(j.runs, samples[b]);
        if (!x || !y || !x->prepared || !y->prepared || x->sample.empty() || x->sample != y->sample) continue;
        const std::string what = samples[a] + " and " + samples[b] + " have the same " + j.runs.density + " preparation";
        if (said.insert(what).second)
          out.push_back(what + " (every value of its last row): a copied sample folder counts one sample twice");
      }
  return out;
}


// The rows judged again from the values `record` holds (judge_recorded throws, naming the file).
std::vector<Judged> judge_record(const Options& o, const validation::RecordedValidation& record, const std::vector<validation::Row>& rows) {
  std::vector<Judged> judged;
  for (validation::RejudgedRow& r : validation::judge_recorded(record, rows, o.from_json, o.references)) {
    validation::RowRuns runs;
    runs.density = r.density;
    judged.push_back({std::move(r.row), std::move(runs), std::move(r.result)});
  }
  return judged;
}

// The stamp of the numbers judged: the results' own (stamp_of_results), or the one the record
// kept (none: every field not recorded, a record made before stamps). A stamp that cannot be read
// leaves its fields not recorded and says why: the verdicts stand without it.
validation::Stamp stamp_of(const Options& o, const std::optional<validation::RecordedValidation>& record) {
  if (record) return record->stamp;
  try {
    return validation::stamp_of_results(o.results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: the stamp (engine, baseline, size, date) not recorded: %s\n", e.what());
    return {};
  }
}

// validation.json: the options, the rules, the stamp, the samples and what is missing (a record's as it
// recorded them), every row (json_row) and the counts.
nlohmann::ordered_json validation_json(const Options& o, const std::string& label, const std::vector<Judged>& judged,
                                       const validation::VerdictCounts& count, const std::vector<std::string>& samples,
                                       const std::vector<std::string>& missing, const std::vector<std::string>& missing_samples,
                                       const std::vector<std::vector<std::string>>& identical, bool from_results,
                                       const validation::Stamp& stamp) {
  nlohmann::ordered_json json;
  json["profile"] = o.profile;
  json["references"] = o.references;
  json["judged_from"] = !from_results ? nlohmann::ordered_json{{"validation_json", o.from_json}} : nlohmann::ordered_json{{"results", o.results}};
  if (!o.densities.empty()) json["judged_from"]["densities"] = o.densities;
  // A study of variants: the ones the rows read, so that a record names the set it judged (one
  // judged again: the variants its record names).
  std::set<std::string> variants(o.record_variants.begin(), o.record_variants.end());
  for (const Judged& j : judged)
    if (from_results && j.runs.variant != "-") variants.insert(j.runs.variant);
  if (!variants.empty()) json["judged_from"]["variants"] = variants;
  for (const auto& b : o.borrowed)
    json["judged_from"]["borrowed"].push_back({{"density", b.density}, {"reading", b.reading}, {"decisions", b.decisions}});
  json["stamp"] = validation::stamp_json(stamp);
  json["rules"] = {
      {"interval", "consistent: the " + label + "'s value, widened by the row's tolerance, overlaps the " +
                       validation::number(100 * validation::prediction_level) + " % prediction interval of one sample (mean -/+ t(" +
                       validation::number(0.5 + validation::prediction_level / 2) + ", n-1) sd sqrt(1 + 1/n))"},
      {"majority", "consistent: the " + label + "'s statement holds in more than half of the samples"},
      {"every", "consistent: the " + label + "'s statement holds in every sample with a value, one or more (a case without scatter)"},
      {"both", "interval and majority: not judged with fewer than 2 samples with a value"}};
  json["samples"] = samples;
  json["missing_samples"] = missing_samples;
  json["identical_samples"] = identical;  // groups of samples that are one sample (identical_samples)
  json["missing_results"] = nlohmann::json::array();
  for (const std::string& m : missing)  // lexical: a link loop cannot throw; a record's are relative already
    json["missing_results"].push_back(from_results ? fs::path(m).lexically_relative(o.results).string() : m);
  json["rows"] = nlohmann::json::array();
  for (const Judged& j : judged) json["rows"].push_back(validation::json_row(j));
  json["consistent"] = count.of(Verdict::Consistent);
  json["inconsistent"] = count.of(Verdict::Inconsistent);
  json["not_judged"] = count.of(Verdict::NotJudged);
  json["total"] = judged.size();
  json["must_pass_inconsistent"] = count.must_pass_failed;
  // Everything asked for done and judged (the exit status 0).
  json["complete"] = missing.empty() && missing_samples.empty() && identical.empty() && count.of(Verdict::NotJudged) == 0;
  return json;
}

// A quasi-static row is not judged by design (its warning says why); any other row not judged
// lacked samples with a value, and fails: false, said on stderr.
bool all_rows_judged(const std::vector<Judged>& judged) {
  int lacking = 0;
  std::string names;
  for (const Judged& j : judged)
    if (j.result.verdict == Verdict::NotJudged && !j.row.quasi_static) names += (names.empty() ? "" : "; ") + j.row.name, ++lacking;
  if (lacking > 0) std::fprintf(stderr, "error: %d row(s) not judged (fewer than 2 samples with a value): %s\n", lacking, names.c_str());
  return lacking == 0;
}

// False, said on stderr, when groups of samples give the same values in every row.
bool samples_distinct(const std::vector<std::vector<std::string>>& identical) {
  for (const std::vector<std::string>& group : identical) {
    std::string names;
    for (std::size_t k = 0; k < group.size(); ++k) names += (k == 0 ? "" : k + 1 == group.size() ? " and " : ", ") + group[k];
    std::fprintf(stderr, "error: samples %s give the same values to the last digit in every row: one sample counted %zu times, "
                 "not independent samples (their seeds set by hand, e.g. particles.lattice.seed in preparation_set, or a copied "
                 "folder?); the verdicts take them as independent\n", names.c_str(), group.size());
  }
  return identical.empty();
}

// What validate reads before judging: the record of --from-json (its profile and densities taken
// when not given), the reference file's rows of the densities judged, the decisions files.
struct Inputs {
  validation::References refs;
  std::vector<validation::DecisionsFile> findings;
  std::optional<validation::RecordedValidation> record;
};

// The inputs, or nothing after saying on stderr what is wrong (exit 2).
std::optional<Inputs> read_inputs(Options& o) {
  Inputs in;
  validation::References& refs = in.refs;
  std::optional<validation::RecordedValidation>& record = in.record;
  if (!o.from_json.empty()) {
    std::error_code ec;
    if (!fs::exists(o.from_json, ec)) {
      std::fprintf(stderr, "error: --from-json '%s' does not exist (an earlier validate's validation.json)\n", o.from_json.c_str());
      return std::nullopt;
    }
    try {
      record = validation::read_validation_file(o.from_json);  // errors name the file
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --from-json %s\n", e.what());
      return std::nullopt;
    }
    if (!o.profile_given) o.profile = record->profile;  // judged again at the profile it was judged at
  }
  try {
    refs = validation::read_references(o.references, o.profile);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return std::nullopt;
  }
  if (record && o.densities.empty()) o.densities = record->densities;  // judged again on the densities it was judged on
  if (record) o.record_variants = record->variants, o.borrowed = o.borrow.empty() ? record->borrowed : o.borrowed;
  try {  // checked against every row of the reference file, before keep_densities leaves some out
    for (const std::string& arg : o.borrow) o.borrowed.push_back(validation::borrowed_density(arg, o.densities, refs.rows, o.references));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --borrow: %s\n", e.what());
    return std::nullopt;
  }
  if (const std::string bad = validation::keep_densities(refs.rows, o.densities); !bad.empty()) {
    std::fprintf(stderr, "error: --densities: %s\n", bad.c_str());
    return std::nullopt;
  }
  if (record) validation::erase_other_densities(record->rows, o.densities);  // a record of every density judged again on some of them
  try {
    in.findings = read_findings(o.decisions);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --decisions %s\n", e.what());
    return std::nullopt;
  }
  // A file that declares profiles knows them all: another name than those and paper (every row as
  // written) is a typo, which would judge every row as written.
  if (!refs.profiles.empty() && !refs.profiles.count(o.profile) && o.profile != "paper") {
    std::string known = "paper (every row as written)";
    for (const std::string& p : refs.profiles) known += ", " + p;
    std::fprintf(stderr, "error: --profile '%s': no row of %s has it; its profiles: %s\n", o.profile.c_str(), o.references.c_str(),
                 known.c_str());
    return std::nullopt;
  }
  return in;
}

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  int code = 2;
  std::optional<Options> opt = parse_options(argc, argv, code);
  if (!opt) return code;
  Options& o = *opt;
  std::optional<Inputs> in = read_inputs(o);
  if (!in) return 2;
  validation::References& refs = in->refs;
  std::vector<validation::DecisionsFile>& findings = in->findings;
  std::optional<validation::RecordedValidation>& record = in->record;
  if (const std::string bad = check_folders(o); !bad.empty()) {
    std::fprintf(stderr, "error: %s\n", bad.c_str());
    return 2;
  }
  try {
    fs::create_directories(o.out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --out '%s': cannot create the folder: %s\n", o.out.c_str(), e.what());
    return 2;
  }
  // The rows judged: from the results (the study's names and the runs each row reads: a row that
  // names what the study lacks is refused), or from the values the record holds.
  std::optional<validation::StudyResults> results;
  std::vector<Judged> judged;
  try {
    judged = record ? judge_record(o, *record, refs.rows) : validation::judge_study(o.results, refs.rows, results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s%s\n", record ? "--from-json " : "", e.what());
    return 2;
  }
  const validation::VerdictCounts count = validation::count_verdicts(judged);
  const int consistent = count.of(Verdict::Consistent), inconsistent = count.of(Verdict::Inconsistent),
            not_judged = count.of(Verdict::NotJudged);
  std::vector<std::string> missing, missing_samples, samples;
  if (results) {
    missing = results->missing();
    missing_samples = results->missing_samples();
    samples = results->samples();
  } else {
    missing = record->missing_results;
    missing_samples = record->missing_samples;
    samples = record->samples;
  }

  const std::vector<std::vector<std::string>> identical = validation::identical_samples(judged);
  const nlohmann::ordered_json json = validation_json(o, refs.label, judged, count, samples, missing, missing_samples, identical,
                                                     results.has_value(), stamp_of(o, record));
  validation::VerdictsContext context;
  context.label = refs.label;
  context.provenance = record ? "Judged again by `validate --from-json` from the per-sample values recorded in `" + o.from_json +
                                    "` (the results are not read), against `" + o.references + "` (profile " + o.profile + ")."
                              : "Judged by `validate` from the results in `" + o.results + "`, against `" + o.references +
                                    "` (profile " + o.profile + ").";
  context.samples = samples.size();
  context.missing = missing.size();
  context.missing_samples = missing_samples.size();
  context.with_causes = !o.decisions.empty();
  context.findings = findings;
  try {
    const fs::path out(o.out);
    dem::write_file_atomically((out / "verdicts.md").string(), validation::verdicts_text(judged, context));
    // With causes, the same as the report shows it: its cause cells link to the causes in the
    // report's appendix (without causes there is no link, and the report shows verdicts.md).
    if (context.with_causes) {
      validation::VerdictsContext in_report = context;
      in_report.causes_document = "";
      dem::write_file_atomically((out / validation::verdicts_in_report_file).string(), validation::verdicts_text(judged, in_report));
    } else {
      fs::remove(out / validation::verdicts_in_report_file);
    }
    // The causes in full, which the compact table links to; none: no stale file from an earlier run.
    if (const std::string causes = validation::causes_text(judged, context); !causes.empty())
      dem::write_file_atomically((out / "causes.md").string(), context.provenance + "\n\n" + causes);
    else
      fs::remove(out / "causes.md");
    dem::write_file_atomically((out / "validation.json").string(), json.dump(2) + "\n");
    dem::write_file_atomically((out / "validation.md").string(),
                               context.provenance + "\n\n" + validation::validation_table(judged, refs.label));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  const std::size_t n_samples = samples.size();
  std::printf("validation of %zu sample%s: %d consistent, %d inconsistent, %d not judged of %zu rows; %d must-pass rows inconsistent; %zu result files missing, %zu samples missing -> %s%s\n",
              n_samples, n_samples == 1 ? "" : "s", consistent, inconsistent, not_judged, judged.size(), count.must_pass_failed,
              missing.size(), missing_samples.size(), (fs::path(o.out) / "validation.json").c_str(),
              record ? (" (judged again from " + o.from_json + ")").c_str() : "");
  for (const Judged& j : judged)  // warnings change no exit status: the verdict stands, and says it
    for (const std::string& w : j.result.warnings) std::fprintf(stderr, "warning: %s: %s\n", j.row.name.c_str(), w.c_str());
  int status = 0;
  if (!missing_samples.empty()) {
    std::string names;
    for (const std::string& m : missing_samples) names += (names.empty() ? "" : ", ") + m;
    std::fprintf(stderr, "error: %s/runs.tsv lists %zu sample(s) whose folder is gone: %s\n",
                 record ? (o.from_json + ": the study's").c_str() : o.results.c_str(), missing_samples.size(), names.c_str());
    status = 1;
  }
  if (!missing.empty()) {
    std::fprintf(stderr, "error: %zu result file(s) missing or not complete (of the runs the rows read), e.g. %s\n", missing.size(), missing.front().c_str());
    if (results) validation::report_unreadable("validate", missing);  // those that are there: why each is not a result
    status = 1;
  }
  if (!all_rows_judged(judged)) status = 1;
  if (results) {  // what only the results show
    if (const std::vector<std::string> bad = non_finite_values(judged, o.results); !bad.empty()) {
      for (const std::string& b : bad) std::fprintf(stderr, "error: %s\n", b.c_str());
      status = 1;
    }
    if (const std::vector<std::string> copies = copied_samples(judged, *results); !copies.empty()) {
      for (const std::string& c : copies) std::fprintf(stderr, "error: %s\n", c.c_str());
      status = 1;
    }
  }
  if (!samples_distinct(identical)) status = 1;
  if (count.must_pass_failed > 0) {
    std::fprintf(stderr, "error: %d must-pass row(s) inconsistent with the %s\n", count.must_pass_failed, refs.label.c_str());
    status = 1;
  }
  return status;
}

int main(int argc, char** argv) { return dem::guarded_main("validate", [&] { return tool_main(argc, argv); }); }
