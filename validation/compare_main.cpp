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

#include "compare.hpp"
#include "io/hdf5.hpp"
#include "results.hpp"

namespace fs = std::filesystem;

namespace {

struct ManifestLine {
  std::string variant, density, test, run, result, starts_from, settings;
  bool may_fail = false;
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
    lines.push_back({f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[6] == "1"});
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

// A Markdown table cell: '|' would end the cell.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    if (c == '\n') { out += ' '; continue; }
    out += c;
  }
  return out;
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: compare-runs convergence|stability RESULTS_DIR OUT_DIR [--reference NAME]\n");
    return 2;
  }
  const std::string mode = argv[1], results = argv[2], out = argv[3];
  std::string reference = "reference";
  for (int i = 4; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--reference") reference = argv[i + 1];
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
        md << "| " << cell(name) << " | " << cell(l.settings) << " | " << (o.acceptable ? "" : "⚠ ") << o.outcome << " | "
           << o.steps << " | " << (o.closure ? percent(*o.closure) : "—") << " | " << cell(o.message) << " |\n";
      }
    }
    std::printf("stability: %zu cases, %d not acceptable -> %s\n", order.size(), bad, (fs::path(out) / "table.md").c_str());
    return bad > 0 ? 1 : 0;
  }
  if (mode != "convergence") {
    std::fprintf(stderr, "compare-runs: unknown mode '%s' (convergence or stability)\n", mode.c_str());
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
