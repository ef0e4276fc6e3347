#include "figures/figures.hpp"

#include "study/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "analysis/fabric.hpp"
#include "analysis/measurements.hpp"
#include "control/stress_path.hpp"
#include "study/ensemble.hpp"
#include "judge/quantities.hpp"
#include "study/columns.hpp"

namespace validation {

namespace {

bool in_cycles(const SeriesRow& r, int max_cycle) { return max_cycle < 0 || r(col::cycle) <= max_cycle; }

}  // namespace

Table target_path(const Columns& legs) {
  Table t;
  t.comments = {"target path in the normalised pi-plane, A at the origin: one arrow per distinct leg (from /legs target_1..3)",
                "x = (s3 - s2)/(sqrt(2) p), y = (2 s1 - s2 - s3)/(sqrt(6) p), p = mean of the leg's targets"};
  t.columns = {"x_from [1]", "y_from [1]", "dx [1]", "dy [1]"};
  const auto& t1 = column(legs, col::target_1);
  const auto& t2 = column(legs, col::target_2);
  const auto& t3 = column(legs, col::target_3);
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  std::set<std::vector<long long>> seen;  // legs compared to 1e-4, as drawn
  const auto key = [](double x) { return std::llround(x * 1e4); };
  for (std::size_t k = 0; k < t1.size(); ++k) {
    const Eigen::Vector2d to = pi_stress(dem::Vec3(t1[k], t2[k], t3[k]));
    if (seen.insert({key(from[0]), key(from[1]), key(to[0]), key(to[1])}).second)
      t.rows.push_back({from[0], from[1], to[0] - from[0], to[1] - from[1]});
    from = to;
  }
  return t;
}

Table stress_path(const Columns& series) {
  Table t;
  t.comments = {"measured stress path in the normalised pi-plane, every row (axis stresses s11, s22, s33)"};
  t.columns = {"x [1]", "y [1]", "cycle [1]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    const Eigen::Vector2d xy = pi_stress(stress_of(r).diagonal());
    t.rows.push_back({xy[0], xy[1], r(col::cycle)});
  }
  return t;
}

Table named_states(double p, double R) {
  Table t;
  t.comments = {"named states of the stress paths (p = " + format_number(p) + " Pa, R = " + format_number(R) +
                ") in the normalised pi-plane"};
  t.columns = {"x [1]", "y [1]"};
  for (const char* name : {"A", "TC1", "TC2", "TC3", "TE1", "TE2", "TE3"}) {
    const Eigen::Vector2d xy = pi_stress(dem::named_state(name, p, R));
    t.labels.push_back(name);
    t.rows.push_back({xy[0], xy[1]});
  }
  return t;
}

Table target_q(double p, double R) {
  Table t;
  t.comments = {"deviator stress q of the TC and TE states (p = " + format_number(p) + " Pa, R = " + format_number(R) + ")"};
  t.columns = {"q [kPa]"};
  for (const char* name : {"TC1", "TE1"}) {
    const dem::Vec3 s = dem::named_state(name, p, R);
    t.labels.push_back(std::string(name).substr(0, 2));
    t.rows.push_back({dem::deviator_stress(dem::Mat3(s.asDiagonal())) / 1e3});
  }
  return t;
}

Table q_against_p(const Columns& series) {
  Table t;
  t.comments = {"mean stress p and deviator stress q of the full stress tensor, every row"};
  t.columns = {"p [kPa]", "q [kPa]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const dem::Mat3 s = stress_of({series, i});
    t.rows.push_back({dem::mean_stress(s) / 1e3, dem::deviator_stress(s) / 1e3});
  }
  return t;
}

Table qp_against_deviatoric_strain(const Columns& series, int max_cycle) {
  Table t;
  t.comments = {"deviatoric strain of paper Eq. 4 and q/p, cycles <= " + std::to_string(max_cycle)};
  t.columns = {"eps_d [%]", "q/p [1]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    if (in_cycles(r, max_cycle)) t.rows.push_back({100 * r(col::deviatoric_strain), q_over_p(stress_of(r))});
  }
  return t;
}

Table volumetric_strain_against(const Columns& series, int test, int max_cycle) {
  const bool against_qp = test == 2 || test == 3;
  Table t;
  t.comments = {std::string("volumetric strain 1 - V/V0 (compression +) against ") +
                (against_qp ? "q/p" : "s11/s33") + ", cycles <= " + std::to_string(max_cycle)};
  t.columns = {against_qp ? "q/p [1]" : "s11/s33 [1]", "eps_v [%]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    if (!in_cycles(r, max_cycle)) continue;
    const dem::Mat3 s = stress_of(r);
    t.rows.push_back({against_qp ? q_over_p(s) : (s(2, 2) > 0 ? s(0, 0) / s(2, 2) : 0.0), 100 * r(col::volumetric_strain)});
  }
  return t;
}

Table qp_against_fabric(const Columns& series, const std::string& which, int max_cycle) {
  Table t;
  t.comments = {(which == "fabric" ? std::string("fabric ratio F_d/F_m of all contacts (paper Eq. 8)")
                                   : std::string("fabric ratio F^s_d/F^s_m of the strong contacts (paper Eqs. 9-10)")) +
                " and q/p, cycles <= " + std::to_string(max_cycle)};
  t.columns = {which + "_ratio [1]", "q/p [1]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    if (in_cycles(r, max_cycle)) t.rows.push_back({fabric_ratio_of(r, which), q_over_p(stress_of(r))});
  }
  return t;
}

const std::vector<CycleQuantity>& cycle_quantities() {
  // The sliding fraction has no cycle 0: the first row's sliding flags come from the saved sample
  // (its preparation friction), not from a step with the shearing friction.
  static const std::vector<CycleQuantity> q = {{"epsv_percent", col::volumetric_strain, "%", 100, true},
                                               {"coordination", col::coordination_number, "1", 1, true},
                                               {"sliding_percent", "sliding_fraction", "%", 100, false}};
  return q;
}

Table cycle_statistics(const std::vector<const TestResult*>& tests, const CycleQuantity& q) {
  std::map<int, std::vector<double>> by_cycle;
  for (const TestResult* t : tests) {
    if (!t || !t->series.count(q.column) || t->series.at(q.column).empty()) continue;
    if (q.from_start) by_cycle[0].push_back(q.scale * t->series.at(q.column).front());
    const int last = last_cycle(t->series);
    for (int c = 1; c <= last; ++c)
      if (const auto v = at_cycle_end(*t, q.column, c)) by_cycle[c].push_back(q.scale * *v);
  }
  Table out;
  out.comments = {q.column + " at the end of each cycle" + (q.from_start ? " (cycle 0: the first row, the start of shearing)" : "") +
                  ", over " + std::to_string(tests.size()) + " sample(s)"};
  out.columns = {"cycle [1]", "mean [" + q.unit + "]", "sd [" + q.unit + "]", "n [1]", "min [" + q.unit + "]", "max [" + q.unit + "]"};
  for (const auto& [c, values] : by_cycle) {
    const Spread s = spread(values);
    out.rows.push_back({static_cast<double>(c), s.mean, s.sd, static_cast<double>(s.n),
                        *std::min_element(values.begin(), values.end()), *std::max_element(values.begin(), values.end())});
  }
  return out;
}

Table ensemble_cycle_table(const std::vector<Sample>& samples, const std::string& density, int test, const CycleQuantity& q,
                           std::size_t* runs) {
  std::vector<const TestResult*> tests;
  for (const Sample& s : samples)
    if (const auto it = s.densities.find(density); it != s.densities.end())
      if (const TestResult* x = find_test(it->second, test)) tests.push_back(x);
  if (runs) *runs = tests.size();
  return cycle_statistics(tests, q);
}

int last_cycle(const Columns& series) {
  const auto it = series.find(col::cycle);
  if (it == series.end() || it->second.empty()) return 0;
  return static_cast<int>(*std::max_element(it->second.begin(), it->second.end()));
}

CyclicTestLine cyclic_test_line(const Columns& series, const Columns& legs) {
  CyclicTestLine line{"—", "—", "—", "—", "—", "—", "—", "—", "—"};
  const auto has = [](const Columns& c, const char* k) { return c.count(k) && !c.at(k).empty(); };
  if (has(series, col::step)) line.steps = std::to_string(static_cast<long long>(series.at(col::step).back()));
  if (has(legs, "rms_error_1") && has(legs, "rms_error_2") && has(legs, "rms_error_3")) {
    double worst = 0;
    for (const char* k : {"rms_error_1", "rms_error_2", "rms_error_3"})
      worst = std::max(worst, *std::max_element(legs.at(k).begin(), legs.at(k).end()));
    line.tracking_percent = fixed(100 * worst, 3);
  }
  if (has(legs, "max_inertial_number")) {
    const auto& in = legs.at("max_inertial_number");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", *std::max_element(in.begin(), in.end()));
    line.inertial_number = buf;
  }
  if (has(series, col::coordination_number)) line.cn_start = fixed(series.at(col::coordination_number).front(), 3);
  if (!(has(series, col::cycle) && has(series, col::cycle_end) && has(series, col::volumetric_strain) && has(series, col::coordination_number)))
    return line;
  const int last = last_cycle(series);
  line.last_cycle = std::to_string(last);
  const auto& cyc = series.at(col::cycle);
  const auto& end = series.at(col::cycle_end);
  for (std::size_t i = 0; i < cyc.size(); ++i) {
    if (end[i] != 1) continue;
    const std::string ev = fixed(100 * series.at(col::volumetric_strain)[i], 4), cn = fixed(series.at(col::coordination_number)[i], 3);
    if (cyc[i] == 1) line.ev_cycle1 = ev, line.cn_cycle1 = cn;
    if (cyc[i] == last) line.ev_last = ev, line.cn_last = cn;
  }
  return line;
}

Table test5_blocks(const Columns& series, const Columns& legs, std::vector<std::string>& titles) {
  // The loaded axis of each cycle: the largest target of its legs that are not A.
  const auto& lc = column(legs, col::cycle);
  const auto& t1 = column(legs, col::target_1);
  const auto& t2 = column(legs, col::target_2);
  const auto& t3 = column(legs, col::target_3);
  std::map<int, int> axis;
  int cycles = 0;
  for (std::size_t k = 0; k < lc.size(); ++k) {
    int a = 1;
    if (t2[k] > t1[k] && t2[k] >= t3[k]) a = 2;
    if (t3[k] > t1[k] && t3[k] > t2[k]) a = 3;
    if (t1[k] != t2[k] || t2[k] != t3[k]) axis[static_cast<int>(lc[k])] = a;
    cycles = std::max(cycles, static_cast<int>(lc[k]));
  }
  std::map<int, int> block_of;  // cycle -> block (from 1)
  struct Block {
    int first, last, axis;
  };
  std::vector<Block> blocks;
  for (int c = 1, prev = 0; c <= cycles; ++c) {
    const int a = axis.count(c) ? axis[c] : 0;
    if (a != prev) blocks.push_back({c, c, a}), prev = a;
    blocks.back().last = c;
    block_of[c] = static_cast<int>(blocks.size());
  }
  titles.clear();
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "cycles %d–%d: A↔TC%d (steps %zu–%zu)", blocks[b].first, blocks[b].last, blocks[b].axis,
                  2 * b + 1, 2 * b + 2);
    titles.push_back(buf);
  }
  Table t;
  t.comments = {"Test 5: s11/s33 and volumetric strain, every row; one block (gnuplot index) per run of cycles loading the same axis",
                "each block starts with the previous block's last row, so the curve is continuous"};
  t.columns = {"s11/s33 [1]", "eps_v [%]", "cycle [1]"};
  int current = 0;
  std::vector<double> last;
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    const int c = std::max(1, static_cast<int>(r(col::cycle)));
    const int b = block_of.count(c) ? block_of[c] : current;
    const dem::Mat3 s = stress_of(r);
    const std::vector<double> row = {s(2, 2) > 0 ? s(0, 0) / s(2, 2) : 0.0, 100 * r(col::volumetric_strain), r(col::cycle)};
    if (b != current) {
      if (current) {
        t.block_starts.push_back(t.rows.size());
        t.rows.push_back(last);
      }
      current = b;
    }
    t.rows.push_back(row);
    last = row;
  }
  return t;
}

Table strain_increments(const Columns& series, int cycle, double scale) {
  Table t;
  t.comments = {"the legs of cycle " + std::to_string(cycle) +
                    ": measured stress at the leg's end (normalised pi-plane) and the leg's strain increment in the pi-plane",
                "arrow = increment x " + format_number(scale) + " (the scale of the panel)"};
  t.columns = {"x [1]", "y [1]", "deps_x [1]", "deps_y [1]", "arrow_dx [1]", "arrow_dy [1]", "leg [1]", "order [1]"};
  int order = 0;
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    if (r(col::leg_end) != 1 || static_cast<int>(r(col::cycle)) != cycle) continue;
    const Eigen::Vector2d xy = pi_stress(stress_of(r).diagonal());
    const double dx = r("pi_strain_increment_x"), dy = r("pi_strain_increment_y");
    t.rows.push_back({xy[0], xy[1], dx, dy, dx * scale, dy * scale, r("leg"), static_cast<double>(++order)});
  }
  return t;
}

Table cycle_stress_path(const Columns& series, int cycle) {
  Table t;
  t.comments = {"measured stress path of cycle " + std::to_string(cycle) + " (from the leg end before it), normalised pi-plane"};
  t.columns = {"x [1]", "y [1]"};
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    const int c = static_cast<int>(r(col::cycle));
    if (c != cycle && !(c == cycle - 1 && r(col::leg_end) == 1)) continue;
    const Eigen::Vector2d xy = pi_stress(stress_of(r).diagonal());
    t.rows.push_back({xy[0], xy[1]});
  }
  return t;
}

double arrow_scale(const Columns& series, const std::vector<int>& cycles) {
  double longest = 0;
  for (std::size_t i = 0; i < row_count(series); ++i) {
    const SeriesRow r{series, i};
    if (r(col::leg_end) != 1 || std::find(cycles.begin(), cycles.end(), static_cast<int>(r(col::cycle))) == cycles.end()) continue;
    longest = std::max(longest, std::hypot(r("pi_strain_increment_x"), r("pi_strain_increment_y")));
  }
  if (longest <= 0) return 1;
  const double s = 0.12 / longest;
  const double e = std::pow(10.0, std::trunc(std::log10(s) - (s < 1 ? 1 : 0)));
  const double f = s / e;
  return (f >= 5 ? 5 : f >= 2 ? 2 : 1) * e;
}

EnergyCurves energy_curves(const Columns& series) {
  EnergyCurves c;
  const std::size_t n = row_count(series);
  const auto col = [&](const std::string& name) -> const std::vector<double>& { return column(series, name); };
  static const std::vector<double> none;
  const auto optional_col = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = series.find(name);
    return it == series.end() ? none : it->second;
  };
  const auto& t = col(validation::col::time);
  const auto& w = col("work_by_cell");
  const auto& dd = col("dissipated_by_damping");
  const auto& df = col("dissipated_by_friction");
  const auto& dr = optional_col("dissipated_by_rolling");
  const auto& en = col("elastic_energy_normal");
  const auto& et = col("elastic_energy_tangential");
  const auto& er = optional_col("elastic_energy_rolling");
  const auto& k = col("kinetic_energy_centred");
  const auto& contacts = col("contacts");
  const auto at = [](const std::vector<double>& v, std::size_t i) { return v.empty() ? 0.0 : v.at(i); };
  // An engine before the fix wrote row 0 before any force evaluation: its energy columns are 0
  // although the sample holds contacts (the springs' energy is not 0). Such a row is not the state.
  c.baseline_row = n > 1 && contacts.at(0) > 0 && en.at(0) == 0 ? 1 : 0;
  const std::size_t b = c.baseline_row;
  const auto stored = [&](std::size_t i) { return en.at(i) + et.at(i) + at(er, i) + k.at(i); };
  const auto damping = [&](std::size_t i) { return dd.at(i); };
  const auto friction = [&](std::size_t i) { return df.at(i) + at(dr, i); };
  for (std::size_t i = b; i < n; ++i) {
    c.time_s.push_back(t.at(i));
    c.work_J.push_back(w.at(i) - w.at(b));
    c.damping_J.push_back(damping(i) - damping(b));
    c.friction_J.push_back(friction(i) - friction(b));
    c.dissipated_J.push_back(c.damping_J.back() + c.friction_J.back());
    c.stored_change_J.push_back(stored(i) - stored(b));
    c.gap_J.push_back(c.work_J.back() - (c.dissipated_J.back() + c.stored_change_J.back()));
  }
  return c;
}

double EnergyCurves::closure_relative_to_work() const {
  const double total = work_total_J();
  if (!(std::abs(total) > 0)) return std::nan("");
  double worst = 0;
  for (double g : gap_J) worst = std::max(worst, std::abs(g));
  return worst / std::abs(total);
}

std::optional<double> EnergyCurves::parting_time_s(double fraction) const {
  const double total = std::abs(work_total_J());
  for (std::size_t i = 0; i < gap_J.size(); ++i)
    if (std::abs(work_J[i]) > 0.01 * total && std::abs(gap_J[i]) > fraction * std::abs(work_J[i])) return time_s[i];
  return std::nullopt;
}

Table energy_balance(const Columns& series) {
  const EnergyCurves c = energy_curves(series);
  const auto& err = column(series, "energy_closure_error");
  Table t;
  t.comments = {"energy balance, every curve from row " + std::to_string(c.baseline_row + 1) +
                    " of the time series (" + (c.time_s.empty() ? std::string("no rows") : "t = " + number(c.time_s.front()) + " s") +
                    "; engine/README.md, Energy balance; validation/figures.hpp, energy_curves)",
                "gap = work - (dissipated + change of stored); closure_error: the engine's, |E_in - (stored + dissipated)| / E_in"};
  t.columns = {"time [s]", "work_by_cell [J]", "dissipated_by_damping [J]", "dissipated_by_friction [J]", "stored_change [J]",
               "dissipated_plus_stored_change [J]", "gap [J]", "energy_closure_error [1]"};
  for (std::size_t i = 0; i < c.time_s.size(); ++i)
    t.rows.push_back({c.time_s[i], c.work_J[i], c.damping_J[i], c.friction_J[i], c.stored_change_J[i],
                      c.dissipated_J[i] + c.stored_change_J[i], c.gap_J[i], err.at(c.baseline_row + i)});
  return t;
}

Table grading_target(const dem::SceneConfig& scene) {
  Table t;
  const bool mass = scene.particles.grading_basis == dem::GradingCurve::Basis::Mass;
  t.comments = {std::string("grading curve of the scene (particles.grading), read by ") + (mass ? "mass" : "count")};
  t.columns = {"diameter [mm]", "percent_finer [%]"};
  for (std::size_t k = 0; k < scene.particles.grading_diameters_m.size(); ++k)
    t.rows.push_back({1e3 * scene.particles.grading_diameters_m[k], scene.particles.grading_percent_finer.at(k)});
  return t;
}

Table grading_realised(const std::vector<double>& radius_m) {
  std::vector<double> d;
  for (double r : radius_m) d.push_back(2e3 * r);
  std::sort(d.begin(), d.end());
  double total = 0;
  for (double x : d) total += x * x * x;
  Table t;
  t.comments = {"grading realised by " + std::to_string(d.size()) + " spheres, sorted by diameter"};
  t.columns = {"diameter [mm]", "percent_finer_by_mass [%]", "percent_finer_by_count [%]"};
  double mass = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    mass += d[i] * d[i] * d[i];
    t.rows.push_back({d[i], 100 * mass / total, 100 * static_cast<double>(i + 1) / static_cast<double>(d.size())});
  }
  return t;
}

double grading_diameter_at(const std::vector<double>& d, const std::vector<double>& P, double percent) {
  if (d.empty() || d.size() != P.size()) return NAN;
  if (percent <= P.front()) return d.front();
  for (std::size_t k = 1; k < d.size(); ++k)
    if (percent <= P[k]) return d[k - 1] + (d[k] - d[k - 1]) * (percent - P[k - 1]) / (P[k] - P[k - 1]);
  return d.back();
}

Table spheres(const dem::Particles& particles, const dem::PeriodicCell& cell) {
  Table t;
  const dem::Vec3& L = cell.lengths();
  t.comments = {std::to_string(particles.size()) + " spheres in a cell of " + format_number(1e3 * L[0]) + " x " +
                format_number(1e3 * L[1]) + " x " + format_number(1e3 * L[2]) + " mm"};
  t.columns = {"x1 [mm]", "x2 [mm]", "x3 [mm]", "diameter [mm]"};
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const dem::Vec3 x = cell.to_real(particles.s[i]);
    t.rows.push_back({1e3 * x[0], 1e3 * x[1], 1e3 * x[2], 2e3 * particles.radius[i]});
  }
  return t;
}

std::optional<double> paper_value(const std::vector<Row>& rows, const std::string& quantity, const std::string& density) {
  for (const Row& r : rows)
    if (r.quantity == quantity && (density.empty() || r.density == density)) return r.reference;
  return std::nullopt;
}

double square_axis_max(const std::vector<const Table*>& tables) {
  double m = 0;
  for (const Table* t : tables)
    for (const auto& row : t->rows)
      for (std::size_t k = 0; k < 2 && k < row.size(); ++k) m = std::max(m, row[k]);
  m *= 1.05;
  if (m < 0.3) m = 0.3;
  return std::ceil(m / 0.05 - 1e-9) * 0.05;
}

}  // namespace validation
