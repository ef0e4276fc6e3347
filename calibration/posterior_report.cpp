#include "posterior_report.hpp"
#include "posterior_parts.hpp"

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
#include "discrepancy.hpp"
#include "row_verdicts.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "study/posterior_summary.hpp"
#include "study/series.hpp"
#include "study/stamp.hpp"

namespace calibration {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void write_file(const fs::path& path, const std::string& text) { dem::write_file_atomically(path.string(), text); }

std::string g(double x) { return validation::format_number(x); }

std::string prior_text_of(const Parameter& p) {
  if (p.prior == Parameter::Prior::Values) {
    std::string s = "one of";
    for (const std::string& v : p.values) s += " " + v;
    return s;
  }
  return std::string(p.prior == Parameter::Prior::Uniform ? "uniform" : "log-uniform") + " [" +
         validation::significant(p.low, 3) + ", " + validation::significant(p.high, 3) + "]";
}

std::size_t best_set(const std::vector<ParameterSet>& sets) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < sets.size(); ++i)
    if (sets[i].log_likelihood > sets[best].log_likelihood) best = i;
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
std::string value_shares_of(const Parameter& p, std::size_t j, const Outcome& o) {
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

// The stamp of every size's runs made one (a field on which they differ lists each value).
validation::Stamp stamp_of(const Outcome& o) {
  if (o.sizes.size() == 1) return o.first().stamp;
  std::vector<validation::Stamp> stamps;
  for (const SizeOutcome& s : o.sizes) stamps.push_back(s.stamp);
  return validation::combined(stamps);
}

// Where a size's sets from the ledger came from, when not from runs of these hashes.
void add_ledger_provenance(json& x, const SizeOutcome& s) {
  if (s.other_engine_sets > 0) x["sets_scored_by_another_engine"] = {{"sets", s.other_engine_sets}, {"engine", s.other_engine}};
  if (s.verified_sets > 0) x["sets_taken_after_verification"] = {{"sets", s.verified_sets}, {"verified_by", s.verified_by}};
}

// The sets a size ran to confirm the posterior's best prediction: what it predicted, what they gave.
json confirmed_json(const SizeOutcome& s) {
  namespace keys = validation::posterior_keys;
  json out = json::array();
  for (const SizeOutcome::Confirmed& c : s.confirmed) {
    const std::vector<const RowMisfit*> measured = s.measured(c);
    json rows = json::array();
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
      json row{{keys::name, c.rows[i]}, {keys::predicted_probability, c.row_probability[i]}};
      if (const RowMisfit* m = measured[i]) {
        if (m->consistent) row[keys::consistent] = *m->consistent;
        if (m->model.size() == 1) row[keys::mean] = m->model[0], row[keys::sd] = m->model_sd[0], row[keys::samples] = m->samples;
      }
      rows.push_back(row);
    }
    out.push_back({{keys::set, c.set}, {keys::chosen, validation::choice_names[static_cast<int>(c.chosen)]}, {keys::predicted_probability, c.probability}, {keys::rows, rows}});
  }
  return out;
}

// How far the posterior at a size lets each of its rows be reached (SizeOutcome::reach_*).
json reach_json(const SizeOutcome& s) {
  namespace keys = validation::posterior_keys;
  json rows = json::array();
  for (std::size_t i = 0; i < s.reach_rows.size(); ++i) rows.push_back({{keys::name, s.reach_rows[i]}, {keys::largest_probability, s.reach_most[i]}});
  return {{keys::points, s.reach_points}, {keys::largest_probability_all_rows, s.reach_all}, {keys::rows, rows}};
}

json sizes_json(const Report& r) {
  json out = json::array();
  for (std::size_t k = 0; k < r.o.sizes.size(); ++k) {
    const SizeOutcome& s = r.o.sizes[k];
    json x{{"profile", s.profile}, {"seeds", s.seeds}, {"sets", s.sets.size()}, {"runs", s.runs}, {"core_seconds", s.core_seconds},
           {"sets_from_ledger", s.ledger_sets}, {validation::posterior_keys::stamp, validation::stamp_json(s.stamp)}};
    add_ledger_provenance(x, s);
    if (!s.densities.empty()) x[validation::posterior_keys::densities] = s.densities;
    if (k > 0) {
      x["sets_at_most"] = s.sets_at_most();
      if (!s.confirmed.empty()) x[validation::posterior_keys::confirmed] = confirmed_json(s);
      if (s.reach_points > 0) x[validation::posterior_keys::reach] = reach_json(s);
      x["discrepancy"] = {{"pairs", s.discrepancy_pairs}, {"form", s.discrepancy_linear ? "linear" : "constant"}};
      for (const SizeOutcome::Change& c : s.changes) x["discrepancy"]["at_posterior_mean"][c.row] = {{"shift", c.shift}, {"sd", c.shift_sd}};
    }
    out.push_back(x);
  }
  return out;
}

json parameters_json(const Report& r) {
  const Calibration& c = r.o.calibration;
  json out = json::array();
  for (std::size_t k = 0; k < c.parameters.size(); ++k) {
    const Parameter& p = c.parameters[k];
    const Marginal& m = r.last.marginals[k];
    json x{{"name", p.name}, {"keys", p.keys}, {"applies_to", p.applies_to}, {"prior", prior_text_of(p)},
           {"mean", m.mean}, {"sd", m.sd}, {"median", m.median}, {"lower_95", m.lower_95}, {"upper_95", m.upper_95},
           {"narrowing", m.narrowing}, {"identified", m.identified},
           {"best", p.value(r.o.first().sets[r.best].u(static_cast<Eigen::Index>(k)))}};
    if (!p.densities.empty()) x["densities"] = p.densities;
    if (const auto t = r.truth.find(p.name); t != r.truth.end())
      x["truth"] = t->second, x["truth_inside_95"] = t->second >= m.lower_95 && t->second <= m.upper_95;
    if (!r.o.first_size_only.empty()) {
      const Marginal& f = r.o.first_size_only[k];
      x["first_size_only"] = {{"mean", f.mean}, {"sd", f.sd}, {"lower_95", f.lower_95}, {"upper_95", f.upper_95}};
      if (const auto t = r.truth.find(p.name); t != r.truth.end())
        x["first_size_only"]["truth_inside_95"] = t->second >= f.lower_95 && t->second <= f.upper_95;
    }
    out.push_back(x);
  }
  return out;
}

json sets_json(const Calibration& c, const std::vector<ParameterSet>& sets, const std::vector<double>* weights, const RowVerdicts& verdicts) {
  json out = json::array();
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const ParameterSet& s = sets[i];
    json x{{"name", s.name}, {"iteration", s.iteration}, {"scored", s.misfit.valued}};
    if (weights) x["weight"] = (*weights)[i];
    if (s.misfit.valued) x["chi2"] = s.misfit.chi2;
    if (const auto n = std::find_if(verdicts.sets.begin(), verdicts.sets.end(), [&](const SetCount& k) { return k.set == i; });
        n != verdicts.sets.end())
      x["consistent_rows"] = n->consistent, x["judged_rows"] = n->judged;
    if (!s.misfit.left_out.empty()) x["samples_left_out"] = s.misfit.left_out;
    for (std::size_t k = 0; k < c.parameters.size(); ++k) x["values"][c.parameters[k].name] = c.parameters[k].value(s.u(static_cast<Eigen::Index>(k)));
    for (const RowMisfit& m : s.misfit.rows) {
      json row{{"name", m.name}, {"points", m.points}};
      if (m.valued) row["chi2"] = m.chi2; else row["note"] = m.note;
      if (m.consistent) row["consistent"] = *m.consistent;
      x["rows"].push_back(row);
    }
    out.push_back(x);
  }
  return out;
}

json posterior_json(const Report& r) {
  const Outcome& o = r.o;
  const Calibration& c = o.calibration;
  const fs::path dir = c.report;
  json j;
  j["schema"] = 1;
  j["name"] = c.name;
  j["method"] = "adaptive multiple importance sampling: Sobol draws from defensive-mixture proposals, every set weighted "
                "against the mixture of all proposals; likelihood exp(-chi2/2)";
  j["study"] = fs::relative(c.study, dir).string();
  j["references"] = fs::relative(c.references, dir).string();
  j["source"] = o.references.source;
  j["profile"] = o.first().profile;
  j["seeds"] = o.first().seeds;
  j["engine"] = o.engine;
  j["converged"] = o.converged;
  j["stop_reason"] = o.stop_reason;
  int runs = 0, ledger_sets = 0;
  for (const SizeOutcome& s : o.sizes) runs += s.runs, ledger_sets += s.ledger_sets;
  j["runs"] = runs;
  j["sets_from_ledger"] = ledger_sets;
  j["unscored_sets"] = o.unscored;  // "name: why" of each set that weighs nothing for want of a score
  j["core_seconds"] = o.core_seconds();
  if (o.sizes.size() > 1) j[validation::posterior_keys::sizes] = sizes_json(r);
  else add_ledger_provenance(j, o.first());
  j["posterior_from"] = o.posterior_from.empty() ? "the sets' weights" : o.posterior_from;
  if (!o.posterior_from.empty())
    j["response_surface"] = {{"sets", o.surface_sets}, {"points", o.posterior_u.size()},
                             {"residual_sd_over_reference_sd", o.surface_noise}};
  j["effective_sample_size"] = r.last.ess;
  j["sets_effective_sample_size"] = r.last.sets_ess;
  for (const IterationSummary& it : o.iterations) {
    json x{{"iteration", it.number}, {"sets", it.sets},       {"scored", it.valued},          {"effective_sample_size", it.ess},
           {"sets_effective_sample_size", it.sets_ess}, {"moved", it.moved}, {"inside_region", it.contained}};
    for (std::size_t k = 0; k < c.parameters.size(); ++k)
      x["mean"][c.parameters[k].name] = it.marginals[k].mean, x["sd"][c.parameters[k].name] = it.marginals[k].sd;
    j["iterations"].push_back(x);
  }
  j["parameters"] = parameters_json(r);
  for (Eigen::Index a = 0; a < r.correlation.rows(); ++a) {
    std::vector<double> row;
    for (Eigen::Index b = 0; b < r.correlation.cols(); ++b) row.push_back(r.correlation(a, b));
    j["correlations"].push_back(row);
  }
  const ParameterSet& best = o.first().sets[r.best];
  namespace keys = validation::posterior_keys;  // what the report reads, declared once
  j[keys::best_set] = {{keys::name, best.name}, {"chi2", best.misfit.chi2}};
  if (r.verdicts.rows > 0) j[keys::rows_consistent] = rows_json(r.verdicts, o.first().sets);
  j["sets"] = sets_json(c, o.first().sets, &o.weights, r.verdicts);
  for (const Report::Part& part : r.parts) {
    const SizeOutcome& size = o.sizes[part.size];
    json x{{"profile", size.profile}, {keys::densities, size.densities}, {"sets", sets_json(c, size.sets, nullptr, part.verdicts)}};
    if (part.best) x["best_set"] = {{"name", size.sets[*part.best].name}, {"chi2", size.sets[*part.best].misfit.chi2}};
    if (part.verdicts.rows > 0) x["rows_consistent"] = rows_json(part.verdicts, size.sets);
    j[keys::largest_size_parts].push_back(x);
  }
  if (o.sizes.size() > 1 && !o.in_parts()) {
    const SizeOutcome& top = o.largest();
    json x{{"profile", top.profile}, {"sets", sets_json(c, top.sets, nullptr, r.largest_verdicts)}};
    if (r.best_largest) x["best_set"] = {{"name", top.sets[*r.best_largest].name}, {"chi2", top.sets[*r.best_largest].misfit.chi2}};
    if (r.largest_verdicts.rows > 0) x["rows_consistent"] = rows_json(r.largest_verdicts, top.sets);
    j["largest_size"] = x;
  }
  // The stamp of the runs (engine, baseline, spheres, samples, date), for the report's section line.
  j[keys::stamp] = validation::stamp_json(stamp_of(o));
  return j;
}

void write_figure_data(const Report& r) {
  const Outcome& o = r.o;
  const Calibration& c = o.calibration;
  const fs::path dir = c.report;
  const std::size_t d = c.parameters.size();
  const std::vector<ParameterSet>& all = o.first().sets;
  std::ostringstream sets;
  sets << "# every parameter set: iteration, its values, chi2 (NaN: not scored), its own weight exp(-chi2/2) over the proposals\n# iteration";
  for (const Parameter& p : c.parameters) sets << " " << p.name;
  sets << " chi2 weight\n";
  for (std::size_t i = 0; i < all.size(); ++i) {
    sets << all[i].iteration;
    for (std::size_t k = 0; k < d; ++k) sets << " " << g(c.parameters[k].value(all[i].u(static_cast<Eigen::Index>(k))));
    sets << " " << (all[i].misfit.valued ? g(all[i].misfit.chi2) : "NaN") << " " << g(o.weights[i]) << "\n";
  }
  write_file(dir / "sets.dat", sets.str());
  for (std::size_t k = 0; k < d; ++k)
    write_file(dir / ("marginal_" + std::to_string(k + 1) + ".dat"), marginal_data(c.parameters[k], k, o, r.last.marginals[k]));
  write_file(dir / "posterior_points.dat", posterior_points(o));
  // The curves of the best set: at the largest size when it has one there, else at the first.
  const bool at_largest = o.sizes.size() > 1 && r.best_largest;
  const SizeOutcome& shown = at_largest ? o.largest() : o.first();
  const std::string best_name = at_largest ? shown.sets[*r.best_largest].name : all[r.best].name;
  const auto best_samples = shown.samples.find(best_name);
  for (std::size_t k = 0; k < o.references.curves.size(); ++k)
    write_file(dir / ("curve_" + std::to_string(k + 1) + ".dat"),
               curve_data(o.references.curves[k], best_samples == shown.samples.end() ? std::vector<validation::Sample>{} : best_samples->second));
  validation::GnuplotValues v;
  v.number("parameters", static_cast<double>(d));
  v.number("curves", static_cast<double>(o.references.curves.size()));
  v.number("samples", best_samples == shown.samples.end() ? 0.0 : static_cast<double>(best_samples->second.size()));
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
          std::abs(r.correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b))) > strongest)
        strongest = std::abs(r.correlation(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b))), pair_a = static_cast<int>(a) + 1,
        pair_b = static_cast<int>(b) + 1;
  v.number("pair_a", pair_a);
  v.number("pair_b", pair_b);
  for (std::size_t k = 0; k < d; ++k) {
    const auto t = r.truth.find(c.parameters[k].name);
    v.number("truth_" + std::to_string(k + 1), t == r.truth.end() ? NAN : t->second);
    v.number("discrete_" + std::to_string(k + 1), c.parameters[k].discrete() ? 1 : 0);
    v.number("log_" + std::to_string(k + 1), c.parameters[k].prior == Parameter::Prior::LogUniform ? 1 : 0);
    v.number("values_" + std::to_string(k + 1), static_cast<double>(c.parameters[k].values.size()));
    // The range the scatter panel shows: the posterior's mean -+ 6 sd on the unit interval.
    const Marginal& m = r.last.marginals[k];
    v.number("low_" + std::to_string(k + 1), c.parameters[k].value(std::max(0.0, m.unit_mean - 6 * m.unit_sd)));
    v.number("high_" + std::to_string(k + 1), c.parameters[k].value(std::min(1.0, m.unit_mean + 6 * m.unit_sd)));
  }
  write_file(dir / "values.gp", v.text_file("calibration " + c.name + ": what calibration.gp draws"));
}

}  // namespace

std::string prior_text(const Parameter& p) { return prior_text_of(p); }
std::string value_shares(const Parameter& p, std::size_t j, const Outcome& o) { return value_shares_of(p, j, o); }

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
  Report r{o, truth, o.iterations.back(), best_set(o.first().sets), {}, std::nullopt, {}, correlations(o.posterior_u, o.posterior_w)};
  r.verdicts = tally_rows(o.first().sets, r.best);
  // The best set among a size's scored sets, by their own misfit, and its rows' verdicts.
  const auto best_of = [](const SizeOutcome& size, std::optional<std::size_t>& best, RowVerdicts& verdicts) {
    if (std::none_of(size.sets.begin(), size.sets.end(), [](const ParameterSet& s) { return s.misfit.valued; })) return;
    std::vector<ParameterSet> top = size.sets;
    for (ParameterSet& s : top) s.log_likelihood = s.misfit.valued && !std::isnan(s.misfit.chi2) ? -0.5 * s.misfit.chi2 : -INFINITY;
    best = best_set(top);
    verdicts = tally_rows(size.sets, *best);
  };
  if (o.in_parts())
    for (std::size_t k = 1; k < o.sizes.size(); ++k) {
      r.parts.push_back({k, std::nullopt, {}});
      best_of(o.sizes[k], r.parts.back().best, r.parts.back().verdicts);
    }
  else if (o.sizes.size() > 1)
    best_of(o.largest(), r.best_largest, r.largest_verdicts);
  validation::write_stamp_file(dir.string(), stamp_of(o));
  write_file(dir / "posterior.json", posterior_json(r).dump(1) + "\n");
  write_figure_data(r);
  write_file(dir / "section.md", section_markdown(r));
}

}  // namespace calibration
