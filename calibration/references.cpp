#include "references.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/time_series.hpp"
#include "config/yaml_section.hpp"
#include "study/ensemble.hpp"

namespace calibration {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) {
    cell.erase(0, cell.find_first_not_of(" \t\r"));
    cell.erase(cell.find_last_not_of(" \t\r") + 1);
    out.push_back(cell);
  }
  return out;
}

// A point's chi^2 divides its residual by the reference's variance, tolerance^2 + sd^2 / specimens
// (plus the samples', which may be 0): that must be a positive, finite number that is not
// subnormal (sd = 1e-300 squares to 0), and y over its square root must square to a finite
// number (y = 1e300), or the point's chi^2 is infinite or not a number whatever the runs give, and
// no set would weigh anything.
void check_points(const dem::Section& c, const CurveRow& row) {
  for (std::size_t k = 0; k < row.points.size(); ++k) {
    const CurvePoint& p = row.points[k];
    const double var = row.tolerance * row.tolerance + p.sd * p.sd / row.specimens;
    std::string why;
    if (var == 0 && p.sd == 0)
      why = "has sd 0 and the curve's tolerance is 0: its misfit would divide by 0; give the point an sd > 0 or the curve a tolerance";
    else if (!std::isnormal(var))
      why = "has a variance (tolerance^2 + sd^2 / specimens) that underflows to 0 or overflows; give an sd or a tolerance between "
            "about 1e-150 and 1e150, in y's unit";
    else if (!std::isfinite(p.y * p.y / var))
      why = "has a y so large against its sd and tolerance that its misfit would overflow; give y in the unit of the run's column";
    if (why.empty()) continue;
    std::ostringstream point;
    point << "point " << k + 1 << " of " << row.file << " (x = " << p.x << ", y = " << p.y << ", sd = " << p.sd << ")";
    c.fail("file", "curve '" + row.name + "': " + point.str() + " " + why);
  }
}

// A curve's column is one of the engine's time-series columns (its table, which the runs write),
// checked before any run: a misspelt one would be found only once every run had finished.
void check_column(const dem::Section& c, const std::string& key, const std::string& name) {
  std::string known;
  for (const dem::SeriesColumn& col : dem::series_columns()) {
    if (col.name == name) return;
    known += (known.empty() ? "" : ", ") + col.name;
  }
  c.fail(key, "'" + name + "' is not a column of the runs' time series (dem columns describes them): " + known);
}

}  // namespace

std::vector<CurvePoint> read_curve_csv(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw dem::ConfigError(file + ": cannot be read (a curve: CSV with columns x, y and optionally sd)");
  std::vector<CurvePoint> points;
  std::string line;
  int number = 0;
  std::size_t columns = 0;  // the header's: 2, 3, or 3 and the specimens'
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = split_csv(line);
    if (columns == 0) {  // the first line that is not a comment names the columns
      columns = cells.size();
      const bool specimens = cells.size() > 3;
      for (std::size_t k = 3; k < cells.size(); ++k)
        if (cells[k] != "specimen_" + std::to_string(k - 2))
          throw dem::ConfigError(file + ":" + std::to_string(number) + ": column " + std::to_string(k + 1) + " is named '" +
                                 cells[k].substr(0, 40) + "'; after x, y and sd come specimen_1, specimen_2, ... (each specimen's y)");
      if (cells.size() < 2 || (specimens && cells.size() < 6))
        throw dem::ConfigError(file + ":" + std::to_string(number) + ": the header names " + std::to_string(cells.size()) +
                               " columns; a curve has 2 or 3: x, y and optionally sd, then optionally at least 3 specimens' y");
      continue;
    }
    CurvePoint p;
    std::vector<double> values(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) {
      std::string why;
      if (!dem::parse_decimal(cells[k], values[k], why) || !std::isfinite(values[k]))
        throw dem::ConfigError(file + ":" + std::to_string(number) + ": column " + std::to_string(k + 1) + " is '" +
                               cells[k].substr(0, 40) + "', not a finite number" + (why.empty() ? "" : " (" + why + ")"));
    }
    // Every row as many columns as the header: a point without its sd would weigh as if exact.
    if (cells.size() != columns)
      throw dem::ConfigError(file + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                             " columns where the header has " + std::to_string(columns) +
                             (columns >= 3 ? " (x, y, sd, ...): give every point its sd" : " (x, y)"));
    p.x = values[0], p.y = values[1];
    if (values.size() > 2) p.sd = values[2];
    p.specimens.assign(values.begin() + std::min<std::ptrdiff_t>(3, static_cast<std::ptrdiff_t>(values.size())), values.end());
    if (p.sd < 0) throw dem::ConfigError(file + ":" + std::to_string(number) + ": sd is negative");
    points.push_back(p);
  }
  if (points.empty()) throw dem::ConfigError(file + ": no points (a header line, then x, y[, sd] per line)");
  return points;
}

std::vector<CorrelatedPoints> correlated_points(const std::vector<CurveRow>& curves) {
  std::vector<CorrelatedPoints> groups;
  std::vector<std::pair<std::string, std::string>> runs;  // each group's (density, test)
  std::vector<std::size_t> counts;                        // ... and its specimens
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const CurveRow& row = curves[c];
    const std::size_t n = row.points.front().specimens.size();
    if (n < 3 || std::any_of(row.points.begin(), row.points.end(), [&](const CurvePoint& p) { return p.specimens.size() != n; })) continue;
    std::size_t g = 0;
    while (g < groups.size() && !(runs[g] == std::make_pair(row.density, row.test) && counts[g] == n)) ++g;
    if (g == groups.size()) groups.emplace_back(), runs.emplace_back(row.density, row.test), counts.push_back(n);
    for (std::size_t j = 0; j < row.points.size(); ++j) groups[g].points.emplace_back(c, j);
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::size_t m = groups[g].points.size(), n = counts[g];
    Eigen::MatrixXd values(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
    for (std::size_t k = 0; k < m; ++k) {
      const auto [c, j] = groups[g].points[k];
      for (std::size_t i = 0; i < n; ++i) values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = curves[c].points[j].specimens[i];
    }
    const Eigen::MatrixXd centred = values.rowwise() - values.colwise().mean();
    const Eigen::MatrixXd cov = centred.transpose() * centred / static_cast<double>(n - 1);
    const Eigen::VectorXd sd = cov.diagonal().cwiseSqrt();
    Eigen::MatrixXd r = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    for (Eigen::Index a = 0; a < r.rows(); ++a)
      for (Eigen::Index b = 0; b < r.cols(); ++b)
        if (a != b && sd(a) > 0 && sd(b) > 0) r(a, b) = cov(a, b) / (sd(a) * sd(b));
    const double shrink = 1.0 / static_cast<double>(n - 1);
    groups[g].correlation = (1 - shrink) * r + shrink * Eigen::MatrixXd::Identity(r.rows(), r.cols());
  }
  return groups;
}

References read_references(const std::string& file, const std::string& profile) {
  dem::Section root = dem::Section::load_file(file);
  References r;
  r.file = file;
  r.source = root.text("source", std::nullopt, "where the reference values come from (a paper, a lab, a synthetic truth)");
  for (dem::Section c : root.has("curves") ? root.list("curves", "curves the runs' time series are fitted to")
                                            : std::vector<dem::Section>{}) {
    CurveRow row;
    row.name = c.text("name", std::nullopt, "what tables call the curve");
    row.file = c.file_path("file", "the curve: a CSV with a header line and columns x, y and optionally sd");
    row.x = c.text("x", std::nullopt, "the run's time-series column along the curve (e.g. strain_3)");
    row.y = c.text("y", std::nullopt, "the run's time-series column compared (e.g. q_over_p, volumetric_strain)");
    check_column(c, "x", row.x);
    check_column(c, "y", row.y);
    row.density = c.text("density", std::nullopt, "the study's density whose runs are read");
    row.test = c.text("test", std::nullopt, "the study's test whose runs are read");
    row.specimens = static_cast<int>(c.integer("specimens", 1, 1000, 1, "specimens the curve averages (its sd is their scatter)"));
    row.tolerance = c.number("tolerance", "", {0, 1e300}, 0.0, "how well y is read off the source, in y's unit");
    c.finish();
    row.points = read_curve_csv(row.file);
    if (row.tolerance == 0 && std::all_of(row.points.begin(), row.points.end(), [](const CurvePoint& p) { return p.sd == 0; }))
      c.fail("tolerance", "is 0 and the curve has no sd column: give one of them (the misfit divides by it)");
    check_points(c, row);
    r.curves.push_back(std::move(row));
  }
  if (root.has("rows")) {
    r.rows_file = root.file_path("rows", "a validate reference file whose scalar rows are fitted too");
    r.rows = validation::load_references(r.rows_file, profile);
  }
  root.finish();
  if (r.curves.empty() && r.rows.empty()) root.fail("curves", "is empty and no rows are given: nothing to fit");
  r.correlated = correlated_points(r.curves);
  return r;
}

std::vector<std::optional<double>> curve_on_run(const CurveRow& c, const validation::TestResult& t) {
  const std::vector<double>& x = validation::column(t.series, c.x);
  const std::vector<double>& y = validation::column(t.series, c.y);
  std::size_t first = 0;
  if (const auto s = t.series.find("stage"); s != t.series.end() && !s->second.empty()) {
    const double last = s->second.back();
    while (first < s->second.size() && s->second[first] != last) ++first;
  }
  std::vector<std::optional<double>> out;
  for (const CurvePoint& p : c.points) {
    std::optional<double> v;
    for (std::size_t i = first; i + 1 < x.size() && !v; ++i) {
      const double a = x[i] - p.x, b = x[i + 1] - p.x;
      if (a == 0) v = y[i];
      else if ((a < 0) != (b < 0) || b == 0) v = y[i] + (y[i + 1] - y[i]) * (-a) / (b - a);
    }
    out.push_back(v);
  }
  return out;
}

namespace {

const validation::TestResult* find_named_test(const validation::DensityResults& d, const std::string& name) {
  for (const validation::TestResult& t : d.tests)
    if (t.name == name) return &t;
  return nullptr;
}

RowMisfit curve_misfit(const CurveRow& c, const std::vector<validation::Sample>& samples) {
  RowMisfit m{c.name, 0, 0, "", true};
  std::vector<std::vector<std::optional<double>>> per_sample;
  for (const validation::Sample& s : samples) {
    const auto d = s.densities.find(c.density);
    const validation::TestResult* t = d == s.densities.end() ? nullptr : find_named_test(d->second, c.test);
    if (!t) {
      m.valued = false, m.note = s.name + ": no complete result of " + c.density + " " + c.test;
      return m;
    }
    per_sample.push_back(curve_on_run(c, *t));
  }
  for (std::size_t j = 0; j < c.points.size(); ++j) {
    std::vector<double> ys;
    for (std::size_t k = 0; k < per_sample.size(); ++k) {
      if (!per_sample[k][j]) {
        m.valued = false;
        std::ostringstream why;
        why << samples[k].name << ": the run's " << c.x << " never reaches " << c.points[j].x << " on its last stage";
        m.note = why.str();
        return m;
      }
      ys.push_back(*per_sample[k][j]);
    }
    const validation::Spread s = validation::spread(ys);
    m.model.push_back(s.mean);
    m.model_sd.push_back(s.sd);
    m.samples = static_cast<int>(samples.size());
    m.chi2 += point_chi2(c, c.points[j], s.mean, s.sd, m.samples);
    ++m.points;
  }
  return m;
}

RowMisfit row_misfit(const validation::Row& row, const std::vector<validation::Sample>& samples) {
  RowMisfit m{row.name, 0, 1, "", true};
  const validation::RowResult r = validation::evaluate(row, samples);
  if (r.valued < static_cast<int>(samples.size())) {
    m.valued = false;
    for (const auto& s : r.samples)
      if (!s.measured.value) m.note = s.sample + ": " + s.measured.note;
    return m;
  }
  // What the response surface fits (surrogate.hpp): the samples' mean value and their sd.
  m.model = {r.spread.mean}, m.model_sd = {r.spread.sd}, m.samples = r.valued;
  if (r.verdict != validation::Verdict::NotJudged) m.consistent = r.verdict == validation::Verdict::Consistent;
  if (row.rule != "interval") {
    m.chi2 = -2 * std::log((r.holds + 0.5) / (r.valued + 1.0));
    return m;
  }
  if (std::max(r.spread.sd, row.resolution) == 0) m.note = "one sample and no resolution: the row's tolerance stands for its scatter";
  m.chi2 = interval_chi2(row, r.spread.mean, r.spread.sd, r.spread.n);
  return m;
}

}  // namespace

double point_chi2(const CurveRow& c, const CurvePoint& p, double mean, double sd, int samples) {
  const double sample_var = samples >= 3 ? sd * sd : p.sd * p.sd;
  const double var = c.tolerance * c.tolerance + p.sd * p.sd / c.specimens + sample_var / samples;
  const double r = mean - p.y;
  return var > 0 ? r * r / var : (r == 0 ? 0 : INFINITY);
}

double interval_chi2(const validation::Row& row, double mean, double sd, int samples) {
  const validation::Region paper = validation::paper_region(row.check, row.reference, row.tolerance);
  const double distance = paper.contains(mean) ? 0 : std::min(std::abs(mean - paper.low), std::abs(mean - paper.high));
  double s = std::max(sd, row.resolution);
  if (s == 0) s = row.tolerance;
  const double var = s * s * (1 + 1.0 / samples);
  return distance == 0 ? 0 : var > 0 ? distance * distance / var : INFINITY;
}

namespace {

bool same_chi2(double a, double b) { return a == b || std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

std::string recheck_curve(const CurveRow& c, const RowMisfit& m) {
  const std::size_t n = c.points.size();
  if (m.points != static_cast<int>(n) || m.model.size() != n || m.model_sd.size() != n || m.samples < 1)
    return "its values are not one per point of the curve's " + std::to_string(n);
  double chi2 = 0;
  for (std::size_t j = 0; j < n; ++j) chi2 += point_chi2(c, c.points[j], m.model[j], m.model_sd[j], m.samples);
  return same_chi2(chi2, m.chi2) ? "" : "its chi^2 " + std::to_string(m.chi2) + " is not the " + std::to_string(chi2) + " of its values";
}

std::string recheck_scalar(const validation::Row& row, const RowMisfit& m) {
  if (m.model.size() != 1 || m.model_sd.size() != 1 || m.samples < 1) return "it does not hold one mean and sd";
  if (row.rule == "interval") {
    const double chi2 = interval_chi2(row, m.model[0], m.model_sd[0], m.samples);
    return same_chi2(chi2, m.chi2) ? "" : "its chi^2 " + std::to_string(m.chi2) + " is not the " + std::to_string(chi2) + " of its values";
  }
  // -2 ln((k + 1/2) / (m + 1)) for k of the m samples: k must come out a whole number in [0, m].
  const double k = (m.samples + 1) * std::exp(-0.5 * m.chi2) - 0.5;
  if (std::abs(k - std::round(k)) <= 1e-6 && k > -0.5 && k < m.samples + 0.5) return "";
  return "its chi^2 " + std::to_string(m.chi2) + " is not that of a count of samples in which the statement holds";
}

}  // namespace

std::string recheck(const References& refs, const SetMisfit& s) {
  if (s.rows.size() != refs.curves.size() + refs.rows.size())
    return std::to_string(s.rows.size()) + " rows where the references have " + std::to_string(refs.curves.size() + refs.rows.size());
  double total = 0;
  bool valued = true;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    const RowMisfit& m = s.rows[k];
    const bool curve = k < refs.curves.size();
    const std::string& name = curve ? refs.curves[k].name : refs.rows[k - refs.curves.size()].name;
    if (m.name != name) return "row " + std::to_string(k + 1) + " is '" + m.name + "' where the references have '" + name + "'";
    if (m.valued)
      if (const std::string why = curve ? recheck_curve(refs.curves[k], m) : recheck_scalar(refs.rows[k - refs.curves.size()], m); !why.empty())
        return "'" + m.name + "': " + why;
    total += m.chi2, valued &= m.valued;
  }
  if (valued != s.valued) return "it is called " + std::string(s.valued ? "scored" : "not scored") + " against its rows";
  if (!(std::isnan(total) && std::isnan(s.chi2)) && !same_chi2(total, s.chi2))
    return "its chi^2 " + std::to_string(s.chi2) + " is not the sum of its rows' " + std::to_string(total);
  return "";
}

SetMisfit score(const References& refs, const std::vector<validation::Sample>& samples) {
  SetMisfit s;
  for (const CurveRow& c : refs.curves) s.rows.push_back(curve_misfit(c, samples));
  for (const validation::Row& row : refs.rows) s.rows.push_back(row_misfit(row, samples));
  for (RowMisfit& m : s.rows) {
    if (m.valued && std::isnan(m.chi2)) m.valued = false, m.note = "its chi^2 is not a number (a value of the runs that is not finite)";
    s.valued &= m.valued;
    s.chi2 += m.chi2;
  }
  return s;
}

SetMisfit score_complete(const References& refs, const std::vector<validation::Sample>& samples, std::size_t min_samples) {
  std::vector<validation::Sample> complete;
  std::vector<std::string> left_out;
  for (const validation::Sample& s : samples) {
    std::string lacks;
    for (const auto& [density, d] : s.densities)
      for (const std::string& run : d.missing_runs) lacks += (lacks.empty() ? "" : ", ") + density + " " + run;
    if (lacks.empty()) complete.push_back(s);
    else left_out.push_back((s.name.empty() ? std::string("the sample") : s.name) + " (no " + lacks + ")");
  }
  if (left_out.empty() || complete.size() < std::min(min_samples, samples.size())) return score(refs, samples);
  SetMisfit m = score(refs, complete);
  m.left_out = std::move(left_out);
  return m;
}

References only_densities(const References& refs, const std::vector<std::string>& densities) {
  const auto in = [&](const std::string& d) { return std::find(densities.begin(), densities.end(), d) != densities.end(); };
  References part = refs;
  part.curves.clear(), part.rows.clear();
  for (const CurveRow& c : refs.curves)
    if (in(c.density)) part.curves.push_back(c);
  for (const validation::Row& r : refs.rows)
    if (in(r.density)) part.rows.push_back(r);
  part.correlated = correlated_points(part.curves);
  return part;
}

SetMisfit projected(const SetMisfit& m, const References& from, const References& to) {
  // A misfit's rows: the curves' in order, then the scalar rows' (score).
  std::map<std::string, std::size_t> at;
  for (std::size_t c = 0; c < from.curves.size(); ++c) at["curve\n" + from.curves[c].name] = c;
  for (std::size_t r = 0; r < from.rows.size(); ++r) at["row\n" + from.rows[r].name] = from.curves.size() + r;
  SetMisfit out;
  out.left_out = m.left_out, out.chi2 = 0;
  const auto take = [&](const std::string& key) {
    const RowMisfit& row = m.rows.at(at.at(key));
    out.rows.push_back(row), out.chi2 += row.chi2;
  };
  for (const CurveRow& c : to.curves) take("curve\n" + c.name);
  for (const validation::Row& r : to.rows) take("row\n" + r.name);
  out.valued = std::all_of(out.rows.begin(), out.rows.end(), [](const RowMisfit& r) { return r.valued; });
  return out;
}

}  // namespace calibration
