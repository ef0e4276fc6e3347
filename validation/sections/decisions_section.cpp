// compare-runs decisions: the decisions study (docs/method.md#open-choices). Every validation row on every
// reading's ensemble, the shift of the mean in baseline standard deviations, a tornado chart per
// group of rows, and the reading that explains each inconsistent row. Writes OUT/table.md,
// decisions.json and, per group, tornado_<group>.dat and tornado_values.gp
// (reports/gnuplot/tornado.gp draws tornado_<group>.png). With --from-json, the same table.md,
// tornado_<group>.dat and tornado_values.gp re-drawn from a decisions.json alone (decisions_from_json).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sections/modes.hpp"
#include "judge/decisions.hpp"
#include "judge/decisions_file.hpp"
#include "judge/validation_file.hpp"
#include "judge/weak_verdicts.hpp"
#include "study/series.hpp"
#include "study/format.hpp"
#include "io/atomic_file.hpp"
#include "study/markdown_table.hpp"
#include "study/section_doc.hpp"
#include "study/results.hpp"
#include "study/settings.hpp"
#include "study/stamp.hpp"

namespace fs = std::filesystem;

namespace sections {
namespace {

using validation::number;
using validation::RowDecision;
using validation::RowResult;
using validation::Verdict;

// "mean ± sd" of a row's result (one sample: the mean alone; none: "—").
std::string mean_sd(const RowResult& r) {
  return r.valued ? (r.valued > 1 ? validation::mean_pm_sd(r.spread.mean, r.spread.sd) : number(r.spread.mean)) : std::string("—");
}

bool finite_shift(const validation::ReadingEffect& e) { return e.shift_sd && std::isfinite(*e.shift_sd); }

// Every reading's results, by reading, read from the manifest (`dir`: the folder it is in; the
// results are found under it wherever the study ran): reading -> its samples (one per seed). A run
// whose result is missing or not complete is listed in `missing` and in its density's missing_runs.
std::map<std::string, validation::ReadingResults> read_readings(const std::vector<ManifestLine>& lines, const std::string& dir,
                                                                std::vector<std::string>& missing) {
  // reading -> seed -> density -> (preparation, test number -> result)
  struct Files {
    std::string preparation;
    std::map<int, std::string> tests;
  };
  std::map<std::string, std::map<std::string, std::map<std::string, Files>>> files;
  for (const ManifestLine& l : lines) {
    Files& f = files[l.variant][l.seed][l.density];
    if (l.test == "-") f.preparation = validation::result_under(dir, l);
    else if (l.test.rfind("test", 0) == 0) f.tests[std::atoi(l.test.c_str() + 4)] = validation::result_under(dir, l);
  }
  std::map<std::string, validation::ReadingResults> readings;
  for (const auto& [reading, seeds] : files)
    for (const auto& [seed, densities] : seeds) {
      std::map<std::string, validation::DensityResults> of_seed;
      for (const auto& [density, f] : densities) {
        const std::size_t before = missing.size();
        validation::DensityResults r = validation::load_density(f.preparation, f.tests, missing);
        for (std::size_t k = before; k < missing.size(); ++k) {
          if (missing[k] == f.preparation) r.missing_runs.push_back("prepare");
          for (const auto& [n, file] : f.tests)
            if (missing[k] == file) r.missing_runs.push_back("test" + std::to_string(n));
        }
        of_seed[density] = std::move(r);
      }
      readings[reading].push_back({seed == "-" ? "" : "seed" + seed, "", std::move(of_seed)});
    }
  return readings;
}

// The number of spheres of the first prepared sample of `samples` (0 if none says).
long particles_of(const validation::ReadingResults& samples) {
  for (const validation::Sample& s : samples)
    for (const auto& [density, r] : s.densities)
      if (r.prepared && r.sample.count("particles")) return std::lround(r.sample.at("particles"));
  return 0;
}

// A reading's cell when one of its samples lacks a run the row reads (it is not judged on the row).
const char* lacks_runs = "runs missing";

// One group's section of table.md (its tornado chart and table), and its tornado_<group>.dat and
// the values tornado.gp needs of it.
validation::SectionDoc group_section(const std::string& g, const std::vector<RowDecision>& decided, const std::vector<std::string>& others,
                                    const std::string& out, validation::GnuplotValues& gp_values) {
  const std::string key = "tornado_" + validation::file_safe(g);
  // Tornado data: rows of the group, largest shift first.
  std::vector<const RowDecision*> of_group;
  for (const RowDecision& d : decided)
    if (d.row.group == g) of_group.push_back(&d);
  const auto largest = [](const RowDecision* d) {
    double m = 0;
    for (const auto& e : d->readings)
      if (finite_shift(e)) m = std::max(m, std::abs(*e.shift_sd));
    return m;
  };
  std::stable_sort(of_group.begin(), of_group.end(), [&](auto* a, auto* b) { return largest(a) < largest(b); });
  std::ofstream dat(fs::path(out) / (key + ".dat"));
  dat << "# row_index\treading_index\tshift_sd\trow\treading\n";
  for (std::size_t i = 0; i < of_group.size(); ++i)
    for (std::size_t k = 0; k < of_group[i]->readings.size(); ++k) {
      const auto& e = of_group[i]->readings[k];
      if (finite_shift(e)) dat << i << '\t' << k << '\t' << *e.shift_sd << "\t\"" << of_group[i]->row.name << "\"\t" << e.reading << "\n";
    }
  // What the static script (reports/gnuplot/tornado.gp) needs of this group: its title, the row
  // names as labels (not tic labels: a tic label is a format, whose '%' would need doubling, and
  // gnuplot cut long ones short), the left margin they take and the chart's height.
  std::size_t longest = 0;
  gp_values.text(key + "_title", g);
  std::vector<std::string> labels;
  for (const RowDecision* d : of_group) {
    std::string label = d->row.name;
    for (char& c : label)
      if (c == '"') c = '\'';
    longest = std::max(longest, label.size());
    labels.push_back(label);
  }
  gp_values.texts(key + "_row", labels);
  gp_values.number(key + "_lmargin", static_cast<double>(longest * 9 / 10 + 2));
  gp_values.number(key + "_height", static_cast<double>(220 + 34 * of_group.size() * std::max<std::size_t>(1, others.size() / 3)));

  std::vector<std::string> headings = {"row", "baseline: mean ± sd"};
  headings.insert(headings.end(), others.begin(), others.end());
  headings.push_back("explanation");
  validation::MarkdownTable table(headings);
  for (auto it = of_group.rbegin(); it != of_group.rend(); ++it) {
    const RowDecision& d = **it;
    // The marks of the full-size ensemble's verdicts when it is given, ⚠ on a weak one (weak_verdicts.hpp).
    std::vector<std::string> cells = {d.row.name, mean_sd(d.baseline) + " " + validation::verdict_mark(d.full ? *d.full : d.baseline)};
    for (const auto& e : d.readings)
      cells.push_back(!e.missing.empty() ? std::string(lacks_runs) + " —"
                                         : (finite_shift(e) ? validation::shift_text(*e.shift_sd) : "—") + " " +
                                               (d.full ? e.full ? validation::verdict_mark(*e.full) : validation::verdict_mark(Verdict::NotJudged)
                                                       : validation::verdict_mark(e.result)));
    cells.push_back(d.explanation);
    table.row(cells);
  }
  validation::SectionDoc doc;
  return doc.text("\n").heading(1, g).text("\n").figure(key + ".png", "tornado chart: " + g).text("\n" + table.text());
}

// What a cell of the tables says. `full_size`: the verdicts are those of the paper study's full-size
// ensemble with each reading's shift applied (compare-runs decisions --ensemble).
std::string cell_legend(bool full_size) {
  return std::string("Each cell: the shift of the ensemble mean from the baseline's, in units of max(baseline sd, the row's resolution), "
                     "and the verdict under that reading (✅ consistent, ❌ inconsistent, — not judged; \"") + lacks_runs +
         "\": a sample lacks a run the row reads, so the reading is not judged on it)" +
         (full_size ? std::string(" of the paper study's full-size ensemble with that shift of the mean applied to each of its "
                                  "samples; the baseline column gives this study's mean ± sd and the full-size ensemble's verdict.\n")
                    : std::string(".\n"));
}

// Every group's section of table.md (group_section) in the order of `groups`, and
// OUT/tornado_values.gp, which reports/gnuplot/tornado.gp reads: both modes draw with this.
validation::SectionDoc group_sections(const std::vector<std::string>& groups, const std::vector<RowDecision>& decided,
                                     const std::vector<std::string>& others, const std::string& out) {
  validation::GnuplotValues gp_values;
  gp_values.texts("tornado_reading", others);
  validation::SectionDoc md;
  std::string group_names;
  for (const std::string& g : groups) {
    md.append(group_section(g, decided, others, out, gp_values));
    if (!group_names.empty()) group_names += ' ';
    group_names += validation::file_safe(g);
  }
  gp_values.text("tornado_groups", group_names);
  dem::write_file_atomically((fs::path(out) / "tornado_values.gp").string(),
                             gp_values.text_file("Written by compare-runs decisions: what reports/gnuplot/tornado.gp draws, one chart "
                                                 "per group from tornado_<group>.dat"));
  return md;
}

// What the study was measured at, for the readers of decisions.json (validate --decisions).
struct Size {
  long particles = 0;      // spheres per sample (0: unknown)
  std::size_t samples = 0;  // the baseline's samples
};

// decisions.json's record of the study (judge/decisions_file.hpp declares the file).
validation::DecisionsFile decisions_record(const std::string& baseline, const std::string& baseline_results, const Size& size,
                                           const std::vector<RowDecision>& decided, std::size_t missing, const validation::Stamp& stamp,
                                           std::vector<std::pair<std::string, std::string>> settings) {
  const auto rounded = [](double x) -> std::optional<double> {
    const double v = std::strtod(number(x).c_str(), nullptr);  // six significant digits (the values of a few samples)
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
  };
  validation::DecisionsFile f;
  f.baseline = baseline;
  f.baseline_results = baseline_results;
  if (size.particles > 0) f.particles = size.particles;
  f.samples = size.samples;
  f.stamp = stamp;
  f.missing_results = missing;
  f.settings = std::move(settings);
  for (const RowDecision& d : decided) {
    validation::DecisionsFile::Finding row;
    row.group = d.row.group;
    if (d.baseline.valued) row.baseline_mean = rounded(d.baseline.spread.mean);
    if (d.baseline.valued > 1) row.baseline_sd = rounded(d.baseline.spread.sd);
    row.baseline_verdict = d.baseline.verdict;
    for (const auto& e : d.readings) {
      validation::DecisionsFile::Reading r;
      if (e.result.valued) r.mean = rounded(e.result.spread.mean);
      if (finite_shift(e)) r.shift_sd = rounded(*e.shift_sd);
      r.verdict = e.result.verdict;
      r.missing_runs = e.missing;
      row.readings.emplace_back(e.reading, std::move(r));
    }
    row.judged = d.judged;
    row.explained_by = d.made_consistent_by;
    row.outcome = d.outcome;
    row.explanation = d.explanation;
    f.order.push_back(d.row.name);
    f.rows[d.row.name] = std::move(row);
  }
  return f;
}

}  // namespace

int decisions(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& references,
              const std::string& baseline, const std::string& ensemble, const std::string& baseline_results) {
  std::vector<validation::Row> rows;
  try {
    rows = validation::load_references(references, "paper");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::vector<std::string> missing;
  std::map<std::string, validation::ReadingResults> readings = read_readings(manifest.lines, results, missing);
  std::vector<std::string> order = manifest.variants;  // the readings, the baseline among them
  // The baseline from another study's results (a study of readings only): its samples of the
  // seeds this study has, so that every reading is compared with the same samples.
  if (!baseline_results.empty()) {
    if (readings.count(baseline)) {
      std::fprintf(stderr, "error: %s has a reading named '%s' of its own; --baseline-results gives the baseline from another "
                           "study (name this study's baseline with --reference, or leave --baseline-results out)\n",
                   results.c_str(), baseline.c_str());
      return 2;
    }
    std::vector<ManifestLine> lines;
    try {
      lines = validation::read_manifest(baseline_results);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --baseline-results: %s\n", e.what());
      return 2;
    }
    const std::vector<std::string> seeds = validation::samples_of(manifest.lines);
    std::vector<ManifestLine> of_seeds;
    for (const ManifestLine& l : lines)
      if ((l.variant == "-" || l.variant == baseline) && std::find(seeds.begin(), seeds.end(), validation::sample_of(l)) != seeds.end())
        of_seeds.push_back(l);
    for (const std::string& seed : seeds)
      if (std::none_of(of_seeds.begin(), of_seeds.end(), [&](const ManifestLine& l) { return validation::sample_of(l) == seed; })) {
        std::fprintf(stderr, "error: --baseline-results %s has no runs of sample '%s' (this study's samples must be among its own)\n",
                     baseline_results.c_str(), seed.c_str());
        return 1;
      }
    for (auto& [name, samples] : read_readings(of_seeds, baseline_results, missing)) readings[baseline] = std::move(samples);
    order.insert(order.begin(), baseline);
  }
  // The rows of the densities this study's readings run (a study of one density judges its rows only).
  std::vector<std::string> densities;
  for (const ManifestLine& l : manifest.lines)
    if (l.variant != baseline && std::find(densities.begin(), densities.end(), l.density) == densities.end()) densities.push_back(l.density);
  const std::size_t all_rows = rows.size();
  rows.erase(std::remove_if(rows.begin(), rows.end(),
                            [&](const validation::Row& r) { return std::find(densities.begin(), densities.end(), r.density) == densities.end(); }),
             rows.end());
  std::map<std::string, std::string> settings;  // reading -> its settings
  for (const ManifestLine& l : manifest.lines) settings[l.variant] = l.settings;
  if (!baseline_results.empty()) settings[baseline] = "as written (" + relative_paths(baseline_results, baseline_results) + ")";
  // The paper study's ensemble (full size), if given: the verdicts and causes are judged on it.
  std::vector<validation::Sample> full_samples;
  std::map<std::string, RowResult> full;
  if (!ensemble.empty()) {
    std::vector<std::string> missing_ensemble;
    full_samples = validation::load_samples(ensemble, validation::study_densities(ensemble), missing_ensemble);
    for (const validation::Row& r : rows) full[r.name] = validation::evaluate(r, full_samples);
  }
  std::vector<RowDecision> decided;
  try {
    decided = validation::decide(rows, readings, order, baseline, full);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare-runs: %s\n", e.what());
    return 1;
  }
  Size size;
  size.particles = particles_of(readings.at(baseline));
  size.samples = readings.at(baseline).size();
  std::vector<std::string> others;
  for (const std::string& r : order)
    if (r != baseline) others.push_back(r);
  std::vector<std::string> groups;
  for (const validation::Row& r : rows)
    if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);

  validation::MarkdownTable reading_table({"reading", "settings"});
  std::vector<std::pair<std::string, std::string>> reading_settings;  // recorded in decisions.json
  for (const std::string& r : order) reading_table.row({r, settings[r]}), reading_settings.emplace_back(r, settings[r]);
  const std::string measured = (size.particles > 0 ? validation::thousands(size.particles) + " spheres" : std::string("spheres not recorded")) +
                               ", " + std::to_string(size.samples) + " sample" + (size.samples == 1 ? "" : "s");
  std::string md = "Measured at " + measured + " per reading. Readings (each one change from the baseline" +
                   (baseline_results.empty() ? std::string(")")
                                             : "; the baseline is the samples of the same seeds in `" + relative_paths(baseline_results, baseline_results) +
                                                   "`, the same scenes and engine)") +
                   ":\n\n" + reading_table.text() + "\n" + cell_legend(!full.empty());
  if (rows.size() < all_rows)
    md += "\nOnly the rows of the densities this study runs (" + validation::joined(densities, ", ") + "): " + std::to_string(rows.size()) +
          " of " + std::to_string(all_rows) + ".\n";
  validation::SectionDoc doc;
  doc.text(md).append(group_sections(groups, decided, others, out)).densities = densities;
  try {
    validation::write_section(out, doc);
    dem::write_file_atomically(
        (fs::path(out) / "decisions.json").string(),
        validation::decisions_file_json(decisions_record(baseline, baseline_results.empty() ? "" : relative_paths(baseline_results, baseline_results),
                                                         size, decided, missing.size(), validation::stamp_of_results(results, baseline, baseline_results),
                                                         reading_settings))
                .dump(2) +
            "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::size_t not_judged = 0;
  for (const RowDecision& d : decided) not_judged += !d.judged;
  std::printf("decisions: %zu readings, %zu rows (%zu not judged), %s, %zu result files missing -> %s\n", others.size(), rows.size(),
              not_judged, measured.c_str(), missing.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}

namespace {

// A result as decisions.json records it: its mean and sd. `samples`: how many samples it had, when
// the file says (mean_sd() prints a mean ± sd for more than one; a recorded sd means at least two).
RowResult recorded_result(std::optional<double> mean, std::optional<double> sd, Verdict verdict, std::size_t samples) {
  RowResult r;
  r.verdict = verdict;
  if (!mean) return r;
  r.spread.mean = *mean;
  r.spread.sd = sd.value_or(0.0);
  r.valued = sd ? static_cast<int>(std::max<std::size_t>(2, samples)) : 1;
  r.spread.n = r.valued;
  return r;
}

}  // namespace

int decisions_from_json(const std::string& file, const std::string& out, const std::string& references, const std::string& ensemble_json) {
  std::vector<validation::Row> rows;
  validation::DecisionsFile findings;
  std::map<std::string, RowResult> full;  // the paper study's full-size ensemble, from its validation.json
  try {
    rows = validation::load_references(references, "paper");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  try {
    findings = validation::read_decisions_file(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --from-json %s: %s\n", file.c_str(), e.what());
    return 2;
  }
  if (!ensemble_json.empty()) {
    try {
      const validation::RecordedValidation record = validation::read_validation_file(ensemble_json);
      std::vector<validation::Row> of_record;  // the rows the record has (a readings study's densities)
      for (const validation::Row& r : rows)
        for (const auto& rr : record.rows)
          if (rr.name == r.name) of_record.push_back(r);
      for (const validation::RejudgedRow& r : validation::judge_recorded(record, of_record, ensemble_json, references)) full[r.row.name] = r.result;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --ensemble-json %s: %s\n", ensemble_json.c_str(), e.what());
      return 2;
    }
  }
  std::map<std::string, const validation::Row*> row_of;
  for (const validation::Row& r : rows) row_of[r.name] = &r;
  const std::size_t samples = findings.samples.value_or(0);

  // The readings in the file's order (every row's, first seen first) and the groups likewise.
  std::vector<std::string> others, groups;
  for (const std::string& name : findings.order) {
    const validation::DecisionsFile::Finding& row = findings.rows.at(name);
    for (const auto& [reading, value] : row.readings)
      if (std::find(others.begin(), others.end(), reading) == others.end()) others.push_back(reading);
    if (std::find(groups.begin(), groups.end(), row.group) == groups.end()) groups.push_back(row.group);
  }

  std::vector<RowDecision> decided;
  std::vector<std::string> unknown;  // rows the references do not have: shifts in baseline sd alone
  std::size_t clipped = 0;
  for (const std::string& name : findings.order) {
    const validation::DecisionsFile::Finding& row = findings.rows.at(name);
    RowDecision d;
    d.row.name = name;
    d.row.group = row.group;
    if (row_of.count(name)) d.row = *row_of.at(name), d.row.group = row.group;
    else unknown.push_back(name);
    d.baseline = recorded_result(row.baseline_mean, row.baseline_sd, row.baseline_verdict, samples);
    if (full.count(name)) d.full = full.at(name);
    for (const std::string& reading : others) {
      validation::ReadingEffect e;
      e.reading = reading;
      if (const validation::DecisionsFile::Reading* r = row.reading(reading)) {
        e.result = recorded_result(r->mean, std::nullopt, r->verdict, samples);
        e.missing = r->missing_runs;
        // The shift from the recorded means, against the references' resolution of the row as they
        // stand now (the file's shift_sd used the resolution of its day).
        if (const std::optional<double> by = row.mean_shift(reading); by && e.missing.empty()) {
          const double z = validation::shift_in_sd(*by, row.baseline_sd.value_or(0.0), d.row.resolution);
          if (std::isfinite(z)) e.shift_sd = z;
          if (std::isfinite(z) && std::abs(z) > validation::shift_clip) ++clipped;
          // The full-size ensemble's verdict under the reading: its shift of the mean applied to
          // each of the paper study's samples, as the study drawn from its results does (decide()).
          if (d.full) e.full = validation::shifted(d.row, *d.full, *by);
        }
      }
      d.readings.push_back(std::move(e));
    }
    d.judged = row.judged;
    d.outcome = row.outcome;
    d.explanation = row.explanation;
    decided.push_back(std::move(d));
  }

  // What this table is, computed from the file: where it comes from, its size, and what of the
  // section drawn from the results it cannot show.
  // Its size as the file records it (size_label: "size not recorded" when it does not).
  const std::string size = findings.particles ? "measured at " + validation::size_label(findings) + " per reading" : validation::size_label(findings);
  std::string md = "Re-drawn from `" + file + "` alone, without the study's results (not on the machine that drew it); " + size +
                   ". Each shift is restated from the means the file records, "
                   "(reading mean − baseline mean) / max(baseline sd, the row's resolution in `" + references +
                   "`), and so are the shifts the explanations quote." +
                   (full.empty() ? " What needs the results is not re-drawn: the verdicts of the paper study's full-size ensemble (each mark "
                                   "below is the verdict on this study's own samples, as the file records it; an explanation judged on the "
                                   "full-size ensemble may disagree with it)."
                                 : " The marks are the verdicts of the paper study's full-size ensemble (`" + ensemble_json +
                                       "`) with each reading's shift of the mean applied, as drawn from the results.") +
                   "\n\n";
  if (findings.settings.empty()) {
    md += "Readings (each one change from the baseline, `" + findings.baseline + "`): " + validation::joined(others, ", ") +
          "; their settings are not recorded in the file.\n\n";
  } else {
    validation::MarkdownTable reading_table({"reading", "settings"});
    for (const auto& [reading, text] : findings.settings) reading_table.row({reading, text});
    md += "Readings (each one change from the baseline" +
          (findings.baseline_results.empty() ? std::string(")")
                                             : "; the baseline is the samples of the same seeds in `" + findings.baseline_results +
                                                   "`, the same scenes and engine)") +
          ":\n\n" + reading_table.text() + "\n";
  }
  md += cell_legend(!full.empty());
  // A study of some densities judges their rows only (decisions()).
  std::vector<std::string> densities;
  for (const std::string& name : findings.order)
    if (row_of.count(name) && std::find(densities.begin(), densities.end(), row_of.at(name)->density) == densities.end())
      densities.push_back(row_of.at(name)->density);
  if (findings.order.size() < rows.size() && unknown.empty())
    md += "\nOnly the rows of the densities this study runs (" + validation::joined(densities, ", ") + "): " +
          std::to_string(findings.order.size()) + " of " + std::to_string(rows.size()) + ".\n";
  if (!unknown.empty())
    md += "\nRows not in `" + references + "` (their shifts in baseline sd alone, no resolution known): " + validation::joined(unknown, "; ") + ".\n";
  try {
    fs::create_directories(out);
    validation::SectionDoc doc;
    doc.text(md).append(group_sections(groups, decided, others, out)).densities = densities;
    validation::write_section(out, doc);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("decisions: re-drawn from %s: %zu readings, %zu rows, %s; shifts beyond ±%.0f sd (written with their value): %zu -> %s\n",
              file.c_str(), others.size(), decided.size(), validation::size_label(findings).c_str(), validation::shift_clip, clipped,
              (fs::path(out) / "table.md").c_str());
  return 0;
}

}  // namespace sections
