// compare-runs: the tables of a study of variants, from the pipeline's manifest (DIR/runs.tsv).
//   compare-runs convergence RESULTS_DIR OUT_DIR [--reference NAME]
//       errors of every variant against the reference, with its wall time: OUT_DIR/errors.dat
//       (for the figure) and OUT_DIR/table.md (all variants, then the cheapest within 1, 5, 10 %)
//   compare-runs stability RESULTS_DIR OUT_DIR
//       what became of each case: OUT_DIR/table.md (case, outcome, steps, closure error, message)
// Exit status: 0; 1 if a stability case is not acceptable (see compare.hpp) or the reference is
// missing; 2 on bad arguments or an unreadable manifest.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "io/atomic_file.hpp"
#include "compare.hpp"
#include "decisions.hpp"
#include "figures.hpp"
#include "format.hpp"
#include "io/hdf5.hpp"
#include "results.hpp"

namespace fs = std::filesystem;

namespace {

using validation::cell;
using validation::file_safe;
using validation::json_string;
using validation::number;

struct ManifestLine {
  std::string variant, density, test, run, result, starts_from, settings;
  bool may_fail = false;
  std::string seed = "-";  // the sample of an ensemble ("-": a study of one sample)
};

std::vector<ManifestLine> read_manifest(const std::string& dir) {
  const fs::path file = fs::path(dir) / "runs.tsv";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": no manifest (run the study with build/bin/pipeline first)");
  std::vector<ManifestLine> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, '\t')) f.push_back(cell);
    if (f.size() < 8) throw std::runtime_error(file.string() + ": a line with " + std::to_string(f.size()) + " fields, 8 expected");
    lines.push_back({f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[6] == "1", f.size() > 8 ? f[8] : "-"});
  }
  return lines;
}

// The run time recorded in a complete result (0 if there is none).
double wall_time(const std::string& result) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    return dem::h5::has_attribute(f, "wall_time_s") ? dem::h5::get_double_attribute(f, "wall_time_s") : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

// The pipeline's record of a may_fail run that stopped (<result>.outcome), if any.
void read_stop(const std::string& result, validation::CaseRun& run) {
  try {
    const YAML::Node n = YAML::LoadFile(result + ".outcome");
    run.exit_code = n["exit_code"].as<int>();
    run.message = n["message"].as<std::string>();
  } catch (const std::exception&) {
  }
}

// Paths under the working folder (the repository, when make runs it), or under the repository the
// study ran in (the folder above the results' `results/`), without that folder, so that committed
// tables do not carry the machine's absolute paths.
std::string relative_paths(std::string s, const std::string& results = "") {
  std::vector<std::string> roots = {fs::current_path().string() + "/"};
  std::error_code ec;  // the real folder: a results/ that is a link to another checkout's names that one
  const std::string abs = fs::weakly_canonical(fs::absolute(results), ec).string();
  if (const auto at = abs.rfind("/results/"); !results.empty() && at != std::string::npos) roots.push_back(abs.substr(0, at + 1));
  for (const std::string& root : roots)
    for (std::size_t at; (at = s.find(root)) != std::string::npos;) s.erase(at, root.size());
  return s;
}

std::string percent(double e) {
  if (!std::isfinite(e)) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, e < 0.001 ? "%.2g %%" : "%.2f %%", 100 * e);
  return buf;
}

// The quantities in reading order: e0, coordination number, then εv, εd by cycle, then the slope.
std::vector<std::string> reading_order(const std::map<std::string, double>& q) {
  auto rank = [](const std::string& n) {
    const int group = n.rfind("e0", 0) == 0 ? 0 : n.rfind("coordination", 0) == 0 ? 1 : n.rfind("ev_", 0) == 0 ? 2
                      : n.rfind("ed_", 0) == 0 ? 3 : 4;
    const auto at = n.find("cycle");
    const int cycle = at == std::string::npos ? 0 : std::atoi(n.c_str() + at + 5);
    return std::pair{group, cycle};
  };
  std::vector<std::string> names;
  for (const auto& [name, v] : q) names.push_back(name);
  std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  return names;
}

// Column heading of a quantity: "ev_cycle2" -> "εv 2", "qp_slope" -> "q/p slope".
std::string heading(std::string n) {
  for (const auto& [from, to] : {std::pair{"ev_cycle", "εv "}, std::pair{"ed_cycle", "εd "}, std::pair{"coordination", "CN"},
                                 std::pair{"qp_slope", "q/p slope"}})
    if (n.rfind(from, 0) == 0) n = to + n.substr(std::string(from).size());
  return n;
}

std::string signed_fixed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.2f", x);
  return buf;
}

// The decisions study (SPEC section 7): every validation row on every reading's ensemble, the
// shift of the mean in baseline standard deviations, a tornado chart per group of rows, and the
// reading that explains each inconsistent row. Writes table.md, decisions.json and, per group,
// tornado_<group>.dat and tornado_values.gp (reports/gnuplot/tornado.gp draws tornado_<group>.png).
int decisions(const std::vector<ManifestLine>& manifest, const std::vector<std::string>& order, const std::string& references,
              const std::string& baseline, const std::string& ensemble, const std::string& out) {
  std::vector<validation::Row> rows;
  try {
    rows = validation::load_references(references, "paper");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  // reading -> seed -> density -> (preparation, test number -> result)
  struct Files {
    std::string preparation;
    std::map<int, std::string> tests;
  };
  std::map<std::string, std::map<std::string, std::map<std::string, Files>>> files;
  std::map<std::string, std::string> settings;
  for (const ManifestLine& l : manifest) {
    Files& f = files[l.variant][l.seed][l.density];
    settings[l.variant] = l.settings;
    if (l.test == "-") f.preparation = l.result;
    else if (l.test.rfind("test", 0) == 0) f.tests[std::atoi(l.test.c_str() + 4)] = l.result;
  }
  std::map<std::string, validation::ReadingResults> readings;
  std::vector<std::string> missing;
  for (const auto& [reading, seeds] : files)
    for (const auto& [seed, densities] : seeds) {
      std::map<std::string, validation::DensityResults> of_seed;
      for (const auto& [density, f] : densities) of_seed[density] = validation::load_density(f.preparation, f.tests, missing);
      readings[reading].push_back({"seed" + seed, "", std::move(of_seed)});
    }
  // The paper study's ensemble (full size), if given: the verdicts and causes are judged on it.
  std::vector<validation::Sample> full_samples;
  std::map<std::string, validation::RowResult> full;
  if (!ensemble.empty()) {
    std::vector<std::string> missing_ensemble;
    full_samples = validation::load_samples(ensemble, {"loose", "medium", "dense"}, missing_ensemble);
    for (const validation::Row& r : rows) full[r.name] = validation::evaluate(r, full_samples);
  }
  std::vector<validation::RowDecision> decided;
  try {
    decided = validation::decide(rows, readings, order, baseline, full);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare-runs: %s\n", e.what());
    return 1;
  }
  std::vector<std::string> others;
  for (const std::string& r : order)
    if (r != baseline) others.push_back(r);
  std::vector<std::string> groups;
  for (const validation::Row& r : rows)
    if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);
  const auto verdict_mark = [](validation::Verdict v) {
    return v == validation::Verdict::Consistent ? "✅" : v == validation::Verdict::Inconsistent ? "❌" : "—";
  };
  std::ostringstream md;
  md << "Readings (each one change from the baseline, `pipeline/studies/decisions.yaml`):\n\n| reading | settings |\n|---|---|\n";
  for (const std::string& r : order) md << "| " << cell(r) << " | " << cell(settings[r]) << " |\n";
  md << "\nEach cell: the shift of the ensemble mean from the baseline's, in baseline standard deviations, and the verdict "
        "under that reading (✅ consistent, ❌ inconsistent, — not judged)"
     << (full.empty() ? std::string(".\n")
                      : std::string(" of the paper study's full-size ensemble with that shift of the mean applied to each of its "
                                    "samples; the baseline column gives this study's mean ± sd and the full-size ensemble's verdict.\n"));
  validation::GnuplotValues gp_values;  // tornado_values.gp, read by reports/gnuplot/tornado.gp
  gp_values.texts("tornado_reading", others);
  std::string group_names;
  for (const std::string& g : groups) {
    md << "\n### " << g << "\n\n![tornado chart: " << g << "](tornado_" << file_safe(g) << ".png)\n\n| row | baseline: mean ± sd | ";
    for (const std::string& r : others) md << cell(r) << " | ";
    md << "explanation |\n|---|---|";
    for (std::size_t k = 0; k < others.size(); ++k) md << "---|";
    md << "---|\n";
    // Tornado data: rows of the group, largest shift first.
    std::vector<const validation::RowDecision*> of_group;
    for (const validation::RowDecision& d : decided)
      if (d.row.group == g) of_group.push_back(&d);
    const auto largest = [](const validation::RowDecision* d) {
      double m = 0;
      for (const auto& e : d->readings)
        if (e.shift_sd && std::isfinite(*e.shift_sd)) m = std::max(m, std::abs(*e.shift_sd));
      return m;
    };
    std::stable_sort(of_group.begin(), of_group.end(), [&](auto* a, auto* b) { return largest(a) < largest(b); });
    std::ofstream dat(fs::path(out) / ("tornado_" + file_safe(g) + ".dat"));
    dat << "# row_index\treading_index\tshift_sd\trow\treading\n";
    for (std::size_t i = 0; i < of_group.size(); ++i)
      for (std::size_t k = 0; k < of_group[i]->readings.size(); ++k) {
        const auto& e = of_group[i]->readings[k];
        if (e.shift_sd && std::isfinite(*e.shift_sd))
          dat << i << '\t' << k << '\t' << *e.shift_sd << "\t\"" << of_group[i]->row.name << "\"\t" << e.reading << "\n";
      }
    // What the static script (reports/gnuplot/tornado.gp) needs of this group: its title, the row
    // names as labels (not tic labels: a tic label is a format, whose '%' would need doubling, and
    // gnuplot cut long ones short), the left margin they take and the chart's height.
    std::size_t longest = 0;
    const std::string key = "tornado_" + file_safe(g);
    gp_values.text(key + "_title", g);
    std::vector<std::string> labels;
    for (const validation::RowDecision* d : of_group) {
      std::string label = d->row.name;
      for (char& c : label)
        if (c == '"') c = '\'';
      longest = std::max(longest, label.size());
      labels.push_back(label);
    }
    gp_values.texts(key + "_row", labels);
    gp_values.number(key + "_lmargin", static_cast<double>(longest * 9 / 10 + 2));
    gp_values.number(key + "_height", static_cast<double>(220 + 34 * of_group.size() * std::max<std::size_t>(1, others.size() / 3)));
    group_names += (group_names.empty() ? "" : " ") + file_safe(g);
    for (auto it = of_group.rbegin(); it != of_group.rend(); ++it) {
      const validation::RowDecision& d = **it;
      md << "| " << cell(d.row.name) << " | "
         << (d.baseline.valued ? number(d.baseline.spread.mean) + (d.baseline.valued > 1 ? " ± " + number(d.baseline.spread.sd) : "") : "—")
         << " " << verdict_mark(d.full ? d.full->verdict : d.baseline.verdict) << " | ";
      for (const auto& e : d.readings)
        md << (e.shift_sd && std::isfinite(*e.shift_sd) ? signed_fixed(*e.shift_sd) : "—") << " "
           << verdict_mark(d.full ? (e.full ? e.full->verdict : validation::Verdict::NotJudged) : e.result.verdict) << " | ";
      md << cell(d.explanation) << " |\n";
    }
  }
  gp_values.text("tornado_groups", group_names);
  dem::write_file_atomically((fs::path(out) / "tornado_values.gp").string(),
                             gp_values.text_file("Written by compare-runs decisions: what reports/gnuplot/tornado.gp draws, one chart "
                                                 "per group from tornado_<group>.dat"));
  // The size check: the baseline of this study against the paper study's ensemble (its own
  // sample size), row by row, in units of the paper ensemble's standard deviation.
  if (!ensemble.empty()) {
    const auto& samples = full_samples;
    md << "\n### Size check: this study's baseline against the paper study's ensemble\n\n"
       << "The same rows on the paper study's samples (" << samples.size() << " per density, its size) and on this study's "
       << "baseline; the difference of the means in units of the paper ensemble's standard deviation, and both verdicts. "
       << "A reading's shift is trusted at this study's size where the two agree.\n\n"
       << "| row | paper study: mean ± sd | this study's baseline: mean ± sd | difference / sd | verdicts |\n|---|---|---|---|---|\n";
    for (const validation::RowDecision& d : decided) {
      const validation::RowResult& big = *d.full;
      const auto ms = [](const validation::RowResult& r) {
        return r.valued ? number(r.spread.mean) + (r.valued > 1 ? " ± " + number(r.spread.sd) : "") : std::string("—");
      };
      std::string diff = "—";
      if (big.valued > 1 && big.spread.sd > 0 && d.baseline.valued > 0)
        diff = signed_fixed((d.baseline.spread.mean - big.spread.mean) / big.spread.sd);
      md << "| " << cell(d.row.name) << " | " << ms(big) << " | " << ms(d.baseline) << " | " << diff << " | "
         << verdict_mark(big.verdict) << " / " << verdict_mark(d.baseline.verdict) << " |\n";
    }
  }
  std::ostringstream json;
  json << "{\n  \"baseline\": \"" << baseline << "\",\n  \"rows\": [\n";
  for (std::size_t i = 0; i < decided.size(); ++i) {
    const validation::RowDecision& d = decided[i];
    json << "    {\"name\": " << json_string(d.row.name) << ", \"group\": " << json_string(d.row.group) << ", \"baseline_mean\": "
         << (d.baseline.valued ? number(d.baseline.spread.mean) : "null") << ", \"baseline_sd\": "
         << (d.baseline.valued > 1 ? number(d.baseline.spread.sd) : "null") << ", \"baseline_verdict\": \""
         << validation::to_string(d.baseline.verdict) << "\", \"readings\": {";
    for (std::size_t k = 0; k < d.readings.size(); ++k) {
      const auto& e = d.readings[k];
      json << (k ? ", " : "") << "\"" << e.reading << "\": {\"mean\": " << (e.result.valued ? number(e.result.spread.mean) : "null")
           << ", \"shift_sd\": " << (e.shift_sd && std::isfinite(*e.shift_sd) ? number(*e.shift_sd) : "null") << ", \"verdict\": \""
           << validation::to_string(e.result.verdict) << "\"}";
    }
    json << "}, \"explanation\": " << json_string(d.explanation) << "}" << (i + 1 < decided.size() ? "," : "") << "\n";
  }
  json << "  ],\n  \"missing_results\": " << missing.size() << "\n}\n";
  try {
    dem::write_file_atomically((fs::path(out) / "table.md").string(), md.str());
    dem::write_file_atomically((fs::path(out) / "decisions.json").string(), json.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("decisions: %zu readings, %zu rows, %zu result files missing -> %s\n", order.size(), rows.size(), missing.size(),
              (fs::path(out) / "table.md").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: compare-runs convergence|stability|decisions RESULTS_DIR OUT_DIR [--reference NAME] [--references FILE] [--report-only] [--ensemble PAPER_RESULTS]\n");
    return 2;
  }
  const std::string mode = argv[1], results = argv[2], out = argv[3];
  std::string reference = "reference", references = "reference_data/paper.yaml", ensemble;
  bool report_only = false;  // stability: a case that is not acceptable is marked in the table, not an exit status
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--report-only") report_only = true;
    else if (a == "--reference" && i + 1 < argc) reference = argv[++i];
    else if (a == "--references" && i + 1 < argc) references = argv[++i];
    else if (a == "--ensemble" && i + 1 < argc) ensemble = argv[++i];
    else {
      std::fprintf(stderr, "compare-runs: unknown option '%s'\n", a.c_str());
      return 2;
    }
  }
  std::vector<ManifestLine> manifest;
  try {
    manifest = read_manifest(results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  fs::create_directories(out);
  // Variants in the order of the study, each with its runs.
  std::vector<std::string> order;
  std::map<std::string, std::vector<ManifestLine>> by_variant;
  for (const ManifestLine& l : manifest) {
    if (!by_variant.count(l.variant)) order.push_back(l.variant);
    by_variant[l.variant].push_back(l);
  }
  if (mode == "stability") {
    std::ofstream md(fs::path(out) / "table.md");
    md << "| case | settings | outcome | steps (last row written) | energy closure error | message |\n|---|---|---|---|---|---|\n";
    int bad = 0;
    for (const std::string& v : order) {
      for (const ManifestLine& l : by_variant[v]) {
        validation::CaseRun run;
        run.complete = validation::is_complete(l.result);
        const std::string file = run.complete ? l.result : l.result + ".partial";
        std::error_code ec;
        if (fs::exists(file, ec)) {
          try {
            run.series = validation::read_columns(file, "timeseries");
          } catch (const std::exception&) {
          }
        }
        if (!run.complete) read_stop(l.result, run);
        validation::CaseOutcome o = validation::classify_case(run);
        // The engine names the resolved scene first; the case column already says which it is.
        if (const auto at = o.message.find(".yaml: "); at != std::string::npos && o.message.rfind('/', at) != std::string::npos)
          o.message = o.message.substr(at + 7);
        bad += !o.acceptable;
        const std::string name = l.test == "-" ? v : v + " " + l.test;
        md << "| " << cell(name) << " | " << cell(relative_paths(l.settings, results)) << " | " << (o.acceptable ? "" : "⚠ ") << o.outcome << " | "
           << o.steps << " | " << (o.closure ? percent(*o.closure) : "—") << " | " << cell(o.message) << " |\n";
      }
    }
    std::printf("stability: %zu cases, %d not acceptable -> %s\n", order.size(), bad, (fs::path(out) / "table.md").c_str());
    return bad > 0 && !report_only ? 1 : 0;
  }
  if (mode == "decisions")
    return decisions(manifest, order, references, reference == "reference" ? "baseline" : reference, ensemble, out);
  if (mode != "convergence") {
    std::fprintf(stderr, "compare-runs: unknown mode '%s' (convergence, stability or decisions)\n", mode.c_str());
    return 2;
  }
  struct Row {
    std::string variant, settings, status;
    double wall = 0;
    std::map<std::string, double> quantities, errors;
    double largest = std::numeric_limits<double>::infinity();
  };
  std::vector<Row> rows;
  for (const std::string& v : order) {
    Row r{v, "", "", 0, {}, {}, std::numeric_limits<double>::infinity()};
    std::map<std::string, double> sample;
    std::vector<std::pair<std::string, validation::TestResult>> tests;
    bool complete = true;
    for (const ManifestLine& l : by_variant[v]) {
      r.settings = l.settings;
      if (!validation::is_complete(l.result)) {
        complete = false;
        validation::CaseRun stop;
        read_stop(l.result, stop);
        if (r.status.empty()) r.status = l.run + (stop.exit_code ? ": " + stop.message : " not complete");
        continue;
      }
      r.wall += wall_time(l.result);  // a shared preparation counts in full for every variant using it
      const validation::Columns series = validation::read_columns(l.result, "timeseries");
      if (l.test == "-") {
        for (const auto& [name, values] : series)
          if (!values.empty()) sample[name] = values.back();
      } else {
        tests.push_back({l.test, {0, series, validation::read_columns(l.result, "legs")}});
      }
    }
    if (complete) r.quantities = validation::convergence_quantities(sample, tests);
    rows.push_back(r);
  }
  const Row* ref = nullptr;
  for (const Row& r : rows)
    if (r.variant == reference) ref = &r;
  if (!ref || ref->quantities.empty()) {
    std::fprintf(stderr, "compare-runs: the reference variant '%s' has no complete results in %s\n", reference.c_str(), results.c_str());
    return 1;
  }
  const std::map<std::string, double> ref_q = ref->quantities;
  std::vector<validation::Point> points;
  std::vector<std::size_t> point_row;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Row& r = rows[i];
    if (r.quantities.empty()) continue;
    r.errors = validation::relative_errors(r.quantities, ref_q);
    r.largest = 0;
    for (const auto& [name, e] : r.errors) r.largest = std::max(r.largest, e);
    points.push_back({r.wall, r.largest});
    point_row.push_back(i);
  }
  const std::vector<bool> front = validation::pareto_front(points);
  // errors.dat: one line per variant that finished, for the figure (gnuplot reads columns 2-4).
  {
    std::ofstream dat(fs::path(out) / "errors.dat");
    dat << "# variant\twall_time_s\tlargest_relative_error\tpareto";
    for (const auto& [name, v] : ref_q) dat << '\t' << name;
    dat << "\n";
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Row& r = rows[point_row[k]];
      dat << r.variant << '\t' << r.wall << '\t' << r.largest << '\t' << (front[k] ? 1 : 0);
      for (const auto& [name, v] : ref_q) dat << '\t' << r.errors.at(name);
      dat << "\n";
    }
    // front.dat: the same lines of the Pareto front but the reference (error 0, off a log axis),
    // in order of wall time, for the figure's line (reports/gnuplot/convergence_error_vs_time.gp).
    std::vector<std::size_t> on_front;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (front[k] && points[k].error > 0) on_front.push_back(k);
    std::sort(on_front.begin(), on_front.end(), [&](std::size_t a, std::size_t b) { return points[a].cost < points[b].cost; });
    std::ofstream fr(fs::path(out) / "front.dat");
    fr << "# the Pareto front of errors.dat without the reference, by wall time; columns as errors.dat\n";
    for (std::size_t k : on_front) {
      const Row& r = rows[point_row[k]];
      fr << r.variant << '\t' << r.wall << '\t' << r.largest << "\t1";
      for (const auto& [name, v] : ref_q) fr << '\t' << r.errors.at(name);
      fr << "\n";
    }
  }
  std::ofstream md(fs::path(out) / "table.md");
  // The cheapest variant within 1, 5 and 10 % of the reference, of the points (wall time, error)
  // given, point k being the variant rows[row_of[k]].
  const auto cheapest_table = [&](const std::vector<validation::Point>& pts, const std::vector<std::size_t>& row_of,
                                  const std::string& error_heading) {
    md << "| within | cheapest variant | settings | wall time (s) | " << error_heading
       << " | wall time / reference |\n|---|---|---|---|---|---|\n";
    for (double tol : {0.01, 0.05, 0.10}) {
      const int best = validation::cheapest_within(pts, tol);
      md << "| " << static_cast<int>(std::lround(100 * tol)) << " % | ";
      if (best < 0) { md << "none | | | | |\n"; continue; }
      const Row& r = rows[row_of[static_cast<std::size_t>(best)]];
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.2f", ref->wall > 0 ? r.wall / ref->wall : 0.0);
      md << cell(r.variant) << " | " << cell(r.settings) << " | " << static_cast<long>(std::lround(r.wall)) << " | "
         << percent(pts[static_cast<std::size_t>(best)].error) << " | " << ratio << " |\n";
    }
  };
  md << "Cheapest settings whose every error is within a tolerance of the reference (wall time: preparation + test, "
        "as measured in this study):\n\n";
  cheapest_table(points, point_row, "largest error");
  // Sample-to-sample scatter: the reference on another random sample (variant "seed2", if the study
  // has one). A quantity that differs between two statistically identical samples by more than a
  // tolerance cannot tell settings apart at that tolerance, so a second table judges the variants
  // on the quantities the scatter resolves (scatter below 10 %).
  const Row* scatter = nullptr;
  for (const Row& r : rows)
    if (r.variant == "seed2" && !r.quantities.empty()) scatter = &r;
  if (scatter) {
    std::vector<std::string> resolved;
    for (const auto& [name, e] : scatter->errors)
      if (e < 0.10) resolved.push_back(name);
    std::vector<validation::Point> judged;
    std::vector<std::size_t> judged_row;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Row& r = rows[point_row[k]];
      if (&r == scatter) continue;  // another sample, not another setting
      double largest = 0;
      for (const std::string& name : resolved) largest = std::max(largest, r.errors.at(name));
      judged.push_back({r.wall, largest});
      judged_row.push_back(point_row[k]);
    }
    md << "\nSample-to-sample scatter (the reference on a second random sample, `seed2`): ";
    for (const auto& [name, e] : scatter->errors) md << heading(name) << " " << percent(e) << "; ";
    md << "so only ";
    for (std::size_t k = 0; k < resolved.size(); ++k) md << (k ? ", " : "") << heading(resolved[k]);
    md << " (scatter below 10 %) can tell settings apart. Judged on those alone:\n\n";
    cheapest_table(judged, judged_row, "largest error on these");
  }
  md << "\nEvery variant: relative error against the reference of each quantity (e0 and coordination number after "
        "the preparation; εv and εd, paper Eq. 4, at the end of each cycle; slope of q/p against F^s_d/F^s_m), "
        "★ on the Pareto front of wall time against the largest error.\n\n| variant | settings | wall time (s) |";
  const std::vector<std::string> names = reading_order(ref_q);
  for (const std::string& name : names) md << " " << heading(name) << " |";
  md << " largest |\n|---|---|---|";
  for (std::size_t k = 0; k < ref_q.size() + 1; ++k) md << "---|";
  md << "\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    bool on_front = false;
    for (std::size_t k = 0; k < point_row.size(); ++k)
      if (point_row[k] == i) on_front = front[k];
    md << "| " << cell(r.variant) << (on_front ? " ★" : "") << " | " << cell(r.settings) << " | ";
    if (r.quantities.empty()) {
      md << "— | " << cell(r.status.empty() ? "did not finish" : r.status);
      for (std::size_t k = 0; k < ref_q.size() + 1; ++k) md << " |";
      md << "\n";
      continue;
    }
    md << static_cast<long>(std::lround(r.wall)) << " |";
    for (const std::string& name : names) md << " " << percent(r.errors.at(name)) << " |";
    md << " " << percent(r.largest) << " |\n";
  }
  md << "\nReference values: ";
  for (const std::string& name : names) md << heading(name) << " = " << ref_q.at(name) << "; ";
  md << "\n";
  std::printf("convergence: %zu variants, %zu finished -> %s\n", rows.size(), points.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}
