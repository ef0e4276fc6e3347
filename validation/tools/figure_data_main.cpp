// figure-data: the data behind the report's figures and the numbers its text quotes, from a
// study's results, its resolved scenes and reference_data/paper.yaml (validation/figures/figures.hpp).
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

#include "figures/figure_data.hpp"
#include "figures/figures.hpp"
#include "study/settings.hpp"
#include "study/format.hpp"
#include "study/markdown_table.hpp"
#include "judge/quantities.hpp"
#include "study/manifest.hpp"
#include "study/paths.hpp"
#include "study/results.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/state_io.hpp"
#include "io/failure.hpp"
#include "study/columns.hpp"

namespace fs = std::filesystem;
using validation::Table;

namespace {

using validation::written_path;

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
  const std::vector<std::string> densities = validation::study_densities(results);
  const std::vector<validation::Sample> samples = validation::load_samples(results, densities, missing);
  if (validation::report_unreadable("figure-data", missing) || no_results(samples, results)) return 1;
  if (sample.empty()) sample = samples.front().name;
  const std::string sample_label = sample.empty() ? fs::path(samples.front().dir).filename().string() : sample;
  const auto chosen = std::find_if(samples.begin(), samples.end(), [&](const validation::Sample& s) { return s.name == sample; });
  if (chosen == samples.end()) {
    std::fprintf(stderr, "figure-data: no sample '%s' in %s\n", sample.c_str(), results.c_str());
    return 2;
  }
  std::vector<validation::Row> paper = validation::load_references(references, "paper");
  validation::FigureFolder folder(out);
  const validation::FigureSource src{samples, *chosen, sample_label, written_path(chosen->dir), written_path(results), std::move(paper),
                                     densities};
  validation::write_figure_data(src, folder);
  const validation::GnuplotValues& values = folder.values;
  const int files = folder.files();
  dem::write_file_atomically((fs::path(out) / "values.gp").string(),
                             values.text_file("Written by figure-data from " + written_path(results) + " (sample " + sample_label +
                                              ") and reference_data/paper.yaml: the numbers the scripts in reports/gnuplot/ read"));
  for (const std::string& m : missing) std::fprintf(stderr, "note: %s: missing or not complete, left out\n", written_path(m).c_str());
  std::fprintf(stderr, "figure-data: %d files from %zu sample(s) of %s (single-run figures: %s) -> %s\n", files + 1,
               samples.size(), written_path(results).c_str(), sample_label.c_str(), written_path(out).c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
int settings(const std::string& results, const std::string& prefix, const std::string& run) {
  if (!results_folder_ok("RESULTS_DIR", results)) return 2;
  const std::map<std::string, std::string> kv = validation::setting_texts(validation::run_settings(results, prefix, run));
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
      std::fprintf(stderr, "figure-data: %s: %s\n", written_path(file).c_str(), e.what());
      lost.push_back(file);
    }
  };
  for (const std::string& results : folders) {
    std::error_code ec;
    if (fs::exists(fs::path(results) / "runs.tsv", ec)) {  // the pipeline's list (study/manifest.hpp): its preparations
      for (const validation::ManifestLine& l : validation::read_manifest(results))
        if (l.test == "-") add(l.variant == "-" ? "" : l.variant, l.density, validation::sample_of(l), validation::result_under(results, l));
    } else {
      for (const auto& [name, dir] : validation::sample_dirs(results))
        for (const std::string& d : validation::paper_densities()) add("", d, name, (fs::path(dir) / (d + "_prepare.h5")).string());
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
  for (const std::string& d : validation::paper_densities())
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
    const auto e = values(g, [](const Preparation& p) { return p.last.at(validation::col::void_ratio); });
    const auto z = values(g, [](const Preparation& p) { return p.last.at(validation::col::coordination_number); });
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
        cells.push_back(signed_fixed(mean(e) - mean(values(groups[base_key], [](const Preparation& p) { return p.last.at(validation::col::void_ratio); })), 4));
        cells.push_back(signed_fixed(mean(z) - mean(values(groups[base_key], [](const Preparation& p) { return p.last.at(validation::col::coordination_number); })), 3));
      } else {
        cells.push_back(""), cells.push_back("");
      }
    }
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at(validation::col::coordination_number_mechanical); }), 2));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return 100 * p.last.at("sliding_fraction"); }), 1));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("mean_normal_force"); }), 3));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at("unbalanced_force_ratio"); }), 5));
    cells.push_back(mean_sd(values(g, [](const Preparation& p) { return p.last.at(validation::col::step); }), 0));
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
  for (const std::string& d : validation::paper_densities())
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
