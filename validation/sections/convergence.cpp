// compare-runs convergence: the errors of every variant of the convergence study against the
// reference variant, with its wall time. Writes OUT/errors.dat (for the figure), front.dat (its
// Pareto front) and table.md: the cheapest variant within 1, 5 and 10 %, the same judged on the
// quantities the sample-to-sample scatter resolves (if the study has a `seed2`), then every variant.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sections/variants.hpp"
#include "sections/modes.hpp"
#include "sections/percent.hpp"
#include "io/atomic_file.hpp"
#include "study/markdown_table.hpp"

namespace fs = std::filesystem;

namespace compare_runs {
namespace {

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

// One variant: its settings, summed wall time and quantities, and their errors against the reference.
struct Variant {
  std::string name, settings, status;  // status: why it has no quantities
  double wall = 0;
  std::map<std::string, double> quantities, errors;
  double largest = std::numeric_limits<double>::infinity();
};

Variant read_variant(const std::string& name, const std::vector<ManifestLine>& lines) {
  Variant r{name, "", "", 0, {}, {}, std::numeric_limits<double>::infinity()};
  std::map<std::string, double> sample;
  std::vector<std::pair<std::string, validation::TestResult>> tests;
  bool complete = true;
  for (const ManifestLine& l : lines) {
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
      for (const auto& [column, values] : series)
        if (!values.empty()) sample[column] = values.back();
    } else {
      tests.push_back({l.test, {0, series, validation::read_columns(l.result, "legs"), l.test}});
    }
  }
  if (complete) r.quantities = validation::convergence_quantities(sample, tests);
  return r;
}

// An errors.dat line: variant, wall time, largest error, on the front, then every error.
std::string dat_line(const Variant& r, bool front, const std::map<std::string, double>& ref_q) {
  std::ostringstream s;
  s << r.name << '\t' << r.wall << '\t' << r.largest << '\t' << (front ? 1 : 0);
  for (const auto& [name, v] : ref_q) s << '\t' << r.errors.at(name);
  s << "\n";
  return s.str();
}

}  // namespace

int convergence(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& reference) {
  std::vector<Variant> rows;
  for (const std::string& v : manifest.variants) rows.push_back(read_variant(v, manifest.by_variant.at(v)));
  const Variant* ref = nullptr;
  for (const Variant& r : rows)
    if (r.name == reference) ref = &r;
  if (!ref || ref->quantities.empty()) {
    std::fprintf(stderr, "compare-runs: the reference variant '%s' has no complete results in %s\n", reference.c_str(), results.c_str());
    return 1;
  }
  const std::map<std::string, double> ref_q = ref->quantities;
  std::vector<validation::Point> points;
  std::vector<std::size_t> point_row;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    Variant& r = rows[i];
    if (r.quantities.empty()) continue;
    r.errors = validation::relative_errors(r.quantities, ref_q);
    r.largest = 0;
    for (const auto& [name, e] : r.errors) r.largest = std::max(r.largest, e);
    points.push_back({r.wall, r.largest});
    point_row.push_back(i);
  }
  const std::vector<bool> front = validation::pareto_front(points);
  // errors.dat: one line per variant that finished, for the figure (gnuplot reads columns 2-4).
  std::string errors_dat = "# variant\twall_time_s\tlargest_relative_error\tpareto";
  for (const auto& [name, v] : ref_q) errors_dat += '\t' + name;
  errors_dat += "\n";
  for (std::size_t k = 0; k < points.size(); ++k) errors_dat += dat_line(rows[point_row[k]], front[k], ref_q);
  // front.dat: the same lines of the Pareto front but the reference (error 0, off a log axis),
  // in order of wall time, for the figure's line (reports/gnuplot/convergence_error_vs_time.gp).
  std::vector<std::size_t> on_front;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (front[k] && points[k].error > 0) on_front.push_back(k);
  std::sort(on_front.begin(), on_front.end(), [&](std::size_t a, std::size_t b) { return points[a].cost < points[b].cost; });
  std::string front_dat = "# the Pareto front of errors.dat without the reference, by wall time; columns as errors.dat\n";
  for (std::size_t k : on_front) front_dat += dat_line(rows[point_row[k]], true, ref_q);

  std::ostringstream md;
  // The cheapest variant within 1, 5 and 10 % of the reference, of the points (wall time, error)
  // given, point k being the variant rows[row_of[k]].
  const auto cheapest_table = [&](const std::vector<validation::Point>& pts, const std::vector<std::size_t>& row_of,
                                  const std::string& error_heading) {
    validation::MarkdownTable t({"within", "cheapest variant", "settings", "wall time (s)", error_heading, "wall time / reference"});
    for (double tol : {0.01, 0.05, 0.10}) {
      const int best = validation::cheapest_within(pts, tol);
      const std::string within = std::to_string(std::lround(100 * tol)) + " %";
      if (best < 0) {
        t.row({within, "none", "", "", "", ""});
        continue;
      }
      const Variant& r = rows[row_of[static_cast<std::size_t>(best)]];
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.2f", ref->wall > 0 ? r.wall / ref->wall : 0.0);
      t.row({within, r.name, r.settings, std::to_string(std::lround(r.wall)), percent(pts[static_cast<std::size_t>(best)].error), ratio});
    }
    md << t.text();
  };
  md << "Cheapest settings whose every error is within a tolerance of the reference (wall time: preparation + test, "
        "as measured in this study):\n\n";
  cheapest_table(points, point_row, "largest error");
  // Sample-to-sample scatter: the reference on another random sample (variant "seed2", if the study
  // has one). A quantity that differs between two statistically identical samples by more than a
  // tolerance cannot tell settings apart at that tolerance, so a second table judges the variants
  // on the quantities the scatter resolves (scatter below 10 %).
  const Variant* scatter = nullptr;
  for (const Variant& r : rows)
    if (r.name == "seed2" && !r.quantities.empty()) scatter = &r;
  if (scatter) {
    std::vector<std::string> resolved;
    for (const auto& [name, e] : scatter->errors)
      if (e < 0.10) resolved.push_back(name);
    std::vector<validation::Point> judged;
    std::vector<std::size_t> judged_row;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Variant& r = rows[point_row[k]];
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
        "★ on the Pareto front of wall time against the largest error.\n\n";
  const std::vector<std::string> names = reading_order(ref_q);
  std::vector<std::string> headings = {"variant", "settings", "wall time (s)"};
  for (const std::string& name : names) headings.push_back(heading(name));
  headings.push_back("largest");
  validation::MarkdownTable every(headings);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Variant& r = rows[i];
    bool starred = false;  // on the Pareto front
    for (std::size_t k = 0; k < point_row.size(); ++k)
      if (point_row[k] == i) starred = front[k];
    std::vector<std::string> cells = {r.name + (starred ? " ★" : ""), r.settings};
    if (r.quantities.empty()) {  // the wall time's cell says why; the errors' are empty
      cells.push_back("—");
      cells.push_back(r.status.empty() ? "did not finish" : r.status);
      cells.resize(headings.size());
    } else {
      cells.push_back(std::to_string(std::lround(r.wall)));
      for (const std::string& name : names) cells.push_back(percent(r.errors.at(name)));
      cells.push_back(percent(r.largest));
    }
    every.row(cells);
  }
  md << every.text() << "\nReference values: ";
  for (const std::string& name : names) md << heading(name) << " = " << ref_q.at(name) << "; ";
  md << "\n";
  try {
    dem::write_file_atomically((fs::path(out) / "errors.dat").string(), errors_dat);
    dem::write_file_atomically((fs::path(out) / "front.dat").string(), front_dat);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("convergence: %zu variants, %zu finished -> %s\n", rows.size(), points.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}

}  // namespace compare_runs
