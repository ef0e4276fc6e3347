// compare-runs: the tables of a study of variants, from the pipeline's manifest (DIR/runs.tsv).
//   compare-runs convergence RESULTS_DIR OUT_DIR [--reference NAME]
//       errors of every variant against the reference, with its wall time: OUT_DIR/errors.dat
//       (for the figure) and OUT_DIR/table.md (all variants, then the cheapest within 1, 5, 10 %)
//   compare-runs stability RESULTS_DIR OUT_DIR
//       what became of each case: OUT_DIR/table.md (case, outcome, steps, closure error, message)
//   compare-runs critical-state RESULTS_DIR OUT_DIR
//       peak and critical-state friction angle, void ratio and coordination number of each
//       constant-p shear, and the peaks in the pi-plane beside Mohr-Coulomb, Lade-Duncan and
//       Matsuoka-Nakai: OUT_DIR/table.md, critical_state.dat, pi_plane.dat, values.gp
//   compare-runs liquefaction OUT_DIR RESULTS_DIR...
//       CSR against N_L of the undrained cyclic tests of each folder and r_u against cycles of
//       every run, the holds beside them: OUT_DIR/table.md, csr_nl.dat, ru.dat, values.gp
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
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "io/atomic_file.hpp"
#include "compare.hpp"
#include "contact/contact_law.hpp"
#include "critical_state.hpp"
#include "decisions.hpp"
#include "figures.hpp"
#include "format.hpp"
#include "io/hdf5.hpp"
#include "liquefaction.hpp"
#include "manifest.hpp"
#include "results.hpp"

namespace fs = std::filesystem;

namespace {

using validation::cell;
using validation::fixed;
using validation::file_safe;
using validation::json_string;
using validation::number;

using validation::ManifestLine;
using validation::read_manifest;

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

// Paths under the working folder (the repository, when make runs it), or under the repository the
// study ran in (the folder above the results' `results/`), without that folder, so that committed
// tables do not carry the machine's absolute paths.
std::string relative_paths(std::string s, const std::string& results = "") {
  std::vector<std::string> roots = {fs::current_path().string() + "/"};
  std::error_code ec;  // the real folder: a results/ that is a link to another checkout's names that one
  const std::string abs = fs::weakly_canonical(fs::absolute(results), ec).string();
  if (const auto at = abs.rfind("/results/"); !results.empty() && at != std::string::npos) roots.push_back(abs.substr(0, at + 1));
  for (const std::string& root : roots)
    for (std::size_t at; (at = s.find(root)) != std::string::npos;) s.erase(at, root.size());
  return s;
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

std::string signed_fixed(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.2f", x);
  return buf;
}

// The decisions study (SPEC section 7): every validation row on every reading's ensemble, the
// shift of the mean in baseline standard deviations, a tornado chart per group of rows, and the
// reading that explains each inconsistent row. Writes table.md, decisions.json and, per group,
// tornado_<group>.dat and tornado_values.gp (reports/gnuplot/tornado.gp draws tornado_<group>.png).
int decisions(const std::vector<ManifestLine>& manifest, const std::vector<std::string>& order, const std::string& references,
              const std::string& baseline, const std::string& ensemble, const std::string& out) {
  std::vector<validation::Row> rows;
  try {
    rows = validation::load_references(references, "paper");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  // reading -> seed -> density -> (preparation, test number -> result)
  struct Files {
    std::string preparation;
    std::map<int, std::string> tests;
  };
  std::map<std::string, std::map<std::string, std::map<std::string, Files>>> files;
  std::map<std::string, std::string> settings;
  for (const ManifestLine& l : manifest) {
    Files& f = files[l.variant][l.seed][l.density];
    settings[l.variant] = l.settings;
    if (l.test == "-") f.preparation = l.result;
    else if (l.test.rfind("test", 0) == 0) f.tests[std::atoi(l.test.c_str() + 4)] = l.result;
  }
  std::map<std::string, validation::ReadingResults> readings;
  std::vector<std::string> missing;
  for (const auto& [reading, seeds] : files)
    for (const auto& [seed, densities] : seeds) {
      std::map<std::string, validation::DensityResults> of_seed;
      for (const auto& [density, f] : densities) of_seed[density] = validation::load_density(f.preparation, f.tests, missing);
      readings[reading].push_back({"seed" + seed, "", std::move(of_seed)});
    }
  // The paper study's ensemble (full size), if given: the verdicts and causes are judged on it.
  std::vector<validation::Sample> full_samples;
  std::map<std::string, validation::RowResult> full;
  if (!ensemble.empty()) {
    std::vector<std::string> missing_ensemble;
    full_samples = validation::load_samples(ensemble, {"loose", "medium", "dense"}, missing_ensemble);
    for (const validation::Row& r : rows) full[r.name] = validation::evaluate(r, full_samples);
  }
  std::vector<validation::RowDecision> decided;
  try {
    decided = validation::decide(rows, readings, order, baseline, full);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare-runs: %s\n", e.what());
    return 1;
  }
  std::vector<std::string> others;
  for (const std::string& r : order)
    if (r != baseline) others.push_back(r);
  std::vector<std::string> groups;
  for (const validation::Row& r : rows)
    if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);
  const auto verdict_mark = [](validation::Verdict v) {
    return v == validation::Verdict::Consistent ? "✅" : v == validation::Verdict::Inconsistent ? "❌" : "—";
  };
  std::ostringstream md;
  md << "Readings (each one change from the baseline, `pipeline/studies/decisions.yaml`):\n\n| reading | settings |\n|---|---|\n";
  for (const std::string& r : order) md << "| " << cell(r) << " | " << cell(settings[r]) << " |\n";
  md << "\nEach cell: the shift of the ensemble mean from the baseline's, in baseline standard deviations, and the verdict "
        "under that reading (✅ consistent, ❌ inconsistent, — not judged)"
     << (full.empty() ? std::string(".\n")
                      : std::string(" of the paper study's full-size ensemble with that shift of the mean applied to each of its "
                                    "samples; the baseline column gives this study's mean ± sd and the full-size ensemble's verdict.\n"));
  validation::GnuplotValues gp_values;  // tornado_values.gp, read by reports/gnuplot/tornado.gp
  gp_values.texts("tornado_reading", others);
  std::string group_names;
  for (const std::string& g : groups) {
    md << "\n### " << g << "\n\n![tornado chart: " << g << "](tornado_" << file_safe(g) << ".png)\n\n| row | baseline: mean ± sd | ";
    for (const std::string& r : others) md << cell(r) << " | ";
    md << "explanation |\n|---|---|";
    for (std::size_t k = 0; k < others.size(); ++k) md << "---|";
    md << "---|\n";
    // Tornado data: rows of the group, largest shift first.
    std::vector<const validation::RowDecision*> of_group;
    for (const validation::RowDecision& d : decided)
      if (d.row.group == g) of_group.push_back(&d);
    const auto largest = [](const validation::RowDecision* d) {
      double m = 0;
      for (const auto& e : d->readings)
        if (e.shift_sd && std::isfinite(*e.shift_sd)) m = std::max(m, std::abs(*e.shift_sd));
      return m;
    };
    std::stable_sort(of_group.begin(), of_group.end(), [&](auto* a, auto* b) { return largest(a) < largest(b); });
    std::ofstream dat(fs::path(out) / ("tornado_" + file_safe(g) + ".dat"));
    dat << "# row_index\treading_index\tshift_sd\trow\treading\n";
    for (std::size_t i = 0; i < of_group.size(); ++i)
      for (std::size_t k = 0; k < of_group[i]->readings.size(); ++k) {
        const auto& e = of_group[i]->readings[k];
        if (e.shift_sd && std::isfinite(*e.shift_sd))
          dat << i << '\t' << k << '\t' << *e.shift_sd << "\t\"" << of_group[i]->row.name << "\"\t" << e.reading << "\n";
      }
    // What the static script (reports/gnuplot/tornado.gp) needs of this group: its title, the row
    // names as labels (not tic labels: a tic label is a format, whose '%' would need doubling, and
    // gnuplot cut long ones short), the left margin they take and the chart's height.
    std::size_t longest = 0;
    const std::string key = "tornado_" + file_safe(g);
    gp_values.text(key + "_title", g);
    std::vector<std::string> labels;
    for (const validation::RowDecision* d : of_group) {
      std::string label = d->row.name;
      for (char& c : label)
        if (c == '"') c = '\'';
      longest = std::max(longest, label.size());
      labels.push_back(label);
    }
    gp_values.texts(key + "_row", labels);
    gp_values.number(key + "_lmargin", static_cast<double>(longest * 9 / 10 + 2));
    gp_values.number(key + "_height", static_cast<double>(220 + 34 * of_group.size() * std::max<std::size_t>(1, others.size() / 3)));
    group_names += (group_names.empty() ? "" : " ") + file_safe(g);
    for (auto it = of_group.rbegin(); it != of_group.rend(); ++it) {
      const validation::RowDecision& d = **it;
      md << "| " << cell(d.row.name) << " | "
         << (d.baseline.valued ? (d.baseline.valued > 1 ? validation::mean_pm_sd(d.baseline.spread.mean, d.baseline.spread.sd) : number(d.baseline.spread.mean)) : "—")
         << " " << verdict_mark(d.full ? d.full->verdict : d.baseline.verdict) << " | ";
      for (const auto& e : d.readings)
        md << (e.shift_sd && std::isfinite(*e.shift_sd) ? validation::shift_text(*e.shift_sd) : "—") << " "
           << verdict_mark(d.full ? (e.full ? e.full->verdict : validation::Verdict::NotJudged) : e.result.verdict) << " | ";
      md << cell(d.explanation) << " |\n";
    }
  }
  gp_values.text("tornado_groups", group_names);
  dem::write_file_atomically((fs::path(out) / "tornado_values.gp").string(),
                             gp_values.text_file("Written by compare-runs decisions: what reports/gnuplot/tornado.gp draws, one chart "
                                                 "per group from tornado_<group>.dat"));
  // The size check: the baseline of this study against the paper study's ensemble (its own
  // sample size), row by row, in units of the paper ensemble's standard deviation.
  if (!ensemble.empty()) {
    const auto& samples = full_samples;
    md << "\n### Size check: this study's baseline against the paper study's ensemble\n\n"
       << "The same rows on the paper study's samples (" << samples.size() << " per density, its size) and on this study's "
       << "baseline; the difference of the means in units of the paper ensemble's standard deviation, and both verdicts. "
       << "A reading's shift is trusted at this study's size where the two agree.\n\n"
       << "| row | paper study: mean ± sd | this study's baseline: mean ± sd | difference / sd | verdicts |\n|---|---|---|---|---|\n";
    for (const validation::RowDecision& d : decided) {
      const validation::RowResult& big = *d.full;
      const auto ms = [](const validation::RowResult& r) {
        return r.valued ? (r.valued > 1 ? validation::mean_pm_sd(r.spread.mean, r.spread.sd) : number(r.spread.mean)) : std::string("—");
      };
      std::string diff = "—";
      if (big.valued > 1 && std::max(big.spread.sd, d.row.resolution) > 0 && d.baseline.valued > 0)
        diff = validation::shift_text(validation::shift_in_sd(d.baseline.spread.mean - big.spread.mean, big.spread.sd, d.row.resolution));
      md << "| " << cell(d.row.name) << " | " << ms(big) << " | " << ms(d.baseline) << " | " << diff << " | "
         << verdict_mark(big.verdict) << " / " << verdict_mark(d.baseline.verdict) << " |\n";
    }
  }
  std::ostringstream json;
  json << "{\n  \"baseline\": \"" << baseline << "\",\n  \"rows\": [\n";
  for (std::size_t i = 0; i < decided.size(); ++i) {
    const validation::RowDecision& d = decided[i];
    json << "    {\"name\": " << json_string(d.row.name) << ", \"group\": " << json_string(d.row.group) << ", \"baseline_mean\": "
         << (d.baseline.valued ? number(d.baseline.spread.mean) : "null") << ", \"baseline_sd\": "
         << (d.baseline.valued > 1 ? number(d.baseline.spread.sd) : "null") << ", \"baseline_verdict\": \""
         << validation::to_string(d.baseline.verdict) << "\", \"readings\": {";
    for (std::size_t k = 0; k < d.readings.size(); ++k) {
      const auto& e = d.readings[k];
      json << (k ? ", " : "") << "\"" << e.reading << "\": {\"mean\": " << (e.result.valued ? number(e.result.spread.mean) : "null")
           << ", \"shift_sd\": " << (e.shift_sd && std::isfinite(*e.shift_sd) ? number(*e.shift_sd) : "null") << ", \"verdict\": \""
           << validation::to_string(e.result.verdict) << "\"}";
    }
    json << "}, \"explanation\": " << json_string(d.explanation) << "}" << (i + 1 < decided.size() ? "," : "") << "\n";
  }
  json << "  ],\n  \"missing_results\": " << missing.size() << "\n}\n";
  try {
    dem::write_file_atomically((fs::path(out) / "table.md").string(), md.str());
    dem::write_file_atomically((fs::path(out) / "decisions.json").string(), json.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("decisions: %zu readings, %zu rows, %zu result files missing -> %s\n", order.size(), rows.size(), missing.size(),
              (fs::path(out) / "table.md").c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
// The critical-state and liquefaction sections: each run's time series, resolved scene and the
// stage_end_<stage> attributes that say why each stage ended.

struct RunFile {
  validation::Columns series;
  std::optional<dem::SceneConfig> scene;
  std::map<std::string, std::string> stage_end;  // stage name -> stage_end_<name>
};

// A complete result; throws naming the file if it cannot be read.
RunFile read_run(const std::string& result) {
  RunFile f;
  f.series = validation::read_columns(result, "timeseries");
  dem::h5::Handle h = dem::h5::open_file_read(result);
  if (dem::h5::has_text(h, "scene_yaml")) {  // a dataset (schema 3) or an attribute (before)
    f.scene = dem::scene_from_text(dem::h5::read_text(h, "scene_yaml"), result);
    for (const dem::StageConfig& st : f.scene->stages)
      if (dem::h5::has_attribute(h, "stage_end_" + st.name)) f.stage_end[st.name] = dem::h5::get_string_attribute(h, "stage_end_" + st.name);
  }
  return f;
}

// A number that is the whole of `s` ("0.25"), or none.
std::optional<double> whole_number(const std::string& s) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
  return x;
}

// "mean ± sd" of a spread; "—" without rows.
std::string mean_sd(const validation::Spread& s, int digits) {
  return s.n == 0 ? "—" : fixed(s.mean, digits) + (s.n > 1 ? " ± " + fixed(s.sd, digits) : "");
}

// One run of the critical-state study, as its name says: compression_mu<μ>, extension_mu<μ>, b<b>.
struct ShearRun {
  std::string run, loading;  // loading: compression, extension or "b series" (true triaxial)
  double mu = NAN, b = NAN;  // μ; b the target of the constraint (principal b: 1 in extension)
  double p_target_Pa = NAN;  // the constraint's mean stress
  std::optional<validation::ShearSummary> summary;
  bool held = true;          // p and b as the name says (see held_as_named)
  std::string note;          // why it has no values, or what to know of them
};

// Whether a shear was the test its name says: p at the peak and at the critical state within 5 %
// of the constraint's, b at the critical state within 0.05 of the target. The consolidation holds
// the stresses within 0.5 %; the constant-p servo, a proportional one, holds p within a few % at
// the critical state (its followers move at a steady rate only on an error), but it can lose p
// altogether when they reach their strain-rate cap (a cap of 1/s: p up to 68 MPa at b = 1). A run
// outside these bounds is kept in the table with its values, and a note that says why they are
// not those of its test. Appends the reasons to r.note.
void held_as_named(ShearRun& r) {
  const validation::ShearSummary& s = *r.summary;
  const auto off = [&](double p) { return std::abs(p / r.p_target_Pa - 1) > 0.05; };
  if (std::isfinite(r.p_target_Pa) && (off(s.peak_p_Pa) || (s.p_Pa.n && off(s.p_Pa.mean)))) {
    r.held = false;
    r.note += "⚠ p not held at " + number(r.p_target_Pa / 1e3) + " kPa: " + fixed(s.peak_p_Pa / 1e3, 1) + " kPa at the peak, " +
              fixed(s.p_Pa.mean / 1e3, 1) + " at the critical state, " + fixed(s.p_min_Pa / 1e3, 1) + " – " + fixed(s.p_max_Pa / 1e3, 1) +
              " over the shear; ";
  }
  if (s.b.n && std::abs(s.b.mean - r.b) > 0.05) {
    r.held = false;
    r.note += "⚠ b not held: " + fixed(s.b.mean, 3) + " at the critical state for " + number(r.b) + "; ";
  }
}

bool parse_shear_test(const std::string& test, ShearRun& r) {
  for (const char* loading : {"compression", "extension"}) {
    const std::string prefix = std::string(loading) + "_mu";
    if (test.rfind(prefix, 0) == 0)
      if (const auto mu = whole_number(test.substr(prefix.size()))) {
        r.loading = loading, r.mu = *mu, r.b = r.loading == "compression" ? 0 : 1;
        return true;
      }
  }
  if (test.rfind("b", 0) == 0)
    if (const auto b = whole_number(test.substr(1))) {
      r.loading = "b series", r.b = *b;
      return true;
    }
  return false;
}

// The critical-state analysis of the runs of a study's manifest; cs_to the axial strain the
// critical state is averaged up to (a run that stops short of it is noted).
std::vector<ShearRun> shear_runs(const std::vector<ManifestLine>& manifest, double cs_to) {
  std::vector<ShearRun> runs;
  for (const ManifestLine& l : manifest) {
    if (l.test == "-") continue;  // the preparation
    ShearRun& r = runs.emplace_back();
    r.run = l.run;
    if (!parse_shear_test(l.test, r)) {
      r.note = "not analysed: test '" + l.test + "' is none of compression_mu<μ>, extension_mu<μ>, b<b>";
      continue;
    }
    if (!validation::is_complete(l.result)) {
      r.note = "missing: " + fs::path(l.result).filename().string() + " is not finished";
      continue;
    }
    try {
      const RunFile f = read_run(l.result);
      r.summary = validation::summarise_shear(f.series, 0.3, cs_to);
      if (f.scene) {  // μ, p and b as run: the scene's; a name that says otherwise is noted
        const double mu = dem::friction_coefficient(f.scene->material.law);
        if (std::isfinite(r.mu) && std::abs(mu - r.mu) > 1e-9) r.note += "the scene's friction is " + number(mu) + ", not the name's; ";
        r.mu = mu;
        const dem::CellConstraint& c = f.scene->stages.back().control.constraint;
        if (c.kind == dem::CellConstraint::Kind::ConstantMeanStress) r.p_target_Pa = c.mean_stress_Pa;
        if (r.loading == "b series" && c.b != r.b) r.note += "the scene's b is " + number(c.b) + ", not the name's; ";
      }
      held_as_named(r);
      if (r.summary->max_axial_strain < cs_to) {
        const std::string why = f.scene && f.stage_end.count(f.scene->stages.back().name) ? f.stage_end.at(f.scene->stages.back().name) : "no stage_end";
        r.note += "reached |ε3| = " + fixed(r.summary->max_axial_strain, 3) + " only (" + why + "); critical state over " +
                  std::to_string(r.summary->cs_rows) + " rows; ";
      }
    } catch (const std::exception& e) {
      r.summary.reset();
      r.note = "unreadable: " + std::string(e.what());
    }
  }
  return runs;
}

// The run the pi-plane's surfaces go through: the b series' b = 0 (its μ), else the compression
// run of the b series' μ (the study's b0 is a copy of compression_mu0.5).
const ShearRun* compression_peak(const std::vector<ShearRun>& runs) {
  double mu = NAN;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" && std::isfinite(r.mu)) mu = r.mu;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" && r.b == 0 && r.summary) return &r;
  for (const ShearRun& r : runs)
    if (r.loading == "compression" && r.summary && r.mu == mu) return &r;
  return nullptr;
}

// The pi-plane runs: the b series and the extension run at the b series' μ.
std::vector<const ShearRun*> pi_plane_runs(const std::vector<ShearRun>& runs, const ShearRun* through) {
  std::vector<const ShearRun*> out;
  for (const ShearRun& r : runs)
    if (r.loading == "b series" || (through && r.loading == "extension" && r.mu == through->mu)) out.push_back(&r);
  return out;
}

constexpr validation::Criterion criteria[] = {validation::Criterion::MohrCoulomb, validation::Criterion::LadeDuncan,
                                               validation::Criterion::MatsuokaNakai};

validation::Table critical_state_data(const std::vector<ShearRun>& runs) {
  validation::Table t;
  t.comments = {"compare-runs critical-state: one row per finished run; loading 1 compression, 2 extension, 3 true triaxial (b series);",
                "the critical state is the mean (and row-to-row sd) over the rows with 0.3 <= |axial strain| <= 0.4 (NaN without such rows)"};
  t.columns = {"mu [1]", "loading [1]", "b_target [1]", "peak_phi [deg]", "peak_phi_single_row [deg]", "peak_axial_strain [1]",
               "phi_cs [deg]", "phi_cs_sd [deg]", "e_cs [1]", "e_cs_sd [1]", "cn_cs [1]", "cn_cs_sd [1]", "cn_mechanical_cs [1]",
               "cn_mechanical_cs_sd [1]", "q_over_p_cs [1]", "q_over_p_cs_sd [1]", "b_at_peak [1]", "max_axial_strain [1]", "cs_rows [1]",
               "peak_radius_over_p [1]", "peak_lode [deg]", "p_at_peak [kPa]", "p_cs [kPa]", "b_cs [1]", "p_min [kPa]", "p_max [kPa]",
               "held_as_named [1]"};
  const auto mean = [](const validation::Spread& s) { return s.n ? s.mean : NAN; };
  const auto sd = [](const validation::Spread& s) { return s.n > 1 ? s.sd : NAN; };
  for (const ShearRun& r : runs) {
    if (!r.summary) continue;
    const validation::ShearSummary& s = *r.summary;
    const double loading = r.loading == "compression" ? 1 : r.loading == "extension" ? 2 : 3;
    t.labels.push_back(r.run);
    t.rows.push_back({r.mu, loading, r.b, s.peak_phi_deg, s.peak_phi_raw_deg, s.peak_axial_strain, mean(s.phi_deg), sd(s.phi_deg),
                      mean(s.void_ratio), sd(s.void_ratio), mean(s.coordination), sd(s.coordination), mean(s.coordination_mechanical),
                      sd(s.coordination_mechanical), mean(s.q_over_p), sd(s.q_over_p), s.peak_b, s.max_axial_strain,
                      static_cast<double>(s.cs_rows), s.peak_pi.radius, s.peak_pi.lode_deg, s.peak_p_Pa / 1e3, mean(s.p_Pa) / 1e3, mean(s.b),
                      s.p_min_Pa / 1e3, s.p_max_Pa / 1e3, r.held ? 1.0 : 0.0});
  }
  return t;
}

// pi_plane.dat: the measured peaks (set 0: b series, set 1: extension) and the three criteria
// through the compression peak over every angle (sets 2-4), one block each.
validation::Table pi_plane_data(const std::vector<ShearRun>& runs, const ShearRun* through) {
  validation::Table t;
  t.comments = {"compare-runs critical-state: the pi-plane normalised by p (s1 up, s2 lower left, s3 lower right; lode 0 = compression,",
                "60 = extension); set 0 the b series' peaks, 1 the extension peak at the same mu, 2 Mohr-Coulomb, 3 Lade-Duncan,",
                "4 Matsuoka-Nakai through the compression peak (" + (through ? through->run : std::string("none: not finished")) + ");",
                "held_as_named 0: the run did not hold its p or b (table.md)"};
  t.columns = {"set [1]", "x [1]", "y [1]", "radius [1]", "lode [deg]", "b [1]", "held_as_named [1]"};
  for (const ShearRun* r : pi_plane_runs(runs, through)) {
    if (!r->summary) continue;
    const validation::PiPoint& q = r->summary->peak_pi;
    t.labels.push_back(r->run);
    t.rows.push_back({r->loading == "extension" ? 1.0 : 0.0, q.x, q.y, q.radius, q.lode_deg, r->summary->peak_b, r->held ? 1.0 : 0.0});
  }
  if (!through) return t;
  const dem::Vec3& s = through->summary->peak_principal_Pa;
  const double p = s.sum() / 3;
  for (std::size_t k = 0; k < std::size(criteria); ++k) {
    t.block_starts.push_back(t.rows.size());
    for (int deg = 0; deg <= 360; ++deg) {  // every degree: the hexagon's corners (every 60) are met exactly
      const double lode = deg * std::numbers::pi / 180, radius = validation::criterion_radius(criteria[k], s, lode) / p;
      t.labels.push_back(validation::to_string(criteria[k]));
      t.rows.push_back({static_cast<double>(k + 2), -radius * std::sin(lode), radius * std::cos(lode), radius, static_cast<double>(deg), NAN, 1});
    }
  }
  return t;
}

std::string critical_state_table(const std::vector<ShearRun>& runs, const ShearRun* through, const std::string& settings) {
  std::ostringstream md;
  md << settings << "\n\n"
     << "| run | μ | loading | peak φ (°) | at axial strain | p at peak (kPa) | b at peak | critical φ (°) | e_cs | CN_cs (2Nc/Np) | "
        "CN_cs mechanical | q/p at cs | p at cs (kPa) | b at cs | note |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ShearRun& r : runs) {
    md << "| " << cell(r.run) << " | " << fixed(r.mu, 2) << " | " << cell(r.loading) << (r.loading == "b series" ? " b = " + number(r.b) : "") << " | ";
    if (!r.summary) {
      md << "— | — | — | — | — | — | — | — | — | — | — | " << cell(r.note) << " |\n";
      continue;
    }
    const validation::ShearSummary& s = *r.summary;
    std::string note = r.note;
    if (note.size() >= 2 && note.substr(note.size() - 2) == "; ") note.resize(note.size() - 2);
    md << fixed(s.peak_phi_deg, 2) << " | " << fixed(s.peak_axial_strain, 3) << " | " << fixed(s.peak_p_Pa / 1e3, 1) << " | " << fixed(s.peak_b, 3)
       << " | " << mean_sd(s.phi_deg, 2) << " | " << mean_sd(s.void_ratio, 4) << " | " << mean_sd(s.coordination, 3) << " | "
       << mean_sd(s.coordination_mechanical, 3) << " | " << mean_sd(s.q_over_p, 3) << " | " << fixed(s.p_Pa.n ? s.p_Pa.mean / 1e3 : NAN, 1)
       << " | " << mean_sd(s.b, 3) << " | " << cell(note) << " |\n";
  }
  double worst_p = 0;  // the largest offset of p at the critical state from the constraint's, over the runs
  for (const ShearRun& r : runs)
    if (r.summary && r.summary->p_Pa.n && std::isfinite(r.p_target_Pa))
      worst_p = std::max(worst_p, std::abs(r.summary->p_Pa.mean / r.p_target_Pa - 1));
  md << "\nPeak φ: the largest mobilised friction angle, sin φ = (σ1 − σ3)/(σ1 + σ3) of the principal stresses of the full tensor, "
        "after a centred mean of the principal stresses over 1 % of axial strain (the largest single row is in `critical_state.dat`). "
        "Critical state: mean ± sd over the rows with 0.3 ≤ |ε3| ≤ 0.4; the sd is the row-to-row scatter, not the error of the mean "
        "(the rows are correlated). CN mechanical = (2Nc − N1)/(Np − N0 − N1) (Thornton 2000) leaves out the rattlers, which carry no "
        "load and whose share changes with μ; it is the coordination of the network that carries the stress. ⚠: p at the peak or "
        "at the critical state more than 5 % from the constraint's, or b at the critical state more than 0.05 from the target: the "
        "run is not the test its name says (p at the critical state is at most " << fixed(100 * worst_p, 1)
     << " % from the constraint's in this study); its values are shown, but they are not that test's.\n";
  md << "\n![peak and critical-state friction angle against μ](phi_mu.png)\n\n![critical-state void ratio and coordination number against μ](e_cn_mu.png)\n";
  md << "\n### The peaks in the π-plane\n\n";
  if (!through) {
    md << "No compression peak at the b series' μ yet (its b = 0 run is not finished): no surfaces drawn.\n";
    return md.str();
  }
  md << "The b series and the extension run at μ = " << number(through->mu) << "; the three criteria go through the compression peak ("
     << cell(through->run) << ", φ = " << fixed(through->summary->peak_phi_deg, 2) << "°). Each criterion's φ at the b measured at a "
     << "peak (at the same p), and Δ = measured − predicted:\n\n"
     << "| run | b at peak | Lode angle (°) | ρ/p | measured peak φ (°) | Mohr–Coulomb φ (Δ) | Lade–Duncan φ (Δ) | Matsuoka–Nakai φ (Δ) | note |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const ShearRun* r : pi_plane_runs(runs, through)) {
    md << "| " << cell(r->run) << " | ";
    if (!r->summary) {
      md << "— | — | — | — | — | — | — | " << cell(r->note) << " |\n";
      continue;
    }
    const validation::ShearSummary& s = *r->summary;
    md << fixed(s.peak_b, 3) << " | " << fixed(s.peak_pi.lode_deg, 1) << " | " << fixed(s.peak_pi.radius, 3) << " | " << fixed(s.peak_phi_deg, 2);
    for (validation::Criterion c : criteria) {
      const double predicted = std::isfinite(s.peak_b) ? validation::predicted_friction_deg(c, through->summary->peak_principal_Pa, s.peak_b) : NAN;
      md << " | " << fixed(predicted, 2) << " (" << (std::isfinite(predicted) ? signed_fixed(s.peak_phi_deg - predicted) : "—") << ")";
    }
    md << " | " << (r->held ? "" : "⚠ not the test its name says (see above)") << " |\n";
  }
  md << "\n![the peaks in the π-plane beside the failure criteria](pi_plane.png)\n";
  return md.str();
}

// compare-runs critical-state: table.md, critical_state.dat, pi_plane.dat and values.gp (what
// reports/gnuplot/critical_state_*.gp need).
int critical_state(const std::vector<ManifestLine>& manifest, const std::string& results, const std::string& out) {
  constexpr double cs_to = 0.4;
  const std::vector<ShearRun> runs = shear_runs(manifest, cs_to);
  const ShearRun* through = compression_peak(runs);
  std::size_t finished = 0;
  for (const ShearRun& r : runs) finished += r.summary.has_value();
  // The settings the table quotes, from a finished run's resolved scene.
  std::string settings = "Drained shear at constant p of the dense sample (`scenes/tests/constant_p_shear.yaml`).";
  for (const ManifestLine& l : manifest)
    if (l.test != "-" && validation::is_complete(l.result)) {
      const RunFile f = read_run(l.result);
      if (!f.scene) continue;
      const dem::StageConfig& st = f.scene->stages.back();
      settings = "Drained shear of the dense sample at constant p = " + number(st.control.constraint.mean_stress_Pa / 1e3) +
                 " kPa (`scenes/tests/constant_p_shear.yaml`), axial strain rate " + number(std::abs(st.control.component[2].strain_rate_per_s)) +
                 " s⁻¹ to |ε3| = " + number(st.until.strain) + ", shear stresses held at zero; " + std::to_string(finished) + " of " +
                 std::to_string(runs.size()) + " runs finished.";
      break;
    }
  validation::GnuplotValues values;
  values.number("has_compression_peak", through ? 1 : 0);
  double largest = 0.1;  // the pi-plane's half-width: the largest radius drawn, with a margin
  const validation::Table pi = pi_plane_data(runs, through);
  for (std::size_t i = 0; i < pi.size(); ++i) largest = std::max(largest, pi.rows[i][3]);
  values.number("pi_r", std::ceil(11 * largest) / 10);
  values.number("runs_finished", static_cast<double>(finished));
  values.number("runs_total", static_cast<double>(runs.size()));
  try {
    fs::create_directories(out);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), critical_state_table(runs, through, settings));
    dem::write_file_atomically((fs::path(out) / "critical_state.dat").string(), critical_state_data(runs).text());
    dem::write_file_atomically((fs::path(out) / "pi_plane.dat").string(), pi.text());
    dem::write_file_atomically((fs::path(out) / "values.gp").string(),
                               values.text_file("Written by compare-runs critical-state from " + relative_paths(results, results)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  for (const ShearRun& r : runs)
    if (!r.summary) std::fprintf(stderr, "note: %s: %s\n", r.run.c_str(), r.note.c_str());
  std::printf("critical-state: %zu of %zu runs finished -> %s\n", finished, runs.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}

// One run of a liquefaction study: <density>_csr<CSR> (cyclic) or <density>_hold.
struct CyclicRun {
  std::string run, density;
  bool hold = false;
  double csr_name = NAN;      // from the name
  std::string note;           // why it has no values, or what to know of them
  bool finished = false;
  int stage = -1;             // index of its control stage
  double period_s = NAN;      // of the cyclic loading (a hold: of its density's cyclic runs)
  double amplitude_Pa = NAN;
  double ru_limit = NAN, strain_limit = NAN;  // the scene's until.pore_pressure_ratio, until.double_amplitude_strain
  std::string stage_end;      // its stage_end_<stage> attribute
  validation::ControlStage control;
  validation::Columns series;
};

// The control stage of a scene: the first stage of type control (-1 if none).
int control_stage(const dem::SceneConfig& scene) {
  for (std::size_t k = 0; k < scene.stages.size(); ++k)
    if (scene.stages[k].type == dem::StageConfig::Type::Control) return static_cast<int>(k);
  return -1;
}

// The runs of one liquefaction study folder (its manifest), read and summarised.
std::vector<CyclicRun> cyclic_runs(const std::string& results) {
  std::vector<CyclicRun> runs;
  for (const ManifestLine& l : read_manifest(results)) {
    if (l.test == "-") continue;  // the preparation
    CyclicRun& r = runs.emplace_back();
    r.run = l.run, r.density = l.density, r.hold = l.test == "hold";
    if (!r.hold) {
      const auto csr = validation::csr_from_name(l.run);
      if (!csr) {
        r.note = "not analysed: test '" + l.test + "' is neither hold nor csr<CSR>";
        continue;
      }
      r.csr_name = *csr;
    }
    if (!validation::is_complete(l.result)) {
      r.note = "missing: " + fs::path(l.result).filename().string() + " is not finished";
      continue;
    }
    try {
      RunFile f = read_run(l.result);
      if (!f.scene) throw std::runtime_error(l.result + ": no resolved scene (scene_yaml)");
      r.stage = control_stage(*f.scene);
      if (r.stage < 0) throw std::runtime_error(l.result + ": its scene has no control stage");
      const dem::StageConfig& st = f.scene->stages[static_cast<std::size_t>(r.stage)];
      if (!r.hold && st.cyclic.component < 0) throw std::runtime_error(l.result + ": stages[" + std::to_string(r.stage) + "] has no cyclic loading");
      if (!r.hold) r.period_s = st.cyclic.period_s, r.amplitude_Pa = st.cyclic.amplitude;
      r.ru_limit = st.until.pore_pressure_ratio, r.strain_limit = st.until.double_amplitude_strain;
      r.stage_end = f.stage_end.count(st.name) ? f.stage_end.at(st.name) : "";
      r.series = std::move(f.series);
      r.control = validation::summarise_control_stage(r.series, r.stage, r.period_s);
      r.finished = true;
    } catch (const std::exception& e) {
      r.note = "unreadable: " + std::string(e.what());
    }
  }
  // A hold has no period of its own: its cycles are those of its density's cyclic tests.
  for (CyclicRun& h : runs) {
    if (!h.hold || !h.finished) continue;
    for (const CyclicRun& c : runs)
      if (!c.hold && c.finished && c.density == h.density) h.period_s = c.period_s;
    if (std::isfinite(h.period_s)) h.control.cycles = (h.control.end_time_s - h.control.start_time_s) / h.period_s;
    else h.note = "no finished cyclic test of " + h.density + " to take the period from";
  }
  return runs;
}

// The outcome of a cyclic test in words: liquefied by which criterion, or a censored point.
std::string outcome(const CyclicRun& r) {
  const std::string c = validation::stop_criterion(r.stage_end);
  if (c == "pore_pressure_ratio") return "liquefied: r_u ≥ " + number(r.ru_limit);
  if (c == "double_amplitude_strain") return "liquefied: double-amplitude strain ≥ " + number(100 * r.strain_limit) + " %";
  if (!c.empty()) return "stopped by until." + c;
  return "not liquefied in " + fixed(r.control.cycles, 1) + " cycles" + (r.stage_end.empty() ? " (no stage_end attribute)" : "");
}

const CyclicRun* hold_of(const std::vector<CyclicRun>& runs, const std::string& density) {
  for (const CyclicRun& r : runs)
    if (r.hold && r.finished && r.density == density) return &r;
  return nullptr;
}

// A hold that reached the r_u limit with nothing applied: the N_L of its density's tests that
// liquefied no later than it did are bounded by that collapse, not set by the loading alone.
std::string collapse_notes(const std::vector<CyclicRun>& runs) {
  std::string notes;
  for (const CyclicRun& h : runs) {
    if (!h.hold || !h.finished || validation::stop_criterion(h.stage_end) != "pore_pressure_ratio") continue;
    double low = INFINITY, high = -INFINITY;
    for (const CyclicRun& r : runs)
      if (!r.hold && r.finished && r.density == h.density && !validation::stop_criterion(r.stage_end).empty())
        low = std::min(low, r.control.cycles), high = std::max(high, r.control.cycles);
    notes += "\n⚠ " + h.run + " reached r_u ≥ " + number(h.ru_limit) + " with nothing applied after " +
             fixed(h.control.end_time_s - h.control.start_time_s, 4) + " s (" + fixed(h.control.cycles, 2) + " cycles of " +
             number(h.period_s) + " s)";
    if (std::isfinite(low))
      notes += "; its density's cyclic tests liquefied after " + fixed(low, 2) + " – " + fixed(high, 2) + " cycles" +
               (high <= h.control.cycles ? ", no later than the hold: their N_L are bounded by the sample's own collapse at constant "
                                           "volume, not set by the loading alone"
                                         : "");
    notes += ".\n";
  }
  return notes;
}

std::string liquefaction_table(const std::vector<CyclicRun>& runs, const std::vector<std::string>& folders) {
  std::ostringstream md;
  std::size_t finished = 0;
  for (const CyclicRun& r : runs) finished += r.finished;
  md << "Undrained cyclic triaxial tests (`scenes/tests/undrained_cyclic.yaml`) and their unloaded twins "
        "(`scenes/tests/undrained_hold.yaml`) from " << folders.size() << " study folder(s); " << finished << " of " << runs.size()
     << " runs finished. CSR from the name and from the resolved scene (the cyclic stage's `cyclic.amplitude` / 2 p0, p0 = p at "
        "its start); N_L = (end − start of the cyclic stage) / period; a test that did not liquefy is a censored point "
        "(N_L > N). The last column is the r_u its density's hold had after the same time with nothing applied: the part of the "
        "test's r_u that the loading does not cause.\n\n"
     << "| run | CSR (name) | CSR (scene) | p0 (kPa) | N_L (cycles) | outcome | r_u at the end | hold's r_u at the same time |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const CyclicRun& r : runs) {
    if (r.hold) continue;
    md << "| " << cell(r.run) << " | " << fixed(r.csr_name, 3) << " | ";
    if (!r.finished) {
      md << "— | — | — | " << cell(r.note) << " | — | — |\n";
      continue;
    }
    const double csr = validation::cyclic_stress_ratio(r.amplitude_Pa, r.control.p0_Pa);
    // The consolidation holds every principal stress within 0.5 % of its target, so p0 and the
    // scene's CSR are within about 0.5 % of the nominal; more than 1 % means name and scene disagree.
    const bool agrees = std::abs(csr - r.csr_name) <= 0.01 * r.csr_name;
    std::string at_hold = "—";
    if (const CyclicRun* h = hold_of(runs, r.density)) {
      const double ru = validation::value_since_start(h->series, h->stage, "pore_pressure_ratio", r.control.end_time_s - r.control.start_time_s);
      at_hold = std::isfinite(ru) ? fixed(ru, 3) : "— (the hold lasted " + fixed(h->control.end_time_s - h->control.start_time_s, 3) + " s)";
    }
    const bool censored = validation::stop_criterion(r.stage_end).empty();
    md << fixed(csr, 4) << (agrees ? "" : " ⚠ differs from the name by more than 1 %") << " | " << fixed(r.control.p0_Pa / 1e3, 2) << " | "
       << (censored ? "> " : "") << fixed(r.control.cycles, 2) << " | " << cell(outcome(r)) << " | " << fixed(r.control.ru_end, 3) << " | "
       << cell(at_hold) << " |\n";
  }
  md << "\nThe holds (nothing applied after the same consolidation; cycles of the density's cyclic period):\n\n"
     << "| run | held for (s) | cycles | r_u at the end | largest r_u | how it ended |\n|---|---|---|---|---|---|\n";
  for (const CyclicRun& r : runs) {
    if (!r.hold) continue;
    md << "| " << cell(r.run) << " | ";
    if (!r.finished) {
      md << "— | — | — | — | " << cell(r.note) << " |\n";
      continue;
    }
    md << fixed(r.control.end_time_s - r.control.start_time_s, 3) << " | " << fixed(r.control.cycles, 1) << " | " << fixed(r.control.ru_end, 4)
       << " | " << fixed(r.control.ru_max, 4) << " | " << cell(r.stage_end.empty() ? "no stage_end attribute" : r.stage_end) << (r.note.empty() ? "" : "; " + cell(r.note)) << " |\n";
  }
  md << collapse_notes(runs);
  md << "\n![CSR against the number of cycles to liquefaction](csr_nl.png)\n\n![r_u against the number of cycles](ru.png)\n";
  return md.str();
}

// compare-runs liquefaction: table.md, csr_nl.dat, ru.dat and values.gp (what
// reports/gnuplot/liquefaction_*.gp need) from one or more study folders.
int liquefaction(const std::string& out, const std::vector<std::string>& folders) {
  std::vector<CyclicRun> runs;
  std::vector<std::string> densities;
  try {
    for (const std::string& dir : folders)
      for (CyclicRun& r : cyclic_runs(dir)) {
        if (std::find(densities.begin(), densities.end(), r.density) == densities.end()) densities.push_back(r.density);
        runs.push_back(std::move(r));
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  validation::Table csr;
  csr.comments = {"compare-runs liquefaction: one row per finished cyclic test; density as in values.gp (liq_density_<n>);",
                  "liquefied 0: a censored point, the test ended (duration) before either criterion: N_L > n_cycles"};
  csr.columns = {"density [1]", "csr_name [1]", "csr_scene [1]", "n_cycles [1]", "liquefied [1]", "p0 [kPa]"};
  validation::Table ru;
  ru.comments = {"compare-runs liquefaction: r_u against cycles since the start of the control stage, one block per run (values.gp: liq_run_<k>)"};
  validation::GnuplotValues values;
  std::vector<std::string> run_names, run_density, run_hold;
  for (const CyclicRun& r : runs) {
    if (!r.finished) continue;
    const double d = static_cast<double>(std::find(densities.begin(), densities.end(), r.density) - densities.begin() + 1);
    if (!r.hold) {
      csr.labels.push_back(r.run);
      csr.rows.push_back({d, r.csr_name, validation::cyclic_stress_ratio(r.amplitude_Pa, r.control.p0_Pa), r.control.cycles,
                          validation::stop_criterion(r.stage_end).empty() ? 0.0 : 1.0, r.control.p0_Pa / 1e3});
    }
    if (!std::isfinite(r.period_s)) continue;  // a hold without a cyclic test to count its cycles by
    const validation::Table t = validation::ru_against_cycles(r.series, r.stage, r.period_s);
    if (!ru.rows.empty()) ru.block_starts.push_back(ru.rows.size());
    for (std::size_t i = 0; i < t.size(); ++i) ru.rows.push_back(t.rows[i]), ru.labels.push_back(r.run);
    run_names.push_back(r.run), run_density.push_back(std::to_string(static_cast<int>(d))), run_hold.push_back(r.hold ? "1" : "0");
  }
  ru.columns = {"cycles [1]", "r_u [1]", "time since the stage start [s]"};
  values.texts("liq_density", densities);
  values.texts("liq_run", run_names);
  values.texts("liq_run_density", run_density);
  values.texts("liq_run_hold", run_hold);
  try {
    fs::create_directories(out);
    dem::write_file_atomically((fs::path(out) / "table.md").string(), liquefaction_table(runs, folders));
    dem::write_file_atomically((fs::path(out) / "csr_nl.dat").string(), csr.text());
    dem::write_file_atomically((fs::path(out) / "ru.dat").string(), ru.text());
    std::string from;
    for (const std::string& f : folders) from += (from.empty() ? "" : ", ") + relative_paths(f, f);
    dem::write_file_atomically((fs::path(out) / "values.gp").string(), values.text_file("Written by compare-runs liquefaction from " + from));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::size_t finished = 0;
  for (const CyclicRun& r : runs) {
    finished += r.finished;
    if (!r.finished) std::fprintf(stderr, "note: %s: %s\n", r.run.c_str(), r.note.c_str());
  }
  std::printf("liquefaction: %zu of %zu runs finished -> %s\n", finished, runs.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: compare-runs convergence|stability|decisions|critical-state RESULTS_DIR OUT_DIR [--reference NAME] [--references FILE] [--report-only] [--ensemble PAPER_RESULTS]\n"
                         "       compare-runs liquefaction OUT_DIR RESULTS_DIR...\n");
    return 2;
  }
  const std::string mode = argv[1], results = argv[2], out = argv[3];
  if (mode == "liquefaction") return liquefaction(argv[2], std::vector<std::string>(argv + 3, argv + argc));
  std::string reference = "reference", references = "reference_data/paper.yaml", ensemble;
  bool report_only = false;  // stability: a case that is not acceptable is marked in the table, not an exit status
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--report-only") report_only = true;
    else if (a == "--reference" && i + 1 < argc) reference = argv[++i];
    else if (a == "--references" && i + 1 < argc) references = argv[++i];
    else if (a == "--ensemble" && i + 1 < argc) ensemble = argv[++i];
    else {
      std::fprintf(stderr, "compare-runs: unknown option '%s'\n", a.c_str());
      return 2;
    }
  }
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
        md << "| " << cell(name) << " | " << cell(relative_paths(l.settings, results)) << " | " << (o.acceptable ? "" : "⚠ ") << o.outcome << " | "
           << o.steps << " | " << (o.closure ? percent(*o.closure) : "—") << " | " << cell(o.message) << " |\n";
      }
    }
    std::printf("stability: %zu cases, %d not acceptable -> %s\n", order.size(), bad, (fs::path(out) / "table.md").c_str());
    return bad > 0 && !report_only ? 1 : 0;
  }
  if (mode == "critical-state") return critical_state(manifest, results, out);
  if (mode == "decisions")
    return decisions(manifest, order, references, reference == "reference" ? "baseline" : reference, ensemble, out);
  if (mode != "convergence") {
    std::fprintf(stderr, "compare-runs: unknown mode '%s' (convergence, stability, decisions, critical-state or liquefaction)\n", mode.c_str());
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
        tests.push_back({l.test, {0, series, validation::read_columns(l.result, "legs"), l.test}});
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
    // front.dat: the same lines of the Pareto front but the reference (error 0, off a log axis),
    // in order of wall time, for the figure's line (reports/gnuplot/convergence_error_vs_time.gp).
    std::vector<std::size_t> on_front;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (front[k] && points[k].error > 0) on_front.push_back(k);
    std::sort(on_front.begin(), on_front.end(), [&](std::size_t a, std::size_t b) { return points[a].cost < points[b].cost; });
    std::ofstream fr(fs::path(out) / "front.dat");
    fr << "# the Pareto front of errors.dat without the reference, by wall time; columns as errors.dat\n";
    for (std::size_t k : on_front) {
      const Row& r = rows[point_row[k]];
      fr << r.variant << '\t' << r.wall << '\t' << r.largest << "\t1";
      for (const auto& [name, v] : ref_q) fr << '\t' << r.errors.at(name);
      fr << "\n";
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
