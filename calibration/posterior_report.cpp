#include "posterior_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "config/yaml_section.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "row_verdicts.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "study/series.hpp"
#include "study/stamp.hpp"

namespace calibration {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void write_file(const fs::path& path, const std::string& text) { dem::write_file_atomically(path.string(), text); }

std::string g(double x) { return validation::format_number(x); }

std::string prior_text(const Parameter& p) {
  if (p.prior == Parameter::Prior::Values) {
    std::string s = "one of";
    for (const std::string& v : p.values) s += " " + v;
    return s;
  }
  return std::string(p.prior == Parameter::Prior::Uniform ? "uniform" : "log-uniform") + " [" +
         validation::significant(p.low, 3) + ", " + validation::significant(p.high, 3) + "]";
}

std::size_t best_set(const Outcome& o) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < o.sets.size(); ++i)
    if (o.sets[i].log_likelihood > o.sets[best].log_likelihood) best = i;
  return best;
}

// The posterior's weight on each value of a parameter of values (its unit interval cut in equal
// parts, one per value), over its total.
std::vector<double> value_masses(const Parameter& p, std::size_t j, const Outcome& o) {
  std::vector<double> mass(p.values.size(), 0.0);
  double total = 0;
  for (std::size_t i = 0; i < o.posterior_u.size(); ++i) {
    mass[p.value_index(o.posterior_u[i](static_cast<Eigen::Index>(j)))] += o.posterior_w[i];
    total += o.posterior_w[i];
  }
  if (total > 0)
    for (double& m : mass) m /= total;
  return mass;
}

// The posterior's density over the prior's: a parameter of values, a bar per value; else 30 bins
// over the posterior's range on the unit interval (its mean -+ 4 sd, within [0, 1]).
std::string marginal_data(const Parameter& p, std::size_t j, const Outcome& o, const Marginal& m) {
  std::ostringstream s;
  s << "# " << p.name << ": the posterior's density over the prior's, in bins of the posterior's range\n";
  if (p.discrete()) {  // a bar per value, at its index, labelled with the value
    const std::vector<double> mass = value_masses(p, j, o);
    const double n = static_cast<double>(mass.size());
    s << "# index-0.4 index index+0.4 density_over_prior value\n";
    for (std::size_t b = 0; b < mass.size(); ++b)
      s << g(static_cast<double>(b) - 0.4) << " " << b << " " << g(static_cast<double>(b) + 0.4) << " " << g(mass[b] * n) << " "
        << p.values[b] << "\n";
    return s.str();
  }
  const std::size_t bins = 30;
  const double lo = std::max(0.0, m.unit_mean - 4 * m.unit_sd);
  const double hi = std::min(1.0, m.unit_mean + 4 * m.unit_sd);
  const double width = (hi - lo) / static_cast<double>(bins);
  std::vector<double> mass(bins, 0.0);
  for (std::size_t i = 0; i < o.posterior_u.size(); ++i) {
    const double u = o.posterior_u[i](static_cast<Eigen::Index>(j));
    if (u < lo || u > hi || width <= 0) continue;
    mass[std::min(bins - 1, static_cast<std::size_t>((u - lo) / width))] += o.posterior_w[i];
  }
  s << "# value_low value_centre value_high density_over_prior\n";
  for (std::size_t b = 0; b < bins; ++b) {
    const double a = lo + width * static_cast<double>(b), z = std::min(1 - 1e-12, a + width);
    s << g(p.value(a)) << " " << g(p.value(0.5 * (a + z))) << " " << g(p.value(z)) << " " << g(width > 0 ? mass[b] / width : 0) << "\n";
  }
  return s.str();
}

// "viscous 0.71, local 0.29": the posterior's weight on each value of a parameter of values.
std::string value_shares(const Parameter& p, std::size_t j, const Outcome& o) {
  const std::vector<double> mass = value_masses(p, j, o);
  std::string text;
  for (std::size_t b = 0; b < mass.size(); ++b) text += (b ? ", " : "") + p.values[b] + " " + validation::fixed(mass[b], 2);
  return text;
}

// 1,000 points resampled from the posterior's weighted points (systematic resampling: deterministic).
std::string posterior_points(const Outcome& o) {
  const Calibration& c = o.calibration;
  std::ostringstream s;
  s << "# 1,000 points resampled from the posterior (their values)\n#";
  for (const Parameter& p : c.parameters) s << " " << p.name;
  s << "\n";
  double cumulative = 0;
  std::size_t i = 0;
  for (int k = 0; k < 1000 && !o.posterior_u.empty(); ++k) {
    const double target = (k + 0.5) / 1000;
    while (i + 1 < o.posterior_u.size() && cumulative + o.posterior_w[i] < target) cumulative += o.posterior_w[i++];
    for (std::size_t j = 0; j < c.parameters.size(); ++j)
      s << (j ? " " : "") << g(c.parameters[j].value(o.posterior_u[i](static_cast<Eigen::Index>(j))));
    s << "\n";
  }
  return s.str();
}

// The reference points; then, for each sample of the best set, its curve on its last stage.
std::string curve_data(const CurveRow& c, const std::vector<validation::Sample>& samples) {
  std::ostringstream s;
  s << "# " << c.name << ": " << c.y << " against " << c.x << "\n# block 0: the reference (x y sd)\n";
  for (const CurvePoint& p : c.points) s << g(p.x) << " " << g(p.y) << " " << g(p.sd) << "\n";
  const double x_max = std::max_element(c.points.begin(), c.points.end(), [](auto& a, auto& b) { return a.x < b.x; })->x;
  for (const validation::Sample& sample : samples) {
    s << "\n\n# block: the best set's " << (sample.name.empty() ? "sample" : sample.name) << " (x y)\n";
    const auto d = sample.densities.find(c.density);
    if (d == sample.densities.end()) continue;
    for (const validation::TestResult& t : d->second.tests) {
      if (t.name != c.test) continue;
      const auto& x = validation::column(t.series, c.x);
      const auto& y = validation::column(t.series, c.y);
      const auto& stage = validation::column(t.series, "stage");
      for (std::size_t i = 0; i < x.size(); ++i)
        if (stage[i] == stage.back() && x[i] <= 1.05 * x_max) s << g(x[i]) << " " << g(y[i]) << "\n";
    }
  }
  return s.str();
}

}  // namespace

std::map<std::string, double> parameters_of_result(const Calibration& c, const std::string& result) {
  dem::h5::Handle f = dem::h5::open_file_read(result);
  const YAML::Node scene = dem::parse_yaml(dem::h5::read_text(f, "scene_yaml"), result);
  std::map<std::string, double> values;
  const auto at = [&](const std::string& key) {
    YAML::Node n = YAML::Clone(scene);
    std::stringstream path(key);
    for (std::string part; std::getline(path, part, '.');) {
      if (!n.IsMap() || !n[part]) throw std::runtime_error(result + ": its scene has no " + key);
      n = n[part];
    }
    return n;
  };
  for (const Parameter& p : c.parameters) {
    if (!p.readings.empty()) {  // the reading whose every key the scene holds; its value (Parameter::value)
      for (std::size_t k = 0; k < p.readings.size() && !values.count(p.name); ++k)
        if (std::all_of(p.readings[k].begin(), p.readings[k].end(), [&](const std::pair<std::string, std::string>& kv) {
              return at(kv.first).as<std::string>() == dem::parse_yaml(kv.second, c.file).as<std::string>();
            }))
          values[p.name] = p.value((static_cast<double>(k) + 0.5) / static_cast<double>(p.readings.size()));
      if (!values.count(p.name)) throw std::runtime_error(result + ": its scene holds none of the readings of " + p.name);
      continue;
    }
    std::optional<double> value;
    for (const std::string& key : p.keys) {
      const double x = at(key).as<double>();
      if (value && *value != x) throw std::runtime_error(result + ": the keys of " + p.name + " differ");
      value = x;
    }
    values[p.name] = *value;
  }
  return values;
}

void write_report(const Outcome& o, const std::map<std::string, double>& truth) {
  const Calibration& c = o.calibration;
  const fs::path dir = c.report;
  fs::create_directories(dir);
  const std::size_t d = c.parameters.size();
  const IterationSummary& last = o.iterations.back();
  const std::size_t best = best_set(o);

  json j;
  j["schema"] = 1;
  j["name"] = c.name;
  j["method"] = "adaptive multiple importance sampling: Sobol draws from defensive-mixture proposals, every set weighted "
                "against the mixture of all proposals; likelihood exp(-chi2/2)";
  j["study"] = fs::relative(c.study, dir).string();
  j["references"] = fs::relative(c.references, dir).string();
  j["source"] = o.references.source;
  j["profile"] = o.profile;
  j["seeds"] = o.seeds;
  j["engine"] = o.engine;
  j["converged"] = o.converged;
  j["stop_reason"] = o.stop_reason;
  j["runs"] = o.runs;
  j["sets_from_ledger"] = o.ledger_sets;
  j["unscored_sets"] = o.unscored;  // "name: why" of each set that weighs nothing for want of a score
  j["core_seconds"] = o.core_seconds;
  j["posterior_from"] = o.posterior_from.empty() ? "the sets' weights" : o.posterior_from;
  if (!o.posterior_from.empty())
    j["response_surface"] = {{"sets", o.surface_sets}, {"points", o.posterior_u.size()},
                             {"residual_sd_over_reference_sd", o.surface_noise}};
  j["effective_sample_size"] = last.ess;
  j["sets_effective_sample_size"] = last.sets_ess;
  for (const IterationSummary& it : o.iterations) {
    json x{{"iteration", it.number}, {"sets", it.sets},       {"scored", it.valued},          {"effective_sample_size", it.ess},
           {"sets_effective_sample_size", it.sets_ess}, {"moved", it.moved}, {"inside_region", it.contained}};
    for (std::size_t k = 0; k < d; ++k) x["mean"][c.parameters[k].name] = it.marginals[k].mean, x["sd"][c.parameters[k].name] = it.marginals[k].sd;
    j["iterations"].push_back(x);
  }
  for (std::size_t k = 0; k < d; ++k) {
    const Parameter& p = c.parameters[k];
    const Marginal& m = last.marginals[k];
    json x{{"name", p.name}, {"keys", p.keys}, {"applies_to", p.applies_to}, {"prior", prior_text(p)},
           {"mean", m.mean}, {"sd", m.sd}, {"median", m.median}, {"lower_95", m.lower_95}, {"upper_95", m.upper_95},
           {"narrowing", m.narrowing}, {"identified", m.identified}, {"best", p.value(o.sets[best].u(static_cast<Eigen::Index>(k)))}};
    if (!p.densities.empty()) x["densities"] = p.densities;
    if (const auto t = truth.find(p.name); t != truth.end())
      x["truth"] = t->second, x["truth_inside_95"] = t->second >= m.lower_95 && t->second <= m.upper_95;
    j["parameters"].push_back(x);
  }
  const Eigen::MatrixXd r = correlations(o.posterior_u, o.posterior_w);
  for (Eigen::Index a = 0; a < r.rows(); ++a) {
    std::vector<double> row;
    for (Eigen::Index b = 0; b < r.cols(); ++b) row.push_back(r(a, b));
    j["correlations"].push_back(row);
  }
  j["best_set"] = {{"name", o.sets[best].name}, {"chi2", o.sets[best].misfit.chi2}};
  const RowVerdicts verdicts = tally_rows(o.sets, best);
  if (verdicts.rows > 0) j["rows_consistent"] = rows_json(verdicts, o.sets);
  for (std::size_t i = 0; i < o.sets.size(); ++i) {
    const ParameterSet& s = o.sets[i];
    json x{{"name", s.name}, {"iteration", s.iteration}, {"weight", o.weights[i]}, {"scored", s.misfit.valued}};
    if (s.misfit.valued) x["chi2"] = s.misfit.chi2;
    if (const auto c = std::find_if(verdicts.sets.begin(), verdicts.sets.end(), [&](const SetCount& k) { return k.set == i; });
        c != verdicts.sets.end())
      x["consistent_rows"] = c->consistent, x["judged_rows"] = c->judged;
    if (!s.misfit.left_out.empty()) x["samples_left_out"] = s.misfit.left_out;
    for (std::size_t k = 0; k < d; ++k) x["values"][c.parameters[k].name] = c.parameters[k].value(s.u(static_cast<Eigen::Index>(k)));
    for (const RowMisfit& m : s.misfit.rows) {
      json row{{"name", m.name}, {"points", m.points}};
      if (m.valued) row["chi2"] = m.chi2; else row["note"] = m.note;
      if (m.consistent) row["consistent"] = *m.consistent;
      x["rows"].push_back(row);
    }
    j["sets"].push_back(x);
  }
  // The stamp of the runs (engine, baseline, spheres, samples, date), for the report's section line.
  j["stamp"] = validation::stamp_json(o.stamp);
  validation::write_stamp_file(dir.string(), o.stamp);
  write_file(dir / "posterior.json", j.dump(1) + "\n");

  // Figure data.
  std::ostringstream sets;
  sets << "# every parameter set: iteration, its values, chi2 (NaN: not scored), its own weight exp(-chi2/2) over the proposals\n# iteration";
  for (const Parameter& p : c.parameters) sets << " " << p.name;
  sets << " chi2 weight\n";
  for (std::size_t i = 0; i < o.sets.size(); ++i) {
    sets << o.sets[i].iteration;
    for (std::size_t k = 0; k < d; ++k) sets << " " << g(c.parameters[k].value(o.sets[i].u(static_cast<Eigen::Index>(k))));
    sets << " " << (o.sets[i].misfit.valued ? g(o.sets[i].misfit.chi2) : "NaN") << " " << g(o.weights[i]) << "\n";
  }
  write_file(dir / "sets.dat", sets.str());
  for (std::size_t k = 0; k < d; ++k)
    write_file(dir / ("marginal_" + std::to_string(k + 1) + ".dat"), marginal_data(c.parameters[k], k, o, last.marginals[k]));
  write_file(dir / "posterior_points.dat", posterior_points(o));
  const auto best_samples = o.samples.find(o.sets[best].name);
  for (std::size_t k = 0; k < o.references.curves.size(); ++k)
    write_file(dir / ("curve_" + std::to_string(k + 1) + ".dat"),
               curve_data(o.references.curves[k], best_samples == o.samples.end() ? std::vector<validation::Sample>{} : best_samples->second));
  validation::GnuplotValues v;
  v.number("parameters", static_cast<double>(d));
  v.number("curves", static_cast<double>(o.references.curves.size()));
  v.number("samples", best_samples == o.samples.end() ? 0.0 : static_cast<double>(best_samples->second.size()));
  std::vector<std::string> names, xs, ys, titles;
  for (const Parameter& p : c.parameters) names.push_back(p.name);
  for (const CurveRow& row : o.references.curves) xs.push_back(row.x), ys.push_back(row.y), titles.push_back(row.name);
  v.texts("parameter", names);
  v.texts("curve_x", xs);
  v.texts("curve_y", ys);
  v.texts("curve_title", titles);
  // The plane the scatter panel shows: of the continuous parameters, the two most correlated in
  // the posterior (none with fewer than two).
  int pair_a = 0, pair_b = 0;
  double strongest = -1;
  for (std::size_t a = 0; a < d; ++a)
    for (std::size_t b = a + 1; b < d; ++b)
      if (!c.parameters[a].discrete() && !c.parameters[b].discrete() &&
          std::abs(r(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b))) > strongest)
        strongest = std::abs(r(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b))), pair_a = static_cast<int>(a) + 1,
        pair_b = static_cast<int>(b) + 1;
  v.number("pair_a", pair_a);
  v.number("pair_b", pair_b);
  for (std::size_t k = 0; k < d; ++k) {
    const auto t = truth.find(c.parameters[k].name);
    v.number("truth_" + std::to_string(k + 1), t == truth.end() ? NAN : t->second);
    v.number("discrete_" + std::to_string(k + 1), c.parameters[k].discrete() ? 1 : 0);
    v.number("log_" + std::to_string(k + 1), c.parameters[k].prior == Parameter::Prior::LogUniform ? 1 : 0);
    v.number("values_" + std::to_string(k + 1), static_cast<double>(c.parameters[k].values.size()));
    // The range the scatter panel shows: the posterior's mean -+ 6 sd on the unit interval.
    const Marginal& m = last.marginals[k];
    v.number("low_" + std::to_string(k + 1), c.parameters[k].value(std::max(0.0, m.unit_mean - 6 * m.unit_sd)));
    v.number("high_" + std::to_string(k + 1), c.parameters[k].value(std::min(1.0, m.unit_mean + 6 * m.unit_sd)));
  }
  write_file(dir / "values.gp", v.text_file("calibration " + c.name + ": what calibration.gp draws"));

  // The tables.
  std::ostringstream md;
  md << "Calibration `" << c.name << "` of the study `" << fs::path(c.study).filename().string() << "` (profile " << o.profile
     << ", " << o.seeds.size() << " sample(s) per set) against " << o.references.source << ". Engine " << o.engine << ".\n\n";
  md << o.sets.size() << " parameter sets in " << o.iterations.size() << (o.iterations.size() == 1 ? " iteration of " : " iterations of ") << c.batch << " (" << o.runs
     << " runs, " << validation::significant(o.core_seconds / 60, 3) << " core-min recorded); effective sample size "
     << validation::significant(last.ess, 3) << "; " << (o.converged ? "converged: " : "not converged: ") << o.stop_reason << ".\n\n";
  if (o.ledger_sets > 0)
    md << o.ledger_sets << " of the sets were scored in earlier calls whose runs' results are not kept here: their scores come "
       << "from the ledger `scored_sets.json`, which records each set's run hashes and misfit.\n\n";
  const auto short_of = std::count_if(o.sets.begin(), o.sets.end(), [](const ParameterSet& s) { return !s.misfit.left_out.empty(); });
  if (short_of > 0)
    md << short_of << " of the sets " << (short_of == 1 ? "was" : "were")
       << " scored without a sample some run of which did not finish (`posterior.json`: `samples_left_out`).\n\n";
  if (!o.posterior_from.empty()) {
    md << "The posterior is sampled on a response surface (a quadratic in the parameters per curve point and per scalar row) fitted "
          "to the "
       << o.surface_sets << " sets nearest it, at " << o.posterior_u.size() << " points: the sets' own misfits carry the noise of "
       << "their samples";
    if (o.surface_noise > 0)
      md << " (their scatter about the surface is " << validation::significant(o.surface_noise, 2) << " times the reference mean's sd, on average)";
    md << ", which would let the luckiest set carry the posterior.\n\n";
  }
  std::vector<std::string> head{"parameter", "prior", "posterior mean ± sd", "95 % interval", "prior sd / posterior sd", "identified"};
  if (!truth.empty()) head.insert(head.begin() + 2, "truth");
  validation::MarkdownTable t(head);
  for (std::size_t k = 0; k < d; ++k) {
    const Parameter& p = c.parameters[k];
    const Marginal& m = last.marginals[k];
    // A parameter of values: the posterior's share of each value (its mean of indices means nothing).
    std::vector<std::string> cells{p.name, prior_text(p),
                                   p.discrete() ? value_shares(p, k, o)
                                                : validation::significant(m.mean, 3) + " ± " + validation::significant(m.sd, 2),
                                   p.discrete() ? "—" : "[" + validation::significant(m.lower_95, 3) + ", " + validation::significant(m.upper_95, 3) + "]",
                                   validation::significant(m.narrowing, 2),
                                   m.identified ? "yes" : "no: the references barely narrow its prior"};
    if (!truth.empty()) {
      const auto tr = truth.find(p.name);
      cells.insert(cells.begin() + 2, tr == truth.end() ? "" :
                   validation::significant(tr->second, 3) + (tr->second >= m.lower_95 && tr->second <= m.upper_95 ? " (inside)" : " (OUTSIDE)"));
    }
    t.row(cells);
  }
  md << t.text() << "\n";
  if (d > 1) {
    std::vector<std::string> ch{"correlation"};
    for (const Parameter& p : c.parameters) ch.push_back(p.name);
    validation::MarkdownTable ct(ch);
    for (std::size_t a = 0; a < d; ++a) {
      std::vector<std::string> cells{c.parameters[a].name};
      for (std::size_t b = 0; b < d; ++b) cells.push_back(validation::fixed(r(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)), 2));
      ct.row(cells);
    }
    md << ct.text() << "\n";
  }
  validation::MarkdownTable it({"iteration", "sets", "scored (all so far)", "effective points of the posterior", "largest move"});
  for (const IterationSummary& s : o.iterations)
    it.row({std::to_string(s.number), std::to_string(s.sets), std::to_string(s.valued), validation::significant(s.ess, 3),
            s.number == 1 ? "" : validation::fixed(s.moved, 3)});
  md << it.text() << "\n";
  md << "Best set " << o.sets[best].name << " (χ² " << validation::significant(o.sets[best].misfit.chi2, 3) << "):";
  for (std::size_t k = 0; k < d; ++k)
    md << " " << c.parameters[k].name << " = "
       << (c.parameters[k].discrete() ? c.parameters[k].value_text(o.sets[best].u(static_cast<Eigen::Index>(k)))
                                      : validation::significant(c.parameters[k].value(o.sets[best].u(static_cast<Eigen::Index>(k))), 4))
       << (k + 1 < d ? "," : ".");
  md << "\n";
  validation::MarkdownTable rows({"reference", "points", "χ² at the best set", "χ² per point"});
  for (const RowMisfit& m : o.sets[best].misfit.rows)
    rows.row({m.name, std::to_string(m.points), validation::significant(m.chi2, 3),
              m.points > 0 ? validation::significant(m.chi2 / m.points, 2) : ""});
  md << "\n" << rows.text();
  if (verdicts.rows > 0) md << "\n" << rows_markdown(verdicts, o.sets);
  write_file(dir / "section.md", md.str());
}

}  // namespace calibration
