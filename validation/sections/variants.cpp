#include "sections/variants.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "judge/quantities.hpp"
#include "study/columns.hpp"

namespace validation {

std::map<std::string, double> convergence_quantities(const std::map<std::string, double>& sample,
                                                     const std::vector<std::pair<std::string, TestResult>>& tests) {
  std::map<std::string, double> q;
  DensityResults r;
  r.prepared = !sample.empty();
  r.sample = sample;
  // The preparation's values, through the validation's own definitions.
  for (const auto& [name, quantity] : {std::pair{"e0", "void_ratio_after_preparation"},
                                       std::pair{"coordination", "coordination_after_preparation"}})
    if (const Measured m = compute({quantity, "", 0, 0, 0, ""}, r); m.value) q[name] = *m.value;
  const bool several = tests.size() > 1;
  for (const auto& [test, t] : tests) {
    const std::string suffix = several ? " " + test : "";
    if (!t.series.count(col::cycle) || !t.series.count(col::cycle_end)) continue;
    int last = 0;
    for (double c : t.series.at(col::cycle)) last = std::max(last, static_cast<int>(c));
    for (int c = 1; c <= last; ++c) {
      if (const auto v = at_cycle_end(t, col::volumetric_strain, c)) q["ev_cycle" + std::to_string(c) + suffix] = *v;
      if (const auto v = at_cycle_end(t, col::deviatoric_strain, c)) q["ed_cycle" + std::to_string(c) + suffix] = *v;
      if (t.series.count(col::coordination_number))
        if (const auto v = at_cycle_end(t, col::coordination_number, c)) q["cn_cycle" + std::to_string(c) + suffix] = *v;
      if (t.series.count("pi_strain_increment_x") && t.legs.count(col::cycle))
        if (const auto v = strain_increment_misalignment(t, c)) q["angle_cycle" + std::to_string(c) + suffix] = *v;
    }
    // Changes over the cycles run (the validation's rows read cycles 1 to 5; this study's tests run 2).
    const std::string first = "_cycle1" + suffix, second = "_cycle2" + suffix;
    if (q.count("ev" + first) && q.count("ev" + second)) q["ev_growth_1_2" + suffix] = q["ev" + second] - q["ev" + first];
    if (q.count("cn" + first) && q.count("cn" + second)) q["cn_change_1_2" + suffix] = q["cn" + second] - q["cn" + first];
    DensityResults one;
    one.tests.push_back(t);
    if (const Measured m = compute({"qp_strong_fabric_slope", "", 0, 0, 0, ""}, one); m.value) q["qp_slope" + suffix] = *m.value;
  }
  return q;
}

std::vector<bool> pareto_front(const std::vector<Point>& points) {
  std::vector<bool> front(points.size(), true);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size() && front[i]; ++j) {
      const Point &a = points[i], &b = points[j];
      const bool dominates = b.cost <= a.cost && b.error <= a.error && (b.cost < a.cost || b.error < a.error);
      if (j != i && dominates) front[i] = false;
    }
  return front;
}

int cheapest_within(const std::vector<Point>& points, double tolerance) {
  int best = -1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!(p.error <= tolerance)) continue;  // NaN and +inf errors are never within
    if (best < 0) { best = static_cast<int>(i); continue; }
    const Point& b = points[static_cast<std::size_t>(best)];
    if (p.cost < b.cost || (p.cost == b.cost && p.error < b.error)) best = static_cast<int>(i);
  }
  return best;
}

namespace {

bool all_finite(const Columns& c) {
  for (const auto& [name, values] : c)
    for (double v : values)
      if (!std::isfinite(v)) return false;
  return true;
}

// The energy balance is checked once energy has come in: while the energy in (stored at the start
// plus the cell's work) is below closure_onset_fraction of its largest value, the ratio is a
// quotient of round-offs.
std::optional<double> largest_closure_error(const Columns& c) {
  const auto err = c.find("energy_closure_error");
  if (err == c.end() || err->second.empty()) return std::nullopt;
  // The energy that has come in, row by row: what is stored plus what was dissipated (equal to
  // the engine's energy in, the stored energy of the first row, the state at t = 0, plus the
  // cell's work, up to the closure gap itself).
  // A store below zero (cohesive contacts) counts as zero, as in the engine's denominator
  // (EnergyBalance::closure_error): what it released is in the dissipated energy.
  std::vector<double> in(err->second.size(), 1.0);
  const char* stores[] = {"elastic_energy_normal", "elastic_energy_tangential", "kinetic_energy_centred"};
  const char* sinks[] = {"dissipated_by_damping", "dissipated_by_friction"};
  const auto has = [&](const char* k) { return c.count(k) > 0; };
  if (std::all_of(std::begin(stores), std::end(stores), has) && std::all_of(std::begin(sinks), std::end(sinks), has))
    for (std::size_t i = 0; i < in.size(); ++i) {
      double stored = 0;
      for (const char* k : stores) stored += c.at(k)[i];
      in[i] = std::max(stored, 0.0);
      for (const char* k : sinks) in[i] += c.at(k)[i];
    }
  const double top = *std::max_element(in.begin(), in.end());
  double worst = 0;
  for (std::size_t i = 0; i < in.size(); ++i)
    if (in[i] >= closure_onset_fraction * top) worst = std::max(worst, err->second[i]);
  return worst;
}

}  // namespace

CaseOutcome classify_case(const CaseRun& run, double limit) {
  CaseOutcome o;
  if (const auto s = run.series.find(col::step); s != run.series.end() && !s->second.empty())
    o.steps = static_cast<std::int64_t>(s->second.back());
  const bool finite = all_finite(run.series);
  o.closure = largest_closure_error(run.series);
  if (run.complete) {
    o.message = "";
    if (!finite) o.outcome = "non-finite values in the result";
    else if (!o.closure) o.outcome = "ran; energy closure not measured (engine without energy columns)";
    else if (!(*o.closure <= limit)) o.outcome = "ran; energy closure above the limit";
    else o.outcome = "ran; energy closure within the limit", o.acceptable = true;
    return o;
  }
  if (run.exit_code) {
    o.message = run.message;
    const bool clear = !run.message.empty();
    if (*run.exit_code == 2) o.outcome = "refused before any step", o.steps = 0;
    else o.outcome = "stopped early";
    if (!finite) o.outcome += "; non-finite values in its partial result";
    else if (!clear) o.outcome += " without a message";
    o.acceptable = finite && clear;
    return o;
  }
  o.outcome = "not run";
  return o;
}

}  // namespace validation
