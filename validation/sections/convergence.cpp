// compare-runs convergence: the error budget of the paper's settings. From the study's results
// (or its committed summary.json, --summary), for each density and headline quantity: the errors
// of the paper's settings in the time step, the stress rate and the sample size against the
// extrapolated converged value (convergence_budget.hpp), beside the scatter between samples; then
// every setting's error against the converged value with its cost, the Pareto front and the
// cheapest setting within 1, 5 and 10 %; and, given the paper study's validation.json, whether each
// inconsistent row's miss is larger than the budget. Writes OUT/summary.json (from results only),
// table.md, errors.dat and front.dat (reports/gnuplot/convergence_error_vs_time.gp draws them).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "sections/convergence_budget.hpp"
#include "sections/convergence_rows.hpp"
#include "sections/convergence_summary.hpp"
#include "sections/modes.hpp"
#include "sections/variants.hpp"
#include "study/ensemble.hpp"
#include "study/json_file.hpp"
#include "study/markdown_table.hpp"
#include "study/paths.hpp"

namespace fs = std::filesystem;
using validation::Budget;
using validation::ConvergenceRun;
using validation::ConvergenceSummary;
using validation::Estimate;
using validation::PerSeed;
using validation::budget_number;
using validation::factors_of;

namespace sections {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// The paper study's samples per density: the sampling error of its ensemble's mean.
constexpr int paper_samples = 5;
// A quantity whose converged value is known to better than this (relative half-width) can judge
// settings; the others' errors are the samples' scatter.
constexpr double resolved_below = 0.10;
// Pairs whose correlation is below this share too little of the sample for the difference to
// beat the scatter: the variance of a difference is 2 sd^2 (1 - r), no smaller than unpaired
// samples' 2 sd^2 unless r > 0, and half of it only at r = 0.5.
constexpr double decorrelated_below = 0.5;

// The quantities in reading order and their headings.
const std::vector<std::pair<std::string, std::string>>& headline() {
  static const std::vector<std::pair<std::string, std::string>> q = {
      {"e0", "e0"}, {"coordination", "CN"}, {"ev_cycle1", "εv 1"}, {"ev_cycle2", "εv 2"}, {"ed_cycle1", "εd 1"},
      {"ed_cycle2", "εd 2"}, {"cn_cycle1", "CN 1"}, {"cn_cycle2", "CN 2"}, {"angle_cycle1", "angle 1 (°)"},
      {"angle_cycle2", "angle 2 (°)"}, {"qp_slope", "q/p slope"}, {"ev_growth_1_2", "εv 2 − εv 1"},
      {"cn_change_1_2", "CN 2 − CN 1"}};
  return q;
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }


// "+1.23 ± 0.40 %" of `scale`; the half-width left out when there is none.
std::string signed_percent(const Estimate& e, double scale) {
  if (!std::isfinite(e.value) || !(std::abs(scale) > 0)) return "—";
  char buf[64];
  const double v = 100 * e.value / std::abs(scale), h = 100 * e.half_width / std::abs(scale);
  const char* f = std::abs(v) < 0.1 && (!std::isfinite(h) || h < 0.1) ? "%+.3f" : "%+.2f";
  std::snprintf(buf, sizeof buf, f, v);
  std::string s = buf;
  // A value that rounds to zero has no sign to show: a rounding error of either sign gave "-0.000"
  // from the results and "+0.000" from their summary for the same error.
  if (s.find_first_not_of("+-0.") == std::string::npos) s[0] = '+';
  if (std::isfinite(h)) {
    std::snprintf(buf, sizeof buf, std::abs(h) < 0.1 ? " ± %.3f" : " ± %.2f", h);
    s += buf;
  }
  return s + " %";
}

std::string fixed2(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

// "1.23 ± 0.40 %" (a magnitude or an sd: no sign).
std::string unsigned_percent(const Estimate& e, double scale = 1) {
  const std::string s = signed_percent(e, scale);
  return s.empty() || (s[0] != '+' && s[0] != '-') ? s : s.substr(1);
}

// One density's runs: variant -> seed -> run.
using Runs = std::map<std::string, std::map<int, const ConvergenceRun*>>;

PerSeed values(const Runs& runs, const std::string& variant, const std::string& quantity) {
  PerSeed v;
  if (!runs.count(variant)) return v;
  for (const auto& [seed, r] : runs.at(variant))
    if (r->status.empty() && r->quantities.count(quantity) && std::isfinite(r->quantities.at(quantity))) v[seed] = r->quantities.at(quantity);
  return v;
}

std::vector<double> list(const PerSeed& p) {
  std::vector<double> v;
  for (const auto& [s, x] : p) v.push_back(x);
  return v;
}

// A setting: its runs' shared settings (from its first complete run).
struct Setting {
  std::string variant;
  double dt = nan, prep_dt = nan, rate = nan, core_s = 0;  // the test's and the preparation's time step
  long spheres = 0;
  int samples = 0;
};

std::map<std::string, Setting> settings_of(const Runs& runs) {
  std::map<std::string, Setting> s;
  for (const auto& [variant, seeds] : runs) {
    Setting x{variant};
    for (const auto& [seed, r] : seeds) {
      if (!r->status.empty()) continue;
      if (x.samples == 0) x.dt = r->time_step_s, x.prep_dt = r->preparation_time_step_s, x.rate = r->rate_Pa_s, x.spheres = r->spheres;
      x.core_s += r->core_s;
      ++x.samples;
    }
    if (x.samples) x.core_s /= x.samples;
    s[variant] = x;
  }
  return s;
}

// What one density's analysis found, for the table and the figure.
struct DensityBudget : validation::DensityBudgets {
  std::map<std::string, Setting> settings;
  std::string dt_half, dt_quarter;            // the time step of the test only, on the reference's samples ("" none)
  std::string both_half, both_quarter;        // the time step of the preparation and the test
  std::vector<std::string> rates;             // the rate variants, the paper's among them
  std::vector<std::string> sizes;             // the other sizes' variants
};

// The quantities of the prepared sample: the test's time step does not touch them.
bool of_preparation(const std::string& quantity) { return quantity == "e0" || quantity == "coordination"; }

validation::FactorError not_run(const std::string& why) { return {{nan, nan}, why, false}; }

DensityBudget analyse(const std::string& density, const Runs& runs, const std::string& reference) {
  DensityBudget d;
  d.density = density;
  d.settings = settings_of(runs);
  const Setting& ref = d.settings.at(reference);
  for (const auto& [variant, s] : d.settings) {
    if (s.samples == 0 || variant == reference) continue;
    const bool dt_same = same(s.dt, ref.dt), rate_same = same(s.rate, ref.rate), n_same = s.spheres == ref.spheres;
    const bool prep_same = same(s.prep_dt, ref.prep_dt), prep_with_test = same(s.prep_dt, s.dt);
    if (rate_same && n_same && prep_same && same(s.dt, ref.dt / 2)) d.dt_half = variant;
    if (rate_same && n_same && prep_same && same(s.dt, ref.dt / 4)) d.dt_quarter = variant;
    if (rate_same && n_same && prep_with_test && same(s.dt, ref.dt / 2)) d.both_half = variant;
    if (rate_same && n_same && prep_with_test && same(s.dt, ref.dt / 4)) d.both_quarter = variant;
    if (dt_same && prep_same && n_same && !rate_same) d.rates.push_back(variant);
    if (dt_same && prep_same && rate_same && !n_same) d.sizes.push_back(variant);
  }
  for (const auto& [name, heading] : headline()) {
    const PerSeed paper = values(runs, reference, name);
    if (paper.empty()) continue;
    Budget b;
    b.quantity = name;
    b.paper = validation::mean_of(list(paper));
    const PerSeed both_half = values(runs, d.both_half, name), both_quarter = values(runs, d.both_quarter, name);
    if (of_preparation(name)) {
      b.time_step = {{0, 0}, "the prepared sample's: the test's step does not touch it", false};
      b.preparation_step = validation::time_step_error(paper, both_half, both_quarter);
    } else if (d.dt_quarter.empty()) {
      b.time_step = not_run("the test's step alone not run");
      b.preparation_step = validation::time_step_error(paper, both_half, both_quarter);
      b.preparation_step.how = "preparation and test together: " + b.preparation_step.how;
    } else {
      b.time_step = validation::time_step_error(paper, values(runs, d.dt_half, name), values(runs, d.dt_quarter, name));
      if (d.both_quarter.empty()) {
        b.preparation_step = not_run("no preparation at the finest step");
      } else {
        // The same seeds prepared at the paper's step and at the finest, both sheared at the finest.
        b.preparation_step = validation::paired_difference(values(runs, d.dt_quarter, name), both_quarter);
        b.preparation_step.how = "the same seeds prepared at " + d.dt_quarter + "'s and " + d.both_quarter + "'s step: finest step";
      }
    }
    std::map<double, PerSeed> by_rate = {{ref.rate, paper}};
    for (const std::string& v : d.rates) by_rate[d.settings.at(v).rate] = values(runs, v, name);
    b.rate = validation::rate_error(by_rate, ref.rate);
    std::map<long, PerSeed> by_size = {{ref.spheres, paper}};
    for (const std::string& v : d.sizes) by_size[d.settings.at(v).spheres] = values(runs, v, name);
    b.size = d.sizes.empty() ? not_run("no other size ran") : validation::size_error(by_size, ref.spheres);
    b.sd_one = validation::sd_of(list(paper));
    b.sd_mean = b.sd_one / std::sqrt(paper_samples);
    b.converged = validation::converged_value(b.paper, {&b.time_step, &b.preparation_step, &b.rate, &b.size});
    d.budgets.push_back(b);
  }
  return d;
}

std::string heading_of(const std::string& name) {
  for (const auto& [n, h] : headline())
    if (n == name) return h;
  return name;
}

bool resolved(const Budget& b) {
  return std::isfinite(b.converged.half_width) && std::abs(b.converged.value) > 0 &&
         b.converged.half_width / std::abs(b.converged.value) < resolved_below;
}

// A setting's largest relative error against the converged values over the resolved quantities,
// with the half-width of that quantity's error.
Estimate largest_error(const DensityBudget& d, const Runs& runs, const std::string& variant, std::string& which) {
  Estimate worst{nan, nan};
  for (const Budget& b : d.budgets) {
    if (!resolved(b)) continue;
    const PerSeed v = values(runs, variant, b.quantity);
    if (v.empty()) return {std::numeric_limits<double>::infinity(), nan};
    const Estimate e = validation::relative_error_to(validation::mean_of(list(v)), b.converged);
    if (!std::isfinite(worst.value) || e.value > worst.value) worst = e, which = heading_of(b.quantity);
  }
  return worst;
}

std::string settings_text(const Setting& s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "Δt %g µs, %g MPa/s, %ld spheres", s.dt * 1e6, s.rate * 1e-6, s.spheres);
  return buf;
}

// The section's first line: what the study is and what it cost. A preparation several settings
// share ran once: counted once where the runs record its part.
std::string study_line(const ConvergenceSummary& s, std::size_t densities) {
  double core_s = 0, shared_s = 0;
  std::set<std::string> preparations;
  for (const ConvergenceRun& r : s.runs) {
    core_s += r.core_s;
    char key[160];
    std::snprintf(key, sizeof key, "%s/%d/%ld/%.6g", r.density.c_str(), r.seed, r.spheres, r.preparation_time_step_s);
    if (std::isfinite(r.preparation_core_s) && !preparations.insert(key).second) shared_s += r.preparation_core_s;
  }
  std::ostringstream md;
  std::set<std::string> variants;
  for (const ConvergenceRun& r : s.runs) variants.insert(r.variant);
  md << "Study: " << s.runs.size() << " samples (a preparation and a test each) of " << variants.size() << " settings at "
     << densities << " densities, engine `" << s.engine
     << "`, baseline `" << s.baseline << "`, summarised " << s.date << " from `" << s.results << "`; "
     << std::lround(core_s / 60) << " core-minutes summed over the settings' samples (a preparation several settings share counted with "
        "each; " << s.threads << " thread per run), " << std::lround((core_s - shared_s) / 60)
     << " with each shared preparation counted once where its runs record it.\n";
  return md.str();
}

int write_section(const ConvergenceSummary& s, const std::string& out, const std::string& reference, const std::string& validation_json) {
  std::vector<std::string> densities;
  std::map<std::string, Runs> by_density;
  for (const ConvergenceRun& r : s.runs) {
    if (!by_density.count(r.density)) densities.push_back(r.density);
    by_density[r.density][r.variant][r.seed] = &r;
  }
  std::vector<DensityBudget> all;
  for (const std::string& d : densities) {
    const Runs& runs = by_density.at(d);
    if (!runs.count(reference) || settings_of(runs).at(reference).samples == 0) {
      std::fprintf(stderr, "compare-runs: the reference variant '%s' has no complete %s run\n", reference.c_str(), d.c_str());
      return 1;
    }
    all.push_back(analyse(d, runs, reference));
  }
  std::ostringstream md;
  md << study_line(s, densities.size());
  std::string errors_dat = "# density\tvariant\tcore_s\tlargest_relative_error\thalf_width\tpareto\tquantity\n", front_dat = errors_dat;
  for (const DensityBudget& d : all) {
    const Runs& runs = by_density.at(d.density);
    const Setting& ref = d.settings.at(reference);
    md << "\n#### " << d.density << ": the error budget of the paper's settings (" << settings_text(ref) << ", " << ref.samples
       << " samples)\n\nEach factor's error is the paper's settings' value minus the converged value in that factor, in % of the "
          "converged value, with its 95 % interval; one sample and mean of " << paper_samples
       << " are the scatter between samples (sd, and sd/√" << paper_samples << ").\n\n";
    validation::MarkdownTable t({"quantity", "paper's settings", "Δt of the test", "Δt of the preparation", "rate", "size", "one sample",
                                 "mean of 5", "converged"});
    validation::MarkdownTable pairs({"quantity", "Δt of the test", "Δt of the preparation", "rate", "size: χ²/dof about the line"});
    std::map<std::string, std::vector<std::string>> hows;  // "factor: how" -> quantities
    std::vector<std::string> unhelped;                      // "quantity (factor)" where the pairs decorrelated
    for (const Budget& b : d.budgets) {
      const double c = b.converged.value;
      t.row({heading_of(b.quantity), budget_number(b.paper.value) + " ± " + budget_number(b.paper.half_width), signed_percent(b.time_step.error, c),
             signed_percent(b.preparation_step.error, c), signed_percent(b.rate.error, c), signed_percent(b.size.error, c),
             unsigned_percent({b.sd_one, nan}, c), unsigned_percent({b.sd_mean, nan}, c),
             budget_number(c) + " ± " + budget_number(b.converged.half_width)});
      std::vector<std::string> r;
      for (const auto& [factor, f] : factors_of(b)) {
        if (f == &b.size) continue;
        r.push_back(std::isfinite(f->correlation) ? fixed2(f->correlation) : "—");
        if (std::isfinite(f->correlation) && f->correlation < decorrelated_below) unhelped.push_back(heading_of(b.quantity) + " (" + factor + ")");
      }
      pairs.row({heading_of(b.quantity), r[0], r[1], r[2], std::isfinite(b.size.lack_of_fit) ? fixed2(b.size.lack_of_fit) : "—"});
      hows["Δt of the test: " + b.time_step.how].push_back(heading_of(b.quantity));
      hows["Δt of the preparation: " + b.preparation_step.how].push_back(heading_of(b.quantity));
      hows["rate: " + b.rate.how].push_back(heading_of(b.quantity));
      hows["size: " + b.size.how].push_back(heading_of(b.quantity));
    }
    std::string sizes;
    for (const std::string& v : d.sizes) sizes += (sizes.empty() ? "" : ", ") + v;
    md << t.text() << "\nHow each factor was taken to its limit (Δt of the test: " << (d.dt_half.empty() ? "—" : d.dt_half) << ", "
       << (d.dt_quarter.empty() ? "—" : d.dt_quarter) << "; of the preparation: " << (d.both_half.empty() ? "—" : d.both_half) << ", "
       << (d.both_quarter.empty() ? "—" : d.both_quarter) << "; rates: " << d.rates.size() + 1 << "; sizes: "
       << (sizes.empty() ? "—" : sizes) << "):\n\n";
    for (const auto& [how, qs] : hows) {
      md << "- " << how << ": ";
      for (std::size_t k = 0; k < qs.size(); ++k) md << (k ? ", " : "") << qs[k];
      md << "\n";
    }
    md << "\nHow well the pairs held, and the size's line: the correlation over the samples of the paper's setting's values with the other "
          "setting's (Δt of the test: the finest step on the same prepared samples; of the preparation: the same seeds prepared at "
          "the paper's and the finest step; rate: the slowest rate on the same prepared samples), and how far the sizes' means "
          "stray from their line in 1/N (χ²/dof; above 1 the size's interval is widened by its root). Near 1 the pairs cancel the "
          "samples' scatter; below " << fixed2(decorrelated_below) << " pairing did not help";
    if (unhelped.empty()) md << " (no quantity here).\n\n";
    else {
      md << ": ";
      for (std::size_t k = 0; k < unhelped.size(); ++k) md << (k ? ", " : "") << unhelped[k];
      md << ".\n\n";
    }
    md << pairs.text();
    // Every setting against the converged values.
    std::vector<std::string> names, quantities;
    for (const Budget& b : d.budgets)
      if (resolved(b)) quantities.push_back(heading_of(b.quantity));
    std::vector<validation::Point> points;
    std::vector<Estimate> errors;
    std::vector<std::string> which;
    for (const auto& [variant, setting] : d.settings) {
      if (setting.samples == 0) continue;
      std::string w;
      errors.push_back(largest_error(d, runs, variant, w));
      names.push_back(variant);
      which.push_back(w);
      points.push_back({setting.core_s, errors.back().value});
    }
    const std::vector<bool> front = validation::pareto_front(points);
    if (quantities.empty()) {
      md << "\nNo quantity's converged value is known to better than " << std::lround(100 * resolved_below)
         << " % at this density: the settings cannot be told apart on these samples (cost per sample, preparation + test: ";
      bool first = true;
      for (const auto& [variant, setting] : d.settings)
        if (setting.samples) md << (first ? "" : ", ") << variant << " " << std::lround(setting.core_s) << " core-s", first = false;
      md << ").\n";
      continue;
    }
    md << "\nEvery setting against the converged values: the largest relative error over the quantities known to better than "
       << std::lround(100 * resolved_below) << " % (";
    for (std::size_t k = 0; k < quantities.size(); ++k) md << (k ? ", " : "") << quantities[k];
    md << "), mean over its samples; core-seconds per sample (preparation + test); ★ on the Pareto front.\n\n";
    validation::MarkdownTable e({"setting", "settings", "samples", "core-s", "largest error", "on"});
    std::vector<std::size_t> order(names.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points[a].cost < points[b].cost; });
    for (std::size_t k : order) {
      const Setting& st = d.settings.at(names[k]);
      e.row({names[k] + (front[k] ? " ★" : ""), settings_text(st), std::to_string(st.samples), std::to_string(std::lround(st.core_s)),
             unsigned_percent(errors[k]), which[k]});
      char line[256];
      std::snprintf(line, sizeof line, "%s\t%s\t%.6g\t%.6g\t%.6g\t%d\t%s\n", d.density.c_str(), names[k].c_str(), st.core_s,
                    errors[k].value, errors[k].half_width, front[k] ? 1 : 0, which[k].c_str());
      errors_dat += line;
      if (front[k]) front_dat += line;
    }
    md << e.text() << "\n";
    for (double tol : {0.01, 0.05, 0.10}) {
      const int best = validation::cheapest_within(points, tol);
      md << "Cheapest within " << std::lround(100 * tol) << " % of the converged values: ";
      if (best < 0) {
        md << "none of the settings run.\n";
        continue;
      }
      const std::size_t k = static_cast<std::size_t>(best);
      const bool sure = errors[k].value + (std::isfinite(errors[k].half_width) ? errors[k].half_width : 0) <= tol;
      md << names[k] << " (" << std::lround(points[k].cost) << " core-s, " << unsigned_percent(errors[k])
         << (sure ? ", the whole interval within" : ", its interval reaching beyond") << ").\n";
    }
  }
  if (!validation_json.empty()) {
    const nlohmann::json j = validation::read_json_file(validation_json);
    const std::vector<validation::DensityBudgets> budgets(all.begin(), all.end());
    md << validation::precision_table(budgets, j) << validation::verdict_reading(budgets, j, validation_json);
  }
  try {
    dem::write_file_atomically((fs::path(out) / "errors.dat").string(), errors_dat);
    dem::write_file_atomically((fs::path(out) / "front.dat").string(), front_dat);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("convergence: %zu runs, %zu densities -> %s\n", s.runs.size(), all.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}

}  // namespace

int convergence(const Manifest& manifest, const std::string& results, const std::string& out, const std::string& reference,
                int threads, const std::string& validation_json) {
  ConvergenceSummary s = validation::summarise_convergence(manifest, results, threads);
  const fs::path committed = fs::path(out) / "summary.json";
  std::error_code ec;
  if (fs::exists(committed, ec)) s = validation::merge_summaries(s, validation::read_convergence_summary(committed.string()));
  try {
    dem::write_file_atomically((fs::path(out) / "summary.json").string(), validation::summary_json(s));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return write_section(s, out, reference, validation_json);
}

int convergence_from_summary(const std::string& file, const std::string& out, const std::string& reference,
                             const std::string& validation_json) {
  return write_section(validation::read_convergence_summary(file), out, reference, validation_json);
}

}  // namespace sections
