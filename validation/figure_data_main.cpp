// figure-data: the data behind the report's figures and the numbers its text quotes, from a
// study's results, its resolved scenes and reference_data/paper.yaml (validation/figures.hpp).
//   figure-data figures RESULTS_DIR FIG_DIR [--sample NAME] [--references FILE]
//       every figure's data files (figNN_*.dat, columns named with units) and values.gp, the
//       numbers the static scripts in reports/gnuplot/ read (the paper's among them)
//   figure-data settings RESULTS_DIR [--prefix P | --run NAME]
//       the settings the runs used, read from the resolved scenes of the first sample's
//       P<density>_prepare.h5 and P<density>_test<N>.h5, or of NAME.h5 alone (key<TAB>value), for
//       the report's text
//   figure-data samples-table RESULTS_DIR... --references FILE [--per-sample] [--baseline VARIANT]
//       Markdown table of the prepared samples (the preparations of each folder's runs.tsv, or
//       <sample>/<density>_prepare.h5), mean ± sd over seeds per density, variant and size (or
//       one row per sample), with the paper's values; --baseline adds the shift from that variant
//   figure-data tests-table SAMPLE_DIR
//       Markdown table of one sample's cyclic tests (<density>_test<N>.h5): steps, wall time,
//       worst tracking error, largest inertial number, εv and CN at the ends of cycle 1 and of
//       the last cycle (make cyclic-tests)
// Exit status: 0, 1 if something could not be read or written, 2 for bad arguments.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "figures.hpp"
#include "settings.hpp"
#include "format.hpp"
#include "markdown_table.hpp"
#include "quantities.hpp"
#include "results.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/state_io.hpp"
#include "io/failure.hpp"

namespace fs = std::filesystem;
using validation::Table;

namespace {

const std::vector<std::string> densities = {"loose", "medium", "dense"};

// A path as written into files: relative to the working folder, never absolute.
std::string shown(const std::string& p) {
  const fs::path rel = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  return rel.empty() ? fs::path(p).filename().string() : rel.string();
}

using validation::scene_of;
using validation::stage_of_type;
using validation::joined;

// ---------------------------------------------------------------------------------------------
// True if the results folder of a sub-command is a folder; else false, said on stderr (exit status 2).
bool results_folder_ok(const std::string& what, const std::string& dir) {
  const std::string bad = validation::folder_problem(dir);
  if (!bad.empty()) std::fprintf(stderr, "figure-data: %s '%s' %s\n", what.c_str(), dir.c_str(), bad.c_str());
  return bad.empty();
}

// True (with a message) when none of the samples has a single complete result.
bool no_results(const std::vector<validation::Sample>& samples, const std::string& results) {
  for (const validation::Sample& s : samples)
    for (const auto& [density, r] : s.densities)
      if (r.prepared || !r.tests.empty()) return false;
  std::fprintf(stderr, "figure-data: no complete result in %s (<density>_prepare.h5, <density>_test<N>.h5): nothing written\n",
               results.c_str());
  return true;
}

int figures(const std::string& results, const std::string& out, std::string sample, const std::string& references) {
  if (!results_folder_ok("RESULTS_DIR", results)) return 2;
  std::vector<std::string> missing;
  const std::vector<validation::Sample> samples = validation::load_samples(results, densities, missing);
  if (validation::report_unreadable("figure-data", missing) || no_results(samples, results)) return 1;
  if (sample.empty()) sample = samples.front().name;
  const std::string sample_label = sample.empty() ? fs::path(samples.front().dir).filename().string() : sample;
  const auto chosen = std::find_if(samples.begin(), samples.end(), [&](const validation::Sample& s) { return s.name == sample; });
  if (chosen == samples.end()) {
    std::fprintf(stderr, "figure-data: no sample '%s' in %s\n", sample.c_str(), results.c_str());
    return 2;
  }
  const std::vector<validation::Row> paper = validation::load_references(references, "paper");
  fs::create_directories(out);
  int files = 0;
  const auto write = [&](const std::string& name, const Table& t, const std::string& what) {
    Table copy = t;
    copy.comments.insert(copy.comments.begin(), what);
    dem::write_file_atomically((fs::path(out) / name).string(), copy.text());
    ++files;
  };
  const std::string from = shown(chosen->dir);
  validation::GnuplotValues values;
  values.text("sample", sample_label);
  values.number("samples_n", static_cast<double>(samples.size()));

  // The scenes of the chosen sample: preparations, and the first test's stress path (p, R).
  std::map<std::string, dem::SceneConfig> prepare;
  for (const std::string& d : densities)
    if (auto s = scene_of((fs::path(chosen->dir) / (d + "_prepare.h5")).string())) prepare[d] = *s;
  double p = 1e5, R = 1.24;
  bool path_found = false;
  for (const std::string& d : densities)
    for (int t = 1; t <= 5 && !path_found; ++t)
      if (auto s = scene_of((fs::path(chosen->dir) / (d + "_test" + std::to_string(t) + ".h5")).string()))
        if (const dem::StageConfig* st = stage_of_type(*s, dem::StageConfig::Type::StressPath)) {
          p = st->mean_stress_Pa, R = st->stress_ratio, path_found = true;
          values.number("friction_shear", dem::friction_coefficient(s->material.law));
        }
  values.number("mean_stress_kPa", p / 1e3);
  values.number("stress_ratio", R);
  for (const std::string& d : densities) {
    values.number("has_prepare_" + d, prepare.count(d) ? 1 : 0);
    values.number("friction_prepare_" + d, prepare.count(d) ? dem::friction_coefficient(prepare[d].material.law) : NAN);
    for (const auto& [quantity, name] : std::vector<std::pair<std::string, std::string>>{
             {"coordination_after_preparation", "cn"}, {"void_ratio_after_preparation", "e0"}, {"cell_side_cm_after_preparation", "side_cm"}})
      values.number("paper_" + name + "_" + d, validation::paper_value(paper, quantity, d).value_or(NAN));
  }
  values.number("paper_slope", validation::paper_value(paper, "qp_strong_fabric_slope", "").value_or(NAN));

  // Fig. 1 and 2: the grading and the samples (from /state of each preparation). Without a dense
  // preparation these stay at "none" (has_lattice = 0) and the scripts say "not run".
  values.number("has_lattice", 0);
  values.text("grading_basis", "?");
  for (const char* v : {"grading_d_min_mm", "grading_d50_mm", "grading_d_max_mm", "lattice_side_mm", "target_pressure_kPa"}) values.number(v, 1);
  values.number("particles", 0);
  {
    Table none;
    none.comments = {"no dense preparation"};
    write("fig01_grading_target.dat", none, "Fig. 1");
    write("fig01_grading_sample.dat", none, "Fig. 1");
    write("fig02_lattice.dat", none, "Fig. 2 (A)");
  }
  if (prepare.count("dense")) {
    write("fig01_grading_target.dat", validation::grading_target(prepare["dense"]), "Fig. 1: target grading (" + from + "/dense_prepare)");
    const dem::ParticleSource& g = prepare["dense"].particles;
    values.text("grading_basis", g.grading_basis == dem::GradingCurve::Basis::Mass ? "mass" : "count");
    values.number("grading_d_min_mm", 1e3 * g.grading_diameters_m.front());
    values.number("grading_d50_mm", 1e3 * validation::grading_diameter_at(g.grading_diameters_m, g.grading_percent_finer, 50));
    values.number("grading_d_max_mm", 1e3 * g.grading_diameters_m.back());
    // The lattice before compression: the preparation scene's own lattice (generate/), not a run.
    const dem::ParticleSource& src = prepare["dense"].particles;
    if (src.kind == dem::ParticleSource::Kind::Lattice) {
      dem::Particles lattice;
      dem::PeriodicCell cell;
      dem::make_lattice(src.lattice, dem::GradingCurve(src.grading_diameters_m, src.grading_percent_finer, src.grading_basis),
                        prepare["dense"].material.density_kg_per_m3, lattice, cell);
      write("fig02_lattice.dat", validation::spheres(lattice, cell), "Fig. 2 (A): the lattice of " + from + "/dense_prepare before compression");
      values.number("has_lattice", 1);
      values.number("lattice_side_mm", 1e3 * cell.lengths().maxCoeff());
      values.number("particles", static_cast<double>(lattice.size()));
      if (const dem::StageConfig* st = stage_of_type(prepare["dense"], dem::StageConfig::Type::Stress))
        values.number("target_pressure_kPa", st->target_Pa.mean() / 1e3);
    }
  }
  double side_mm = 0;
  for (const std::string& d : densities) {
    const std::string f = (fs::path(chosen->dir) / (d + "_prepare.h5")).string();
    Table t;
    try {
      if (!prepare.count(d)) throw std::runtime_error("not run");
      const dem::SavedState st = dem::read_state(f);
      t = validation::spheres(st.particles, st.cell);
      side_mm = std::max(side_mm, 1e3 * st.cell.lengths().maxCoeff());
      if (d == "dense") write("fig01_grading_sample.dat", validation::grading_realised(st.particles.radius), "Fig. 1: the grading of " + from + "/dense_prepare");
    } catch (const std::exception& e) {
      t.columns = {"x1 [mm]", "x2 [mm]", "x3 [mm]", "diameter [mm]"};
      t.comments = {std::string("no sample: ") + e.what()};
    }
    write("fig02_" + d + ".dat", t, "Fig. 2: the " + d + " sample after compression (" + from + "/" + d + "_prepare)");
  }
  values.number("sample_side_mm", side_mm > 0 ? std::ceil(side_mm / 5) * 5 : 1);

  // Figs. 3-6, 8, 9, 12, 13 from the chosen sample's tests.
  const auto find_test = [](const validation::DensityResults& r, int t) -> const validation::TestResult* {
    for (const validation::TestResult& x : r.tests)
      if (x.number == t) return &x;
    return nullptr;
  };
  // Fig. 9: one arrow scale per test across the densities (a panel row of the figure), so that
  // arrows of different lengths look different: the smallest of the densities' own scales (the one
  // that keeps the longest increment of any of them at about 0.12).
  std::map<int, double> fig09_scale;
  for (int t = 1; t <= 5; ++t)
    for (const std::string& d : densities)
      if (const validation::TestResult* test = find_test(chosen->densities.at(d), t)) {
        const int c2 = std::min(5, validation::last_cycle(test->series));
        const double sc = validation::arrow_scale(test->series, {1, c2});
        fig09_scale[t] = fig09_scale.count(t) ? std::min(fig09_scale[t], sc) : sc;
      }
  std::set<int> targets_done;
  std::vector<Table> fabric_tables, strong_tables;
  for (const std::string& d : densities) {
    const validation::DensityResults& r = chosen->densities.at(d);
    std::vector<std::string> present;
    for (int t = 1; t <= 5; ++t) {
      const std::string dt = d + "_test" + std::to_string(t);
      const validation::TestResult* test = find_test(r, t);
      values.number("has_" + dt, test ? 1 : 0);
      const std::string run = from + "/" + dt;
      if (!test) {
        // Empty files with their header, so that every script finds its files (the curve is absent).
        Table none;
        none.comments = {"not run"};
        for (const std::string& name : {"fig03_" + dt, "fig04_q_p_" + dt, "fig05_qp_epsd_" + dt, "fig06_epsv_" + dt,
                                       "fig12_fabric_" + dt, "fig13_strong_fabric_" + dt, "fig09_" + dt + "_cycle1",
                                       "fig09_" + dt + "_cycle5", "fig09_" + dt + "_cycle1_path", "fig09_" + dt + "_cycle5_path"})
          write(name + ".dat", none, run);
        if (t == 5) write("fig08_test5_" + d + ".dat", none, run), values.texts("fig08_titles_" + d, {});
        values.number("fig09_scale_" + dt, 1);
        values.number("fig09_cycle5_" + dt, 5);
        continue;
      }
      present.push_back(std::to_string(t));
      const validation::Columns& s = test->series;
      if (!targets_done.count(t)) {
        write("fig03_test" + std::to_string(t) + "_target.dat", validation::target_path(test->legs), "Fig. 3: target path of Test " + std::to_string(t) + " (" + run + ")");
        targets_done.insert(t);
      }
      write("fig03_" + dt + ".dat", validation::stress_path(s), "Fig. 3: " + run);
      write("fig04_q_p_" + dt + ".dat", validation::q_against_p(s), "Fig. 4: " + run);
      write("fig05_qp_epsd_" + dt + ".dat", validation::qp_against_deviatoric_strain(s, 5), "Fig. 5: " + run);
      write("fig06_epsv_" + dt + ".dat", validation::volumetric_strain_against(s, t, 5), "Fig. 6: " + run);
      fabric_tables.push_back(validation::qp_against_fabric(s, "fabric", 5));
      strong_tables.push_back(validation::qp_against_fabric(s, "strong_fabric", 5));
      write("fig12_fabric_" + dt + ".dat", fabric_tables.back(), "Fig. 12: " + run);
      write("fig13_strong_fabric_" + dt + ".dat", strong_tables.back(), "Fig. 13: " + run);
      if (t == 5) {
        std::vector<std::string> titles;
        write("fig08_test5_" + d + ".dat", validation::test5_blocks(s, test->legs, titles), "Fig. 8: " + run);
        values.texts("fig08_titles_" + d, titles);
      }
      // Fig. 9: cycles 1 and 5 (the last cycle run if fewer), one arrow scale for both.
      const int c2 = std::min(5, validation::last_cycle(s));
      const double scale = fig09_scale.at(t);
      values.number("fig09_scale_" + dt, scale);
      values.number("fig09_cycle5_" + dt, c2);
      for (const auto& [c, tag] : std::vector<std::pair<int, std::string>>{{1, "cycle1"}, {c2, "cycle5"}}) {
        write("fig09_" + dt + "_" + tag + ".dat", validation::strain_increments(s, c, scale), "Fig. 9: " + run);
        write("fig09_" + dt + "_" + tag + "_path.dat", validation::cycle_stress_path(s, c), "Fig. 9: " + run);
      }
    }
    values.number("has_" + d, present.empty() ? 0 : 1);
    values.text("fig14_tests_" + d, joined(present, ", "));
  }
  for (int t = 1; t <= 5; ++t)
    if (!targets_done.count(t)) {
      Table none;
      none.comments = {"not run"};
      write("fig03_test" + std::to_string(t) + "_target.dat", none, "Fig. 3: target path of Test " + std::to_string(t));
    }
  write("fig03_states.dat", validation::named_states(p, R), "Fig. 3: named states of the tests' stress paths");
  const Table q = validation::target_q(p, R);
  write("fig04_targets.dat", q, "Fig. 4: target deviator stress");
  values.number("q_tc_kPa", q.rows[0][0]);
  values.number("q_te_kPa", q.rows[1][0]);
  std::vector<const Table*> all_fabric, all_strong;
  for (const Table& t : fabric_tables) all_fabric.push_back(&t);
  for (const Table& t : strong_tables) all_strong.push_back(&t);
  values.number("fig12_max", validation::square_axis_max(all_fabric));
  values.number("fig13_max", validation::square_axis_max(all_strong));

  // Figs. 7, 10, 11: per-cycle statistics over every sample of the ensemble.
  const std::map<std::string, std::string> cycle_files = {
      {"epsv_percent", "fig07_epsv_cycles"}, {"coordination", "fig10_coordination"}, {"sliding_percent", "fig11_sliding"}};
  for (const validation::CycleQuantity& cq : validation::cycle_quantities())
    for (const std::string& d : densities)
      for (int t = 1; t <= 5; ++t) {
        std::vector<const validation::TestResult*> tests;
        for (const validation::Sample& s : samples)
          if (const validation::TestResult* x = find_test(s.densities.at(d), t)) tests.push_back(x);
        write(cycle_files.at(cq.name) + "_" + d + "_test" + std::to_string(t) + ".dat", validation::cycle_statistics(tests, cq),
              "Figs. 7, 10, 11: " + d + ", Test " + std::to_string(t) + ", " + std::to_string(tests.size()) + " sample(s) of " + shown(results));
      }

  // The energy balance of every run of the chosen sample (results of an engine without the energy
  // columns are noted and left out).
  for (const std::string& d : densities) {
    std::vector<std::pair<std::string, const validation::Columns*>> runs;
    validation::Columns prepare_series;
    const std::string f = (fs::path(chosen->dir) / (d + "_prepare.h5")).string();
    if (validation::is_complete(f)) {
      prepare_series = validation::read_columns(f, "timeseries");
      runs.emplace_back(d + "_prepare", &prepare_series);
    }
    for (const validation::TestResult& t : chosen->densities.at(d).tests) runs.emplace_back(d + "_test" + std::to_string(t.number), &t.series);
    for (const auto& [run, series] : runs) {
      try {
        write("fig_energy_" + run + ".dat", validation::energy_balance(*series), "energy balance of " + from + "/" + run);
      } catch (const std::out_of_range& e) {
        std::fprintf(stderr, "note: %s/%s: no energy balance (%s)\n", from.c_str(), run.c_str(), e.what());
      }
    }
  }

  dem::write_file_atomically((fs::path(out) / "values.gp").string(),
                             values.text_file("Written by figure-data from " + shown(results) + " (sample " + sample_label +
                                              ") and reference_data/paper.yaml: the numbers the scripts in reports/gnuplot/ read"));
  for (const std::string& m : missing) std::fprintf(stderr, "note: %s: missing or not complete, left out\n", shown(m).c_str());
  std::fprintf(stderr, "figure-data: %d files from %zu sample(s) of %s (single-run figures: %s) -> %s\n", files + 1,
               samples.size(), shown(results).c_str(), sample_label.c_str(), shown(out).c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
int settings(const std::string& results, const std::string& prefix, const std::string& run) {
  if (!results_folder_ok("RESULTS_DIR", results)) return 2;
  const std::map<std::string, std::string> kv = validation::run_settings(results, prefix, run);
  if (kv.empty()) {
    std::fprintf(stderr, "figure-data settings: no result with a scene in %s (%s<density>_prepare.h5 ...)\n",
                 validation::sample_dirs(results).front().second.c_str(), prefix.c_str());
    return 1;
  }
  for (const auto& [k, v] : kv) std::printf("%s\t%s\n", k.c_str(), v.c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
struct Preparation {
  std::string group, density, sample;  // group: the variant ("" without variants)
  std::map<std::string, double> last;   // last time-series row
  double wall_s = 0, particles = 0;
};

// A column of the group's preparations: one sample, the value with `digits` decimals ("0.558");
// several, mean ± sd with the digits from the scatter (the sd to two significant digits, the mean
// to the same decimal: "0.5581 ± 0.0047"; format.hpp).
std::string mean_sd(const std::vector<double>& v, int digits) {
  const validation::Spread s = validation::spread(v);
  if (s.n < 2 || !(s.sd > 0)) return validation::fixed(s.mean, digits);
  return validation::mean_pm_sd(s.mean, s.sd);
}

// A signed value with `digits` decimals ("+0.012").
std::string signed_fixed(double x, int digits) {
  if (!std::isfinite(x)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.*f", digits, x);
  return buf;
}

int samples_table(const std::vector<std::string>& folders, const std::string& references, bool per_sample, const std::string& baseline) {
  for (const std::string& results : folders)
    if (!results_folder_ok("RESULTS_DIR", results)) return 2;
  const std::vector<validation::Row> paper = validation::load_references(references, "paper");
  std::vector<Preparation> preps;
  std::vector<std::string> lost;
  const auto add = [&](const std::string& group, const std::string& density, const std::string& sample, const std::string& file) {
    try {
      if (!validation::is_complete(file)) {
        lost.push_back(file);  // missing (not run) or there but unreadable: report_unreadable tells
        return;
      }
      Preparation p{group, density, sample, {}, 0, 0};
      const validation::Columns c = validation::read_columns(file, "timeseries");
      for (const auto& [name, v] : c)
        if (!v.empty()) p.last[name] = v.back();
      dem::h5::Handle f = dem::h5::open_file_read(file);
      p.wall_s = dem::h5::get_double_attribute(f, "wall_time_s");
      if (dem::h5::exists(f, "particles/all/position/value")) p.particles = static_cast<double>(dem::h5::shape(f, "particles/all/position/value").at(1));
      preps.push_back(p);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "figure-data: %s: %s\n", shown(file).c_str(), e.what());
      lost.push_back(file);
    }
  };
  for (const std::string& results : folders) {
    std::ifstream runs(fs::path(results) / "runs.tsv");
    if (runs) {  // the pipeline's list: variant, density, test, run, result, starts_from, may_fail, settings, seed
      std::string line;
      while (std::getline(runs, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string x; std::getline(ss, x, '\t');) f.push_back(x);
        if (f.size() < 5 || f[2] != "-") continue;
        const std::string seed = f.size() > 8 && f[8] != "-" && !f[8].empty() ? "seed" + f[8] : "";
        add(f[0] == "-" ? "" : f[0], f[1], seed, (fs::path(results) / (f[3] + ".h5")).string());
      }
    } else {
      for (const auto& [name, dir] : validation::sample_dirs(results))
        for (const std::string& d : densities) add("", d, name, (fs::path(dir) / (d + "_prepare.h5")).string());
    }
  }
  if (validation::report_unreadable("figure-data", lost)) return 1;  // lost, not merely not run
  if (preps.empty()) {
    std::fprintf(stderr, "figure-data samples-table: no complete preparation in %s\n", joined(folders, ", ").c_str());
    return 1;
  }
  // Groups in the order met (by density first, as the paper's tables).
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Preparation*>> groups;
  for (const std::string& d : densities)
    for (const Preparation& p : preps) {
      if (p.density != d) continue;
      const std::string key = d + "\t" + p.group + "\t" + (per_sample ? p.sample : std::to_string(static_cast<long>(p.particles)));
      if (!groups.count(key)) order.push_back(key);
      groups[key].push_back(&p);
    }
  const auto values = [](const std::vector<const Preparation*>& g, const std::function<double(const Preparation&)>& f) {
    std::vector<double> v;
    for (const Preparation* p : g) v.push_back(f(*p));
    return v;
  };
  const auto mean = [](const std::vector<double>& v) { return validation::spread(v).mean; };
  const auto side = [](const Preparation& p) {  // cm, scaled to the paper's sample size
    const double v = p.last.at("cell_length_1") * p.last.at("cell_length_2") * p.last.at("cell_length_3");
    return 100 * std::cbrt(p.particles > 0 ? v * validation::paper_particles / p.particles : v);
  };
  const bool deltas = !baseline.empty();
  std::vector<std::string> headings = {"sample", "particles"};
  if (!per_sample) headings.push_back("seeds");
  const std::string side_heading =
      "cell side cm, " + validation::thousands(std::lround(validation::paper_particles)) + "-sphere equivalent (paper)";
  for (const std::string& h : {std::string("e0 (paper)"), std::string("Δe0"), side_heading, std::string("CN (paper)"), std::string("ΔCN")})
    headings.push_back(h);
  if (deltas) headings.push_back("Δe0 vs " + baseline), headings.push_back("ΔCN vs " + baseline);
  for (const char* h : {"CN w/o rattlers", "sliding %", "mean f_n (N)", "unbalanced", "steps", "wall time (s)"}) headings.push_back(h);
  validation::MarkdownTable table(headings);
  for (const std::string& key : order) {
    const auto& g = groups[key];
    const Preparation& first = *g.front();
    const std::string d = first.density;
    const double e_paper = validation::paper_value(paper, "void_ratio_after_preparation", d).value_or(NAN);
    const double z_paper = validation::paper_value(paper, "coordination_after_preparation", d).value_or(NAN);
    const double l_paper = validation::paper_value(paper, "cell_side_cm_after_preparation", d).value_or(NAN);
    const auto e = values(g, [](const Preparation& p) { return p.last.at("void_ratio"); });
    const auto z = values(g, [](const Preparation& p) { return p.last.at("coordination_number"); });
    std::string label = d;
    if (!first.group.empty()) label += ", " + first.group;
    if (per_sample && !first.sample.empty()) label += ", " + first.sample;
    std::vector<std::string> cells = {label, validation::fixed(first.particles, 0)};
    if (!per_sample) cells.push_back(std::to_string(g.size()));
    cells.push_back(mean_sd(e, 3) + " (" + validation::fixed(e_paper, 2) + ")");
    cells.push_back(signed_fixed(mean(e) - e_paper, 3));
    cells.push_back(mean_sd(values(g, side), 2) + " (" + validation::fixed(l_paper, 1) + ")");
    cells.push_back(mean_sd(z, 2) + " (" + validation::fixed(z_paper, 2) + ")");
    cells.push_back(signed_fixed(mean(z) - z_paper, 2));
    if (deltas) {
      const std::string base_key = d + "\t" + baseline + "\t" + key.substr(key.rfind('\t') + 1);
      if (groups.count(base_key)) {
        cells.push_back(signed_fixed(mean(e) - mean(values(groups[base_key], [](const Preparation& p) { return p.last.at("void_ratio"); })), 4));
        cells.push_back(signed_fixed(mean(z) - mean(values(groups[base_key], [](const Preparation& p) { return p.last.at("coordination_number"); })), 3));
      } else {
        cells.push_back(""), cells.push_back("");
      }
    }
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("coordination_number_mechanical"); }), 2));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return 100 * p.last.at("sliding_fraction"); }), 1));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("mean_normal_force"); }), 3));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("unbalanced_force_ratio"); }), 5));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("step"); }), 0));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.wall_s; }), 0));
    table.row(cells);
  }
  std::fputs(table.text().c_str(), stdout);
  return 0;
}

}  // namespace

int tests_table(const std::string& dir) {
  if (!results_folder_ok("SAMPLE_DIR", dir)) return 2;
  std::vector<std::string> lost;  // not complete: not run, or there but unreadable
  validation::MarkdownTable md({"density", "test", "steps", "wall time (s)", "worst leg RMS tracking error (% of p)",
                                "largest inertial number", "last cycle", "εv cycle 1 (%)", "εv last cycle (%)", "CN cycle 0",
                                "CN cycle 1", "CN last cycle"});
  for (const char* d : {"loose", "medium", "dense"})
    for (int t = 1; t <= 5; ++t) {
      const std::string file = (fs::path(dir) / (std::string(d) + "_test" + std::to_string(t) + ".h5")).string();
      if (!validation::is_complete(file)) {
        lost.push_back(file);
        md.row({d, std::to_string(t), "not run", "", "", "", "", "", "", "", "", ""});
        continue;
      }
      const validation::TestResult r = validation::load_test(file, "test" + std::to_string(t));
      dem::h5::Handle f = dem::h5::open_file_read(file);
      const validation::CyclicTestLine l = validation::cyclic_test_line(r.series, r.legs);
      md.row({d, std::to_string(t), l.steps, validation::fixed(dem::h5::get_double_attribute(f, "wall_time_s"), 0), l.tracking_percent,
              l.inertial_number, l.last_cycle, l.ev_cycle1, l.ev_last, l.cn_start, l.cn_cycle1, l.cn_last});
    }
  if (validation::report_unreadable("figure-data", lost)) return 1;  // never "not run" for a result that was lost
  std::fputs(md.text().c_str(), stdout);
  return 0;
}

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  CLI::App app{"figure-data: the data behind the report's figures and the numbers its text quotes, from a study's results, "
               "its resolved scenes and reference_data/paper.yaml"};
  app.name("figure-data");
  app.require_subcommand(1);
  std::string results, figs, sample, references = "reference_data/paper.yaml", prefix, run, table_references, baseline;
  std::vector<std::string> folders;
  bool per_sample = false;

  CLI::App* fig = app.add_subcommand("figures", "every figure's data files (figNN_*.dat, columns named with units) and values.gp, "
                                                "the numbers the static scripts in reports/gnuplot/ read");
  fig->add_option("RESULTS_DIR", results, "the study's results folder")->required();
  fig->add_option("FIG_DIR", figs, "where the data files go (made if missing)")->required();
  fig->add_option("--sample", sample, "the sample whose runs the single-run figures show (default: the first)");
  fig->add_option("--references", references, "the paper's values")->capture_default_str();

  CLI::App* set = app.add_subcommand("settings", "the settings the runs used, from the resolved scenes of the first sample's "
                                                 "P<density>_prepare.h5 and P<density>_test<N>.h5, or of NAME.h5 alone "
                                                 "(key<TAB>value on stdout)");
  set->add_option("RESULTS_DIR", results, "the study's results folder")->required();
  CLI::Option* prefix_opt = set->add_option("--prefix", prefix, "P: the runs' file name prefix");
  set->add_option("--run", run, "NAME: read NAME.h5 alone")->excludes(prefix_opt);

  CLI::App* table = app.add_subcommand("samples-table", "Markdown table of the prepared samples, mean ± sd over seeds per density, "
                                                        "variant and size (or one row per sample), with the paper's values, on stdout");
  table->add_option("RESULTS_DIR", folders, "the studies' results folders")->required();
  table->add_option("--references", table_references, "the paper's values")->required();
  table->add_flag("--per-sample", per_sample, "one row per sample");
  table->add_option("--baseline", baseline, "VARIANT: add the shift of each row from that variant");

  CLI::App* tests = app.add_subcommand("tests-table", "Markdown table of one sample's cyclic tests: steps, wall time, tracking "
                                                    "error, inertial number, εv and CN at cycle ends, on stdout");
  tests->add_option("SAMPLE_DIR", results, "the sample's folder (<density>_test<N>.h5)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
  }
  try {
    if (*fig) return figures(results, figs, sample, references);
    if (*set) return settings(results, prefix, run);
    if (*tests) return tests_table(results);
    return samples_table(folders, table_references, per_sample, baseline);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "figure-data: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
}

int main(int argc, char** argv) { return dem::guarded_main("figure-data", [&] { return tool_main(argc, argv); }); }
