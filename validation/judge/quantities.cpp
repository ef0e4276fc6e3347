#include "judge/quantities.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "judge/critical_state.hpp"
#include "study/format.hpp"
#include "study/columns.hpp"

namespace validation {

std::optional<double> strain_increment_misalignment(const TestResult& t, int c) {
  const auto& legs_cycle = t.legs.at(col::cycle);
  const auto& t1 = t.legs.at(col::target_1);
  const auto& t2 = t.legs.at(col::target_2);
  const auto& t3 = t.legs.at(col::target_3);
  const auto& leg_end = t.series.at(col::leg_end);
  const auto& leg = t.series.at("leg");
  const auto& dx = t.series.at("pi_strain_increment_x");
  const auto& dy = t.series.at("pi_strain_increment_y");
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < legs_cycle.size(); ++k) {
    if (static_cast<int>(legs_cycle[k]) != c) continue;
    const double p1 = k ? t1[k - 1] : 1e5, p2 = k ? t2[k - 1] : 1e5, p3 = k ? t3[k - 1] : 1e5;  // leg 0 starts at A
    const double sx = ((t3[k] - p3) - (t2[k] - p2)) / std::sqrt(2.0);
    const double sy = (2 * (t1[k] - p1) - (t2[k] - p2) - (t3[k] - p3)) / std::sqrt(6.0);
    for (std::size_t i = 0; i < leg.size(); ++i) {
      if (leg_end[i] != 1 || static_cast<std::size_t>(leg[i]) != k) continue;
      const double ns = std::hypot(sx, sy), ne = std::hypot(dx[i], dy[i]);
      if (ns > 0 && ne > 0) {
        const double cosine = std::clamp((sx * dx[i] + sy * dy[i]) / (ns * ne), -1.0, 1.0);
        sum += std::acos(cosine) * 180 / std::numbers::pi;
        ++n;
      }
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

std::optional<double> at_cycle_end(const TestResult& t, const std::string& column, int c) {
  const auto& cyc = t.series.at(col::cycle);
  const auto& end = t.series.at(col::cycle_end);
  const auto& v = t.series.at(column);
  for (std::size_t i = 0; i < cyc.size(); ++i)
    if (end[i] == 1 && static_cast<int>(cyc[i]) == c) return v[i];
  return std::nullopt;
}

namespace {

// Mean over the tests of f(test); the note says which tests contributed, or `none` when none did.
Measured mean_over_tests(const DensityResults& r, const std::function<std::optional<double>(const TestResult&)>& f,
                         const std::string& none = "no test reaches the cycles asked for") {
  double sum = 0;
  int n = 0;
  std::string tests;
  for (const TestResult& t : r.tests)
    if (const auto v = f(t)) {
      sum += *v;
      ++n;
      if (!tests.empty()) tests += ',';
      tests += test_label(t);
    }
  if (n == 0) return {std::nullopt, none};
  return {sum / n, "mean of tests " + tests};
}

std::optional<double> change(const TestResult& t, const std::string& column, int a, int b, double scale) {
  const auto va = at_cycle_end(t, column, a), vb = at_cycle_end(t, column, b);
  if (!va || !vb) return std::nullopt;
  return scale * (*vb - *va);
}



std::optional<double> ev_at(const TestResult& t, int c) {
  const auto v = at_cycle_end(t, col::volumetric_strain, c);
  if (!v) return std::nullopt;
  return 100 * *v;
}

// How far test `n`'s εv after cycle c leads (lead: εv_n - max over the other tests) or lags
// (εv of the least compacted other test - εv_n): positive when the ordering the paper states holds.
Measured ev_margin(const DensityResults& r, const std::string& n, int c, bool lead) {
  std::optional<double> own, other;
  std::ostringstream note;
  for (const TestResult& t : r.tests)
    if (const auto v = ev_at(t, c)) {
      note << "test " << test_label(t) << ": " << *v << " %; ";
      if (t.name == n) own = *v;
      else if (!other || (lead ? *v > *other : *v < *other)) other = *v;
    }
  if (!own || !other) return {std::nullopt, "test " + test_label(n) + " or every other test lacks cycle " + std::to_string(c)};
  return {lead ? *own - *other : *other - *own, note.str()};
}

// What a drained shear gives (critical_state.hpp: the peak on stresses smoothed over 1 % of axial
// strain, the critical state over 30 ... 40 % of it), mean over the tests.
Measured mean_over_shears(const DensityResults& r, const std::function<std::optional<double>(const ShearSummary&)>& f,
                          const std::string& none) {
  return mean_over_tests(r, [&](const TestResult& t) { return f(summarise_shear(t.series)); }, none);
}

using Fn = std::function<Measured(const QuantityRequest&, const DensityResults&)>;

struct Quantity {
  Reads reads;
  Fn fn;
  bool monotonic = false;  // meant for a monotonic shear: a cyclic test does not fit it
};

constexpr Reads preparation = Reads::Preparation, tests = Reads::Tests;

const std::map<std::string, Quantity>& registry() {
  static const std::map<std::string, Quantity> fns = {
      {"void_ratio_after_preparation",
       {preparation, [](const QuantityRequest&, const DensityResults& r) -> Measured {
          if (!r.prepared) return {std::nullopt, "no prepared sample"};
          return {r.sample.at(col::void_ratio), ""};
        }}},
      {"coordination_after_preparation",
       {preparation, [](const QuantityRequest&, const DensityResults& r) -> Measured {
          if (!r.prepared) return {std::nullopt, "no prepared sample"};
          return {r.sample.at(col::coordination_number), "without rattlers: " + std::to_string(r.sample.at(col::coordination_number_mechanical))};
        }}},
      {"coordination_without_rattlers_after_preparation",
       {preparation, [](const QuantityRequest&, const DensityResults& r) -> Measured {
          if (!r.prepared) return {std::nullopt, "no prepared sample"};
          // (2 Nc - N1) / (Np - N0 - N1): the spheres with no contact or one leave the count (Thornton 2000).
          return {r.sample.at(col::coordination_number_mechanical), "rattlers included: " + std::to_string(r.sample.at(col::coordination_number))};
        }}},
      {"cell_side_cm_after_preparation",
       {preparation, [](const QuantityRequest&, const DensityResults& r) -> Measured {
          if (!r.prepared) return {std::nullopt, "no prepared sample"};
          // The paper's cell holds 8,000 spheres: a sample of N spheres is scaled to that count by
          // (8,000 / N)^(1/3), so that smaller samples (the decisions study's) compare too.
          const double v = r.sample.at("cell_length_1") * r.sample.at("cell_length_2") * r.sample.at("cell_length_3");
          const auto n = r.sample.find("particles");
          if (n == r.sample.end() || n->second <= 0) return {100 * std::cbrt(v), "cube root of the cell volume (sphere count unknown)"};
          if (n->second == paper_particles) return {100 * std::cbrt(v), "cube root of the cell volume"};
          return {100 * std::cbrt(v * paper_particles / n->second),
                  "cube root of the cell volume, scaled to " + thousands(std::lround(paper_particles)) + " spheres from " +
                      std::to_string(static_cast<long>(n->second))};
        }}},
      {"qp_strong_fabric_slope",
       {tests, [](const QuantityRequest&, const DensityResults& r) -> Measured {
          double sxy = 0, sxx = 0, syy = 0;
          std::size_t n = 0;
          for (const TestResult& t : r.tests) {
            const auto& x = t.series.at("strong_fabric_ratio");
            const auto& y = t.series.at(col::q_over_p);
            const auto& leg = t.series.at("leg");
            for (std::size_t i = 0; i < x.size(); ++i)
              if (leg[i] >= 0) sxy += x[i] * y[i], sxx += x[i] * x[i], syy += y[i] * y[i], ++n;
          }
          if (n < 2 || sxx == 0) return {std::nullopt, "no shearing rows"};
          const double slope = sxy / sxx;
          const double r2 = 1 - (syy - 2 * slope * sxy + slope * slope * sxx) / syy;  // uncentred, fit through 0
          std::ostringstream note;
          note << "least squares through the origin over " << n << " rows of " << r.tests.size() << " tests, R^2 = " << r2;
          return {slope, note.str()};
        }}},
      {"ev_after_cycle",
       {tests, [](const QuantityRequest& q, const DensityResults& r) {
          return mean_over_tests(r, [&](const TestResult& t) { return ev_at(t, q.cycle); });
        }}},
      {"ev_growth",
       {tests, [](const QuantityRequest& q, const DensityResults& r) {
          return mean_over_tests(r, [&](const TestResult& t) { return change(t, col::volumetric_strain, q.from_cycle, q.to_cycle, 100); });
        }}},
      {"cn_change",
       {tests, [](const QuantityRequest& q, const DensityResults& r) {
          return mean_over_tests(r, [&](const TestResult& t) { return change(t, col::coordination_number, q.from_cycle, q.to_cycle, 1); });
        }}},
      {"sliding_change",
       {tests, [](const QuantityRequest& q, const DensityResults& r) {
          return mean_over_tests(r, [&](const TestResult& t) { return change(t, "sliding_fraction", q.from_cycle, q.to_cycle, 100); });
        }}},
      {"ev_lead", {Reads::TestAmongTests, [](const QuantityRequest& q, const DensityResults& r) { return ev_margin(r, q.test, q.cycle, true); }}},
      {"ev_lag", {Reads::TestAmongTests, [](const QuantityRequest& q, const DensityResults& r) { return ev_margin(r, q.test, q.cycle, false); }}},
      {"strain_increment_alignment_gain",
       {tests, [](const QuantityRequest& q, const DensityResults& r) {
          return mean_over_tests(r, [&](const TestResult& t) -> std::optional<double> {
            const auto a = strain_increment_misalignment(t, q.from_cycle), b = strain_increment_misalignment(t, q.to_cycle);
            if (!a || !b) return std::nullopt;
            return *a - *b;
          });
        }}},
      // A drained shear (a triaxial compression or extension, a constant-p shear): its last stage.
      {"peak_friction_angle",
       {tests, [](const QuantityRequest&, const DensityResults& r) {
          return mean_over_shears(r, [](const ShearSummary& s) -> std::optional<double> {
            if (s.rows == 0) return std::nullopt;
            return s.peak_phi_deg;
          }, "no test has shearing rows");
        }, true}},
      // The largest sigma_1 / sigma_3 of the shear, unsmoothed (a crystal's peak comes at ~1e-3 strain,
      // well inside the peak angle's 1 % smoothing window): Thornton's FCC strength.
      {"peak_principal_stress_ratio",
       {tests, [](const QuantityRequest&, const DensityResults& r) {
          return mean_over_shears(r, [](const ShearSummary& s) -> std::optional<double> {
            if (s.rows == 0 || s.peak_ratio_raw == 0) return std::nullopt;
            return s.peak_ratio_raw;
          }, "no test has shearing rows");
        }, true}},
      {"critical_state_friction_angle",
       {tests, [](const QuantityRequest&, const DensityResults& r) {
          return mean_over_shears(r, [](const ShearSummary& s) -> std::optional<double> {
            if (s.cs_rows == 0) return std::nullopt;
            return s.phi_deg.mean;
          }, "no test reaches 30 % axial strain");
        }, true}},
      {"critical_state_void_ratio",
       {tests, [](const QuantityRequest&, const DensityResults& r) {
          return mean_over_shears(r, [](const ShearSummary& s) -> std::optional<double> {
            if (s.cs_rows == 0) return std::nullopt;
            return s.void_ratio.mean;
          }, "no test reaches 30 % axial strain");
        }, true}},
  };
  return fns;
}

// The tests a quantity reads: all of the density's, or only the one the row names.
DensityResults only_test(const DensityResults& r, const std::string& name) {
  DensityResults out;
  out.prepared = r.prepared;
  out.sample = r.sample;
  for (const TestResult& t : r.tests)
    if (t.name == name) out.tests.push_back(t);
  return out;
}

}  // namespace

// "<quantity>_magnitude" is the absolute value of <quantity> (for "hardly changes" statements).
const std::string magnitude_suffix = "_magnitude";

std::string base_name(const std::string& name) {
  const bool magnitude = name.size() > magnitude_suffix.size() &&
                         name.compare(name.size() - magnitude_suffix.size(), magnitude_suffix.size(), magnitude_suffix) == 0;
  return magnitude ? name.substr(0, name.size() - magnitude_suffix.size()) : name;
}

bool known_quantity(const std::string& name) { return registry().count(base_name(name)) > 0; }

Reads reads_of(const std::string& name) { return registry().at(base_name(name)).reads; }

std::vector<std::string> known_quantities() {
  std::vector<std::string> out;
  for (const auto& [name, q] : registry()) out.push_back(name);
  return out;
}

namespace {

// The cyclic tests among `r`'s, "test1 (10 cycles), ...": a test whose time series counts a cycle.
std::string cyclic_tests(const DensityResults& r) {
  std::string out;
  for (const TestResult& t : r.tests) {
    const auto c = t.series.find(col::cycle);
    if (c == t.series.end() || c->second.empty()) continue;
    const double cycles = *std::max_element(c->second.begin(), c->second.end());
    if (cycles >= 1) out += (out.empty() ? "" : ", ") + t.name + " (" + number(cycles) + " cycle" + (cycles == 1 ? "" : "s") + ")";
  }
  return out;
}

}  // namespace

Measured compute(const QuantityRequest& q, const DensityResults& r) {
  try {
    const Quantity& quantity = registry().at(base_name(q.quantity));
    const bool one_test = quantity.reads == Reads::Tests && !q.test.empty();
    const DensityResults& read = one_test ? only_test(r, q.test) : r;
    Measured m = quantity.fn(q, read);
    if (m.value && base_name(q.quantity) != q.quantity) m.value = std::abs(*m.value);
    if (quantity.monotonic)
      if (const std::string cyclic = cyclic_tests(read); !cyclic.empty())
        m.misfit = q.quantity + " is meant for a monotonic shear; it read cyclic tests: " + cyclic;
    return m;
  } catch (const std::out_of_range&) {
    return {std::nullopt, "a column this quantity needs is missing from the results"};
  }
}

}  // namespace validation
