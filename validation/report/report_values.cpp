#include "report/report_values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/hdf5.hpp"
#include "judge/decisions_file.hpp"
#include "judge/validation_file.hpp"
#include "judge/verdicts.hpp"
#include "report/baseline_check.hpp"
#include "report/open_choices_check.hpp"
#include "report/open_choices_paper_size.hpp"
#include "report/open_choices_parts.hpp"
#include "report/other_sections.hpp"
#include "report/study_values.hpp"
#include "sections/variants.hpp"
#include "source_hash.hpp"
#include "study/format.hpp"
#include "study/json_file.hpp"
#include "study/manifest.hpp"
#include "study/markdown_table.hpp"
#include "study/paths.hpp"
#include "study/section_doc.hpp"
#include "study/settings.hpp"
#include "study/utc_day.hpp"
#include "version.hpp"
#include "study/columns.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

// A setting scaled to the unit the text quotes (100000 Pa / 1e3 -> "100" kPa), put under `key`;
// no key at all when the setting is absent: the template says so where it quotes it.
void put_scaled(Values& v, const std::string& key, const std::optional<double>& value, double factor) {
  if (value) v[key] = number(*value / factor);
}

// The section another study made in REPORT/DIR (compare-runs wrote its parts as data:
// study/section_doc.hpp), none when the folder has none. A folder with only a table.md (written
// before the parts were kept) or an unreadable section.json is said on stderr and left out: its
// figures and headings cannot be placed without reading its Markdown back.
std::optional<SectionDoc> section_doc_in(const fs::path& report, const std::string& dir) {
  std::error_code ec;
  try {
    if (std::optional<SectionDoc> doc = read_section_doc(report / dir)) return doc;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s; the section is left out\n", e.what());
    return std::nullopt;
  }
  if (fs::exists(report / dir / "table.md", ec))
    std::fprintf(stderr, "report: %s has a table.md but no %s (written before sections were kept as data): left out; write it again with "
                 "build/bin/compare-runs\n", (report / dir).c_str(), section_doc_file);
  return std::nullopt;
}

// That section placed under a heading of `level` in REPORT/index.md: its headings below it, its
// figures' paths from the report's folder, a figure not drawn said so; "" when there is none.
std::string section_text(const fs::path& report, const std::string& dir, int level) {
  const std::optional<SectionDoc> doc = section_doc_in(report, dir);
  return doc ? render(*doc, {level, dir, report / dir}) : "";
}

// "Readings of the medium and dense samples" for a study of some of the paper's densities (as its
// section records them); else "Readings: " and the folder's name, '_' shown as a space.
std::string readings_title(std::string name, const std::vector<std::string>& densities) {
  const std::vector<std::string>& paper = paper_densities();
  const bool some = !densities.empty() && densities.size() < paper.size() &&
                    std::all_of(densities.begin(), densities.end(), [&](const std::string& d) { return std::find(paper.begin(), paper.end(), d) != paper.end(); });
  if (some) return "Readings of the " + joined(densities, " and ") + " sample" + (densities.size() > 1 ? "s" : "");
  std::replace(name.begin(), name.end(), '_', ' ');
  return "Readings: " + name;
}

// The number of samples (seeds) a study's runs.tsv lists for one variant (0 without a manifest).
std::size_t seeds_in(const std::string& dir, const std::string& variant) {
  std::set<std::string> seeds;
  try {
    for (const ManifestLine& l : read_manifest(dir))
      if (l.variant == variant && l.test == "-") seeds.insert(l.seed);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s\n", e.what());
  }
  return seeds.size();
}

// A study's decisions.json, read once; none when it is not there (the error of one that cannot be
// read is said, and the section goes without its check).
std::optional<DecisionsFile> decisions_record(const fs::path& json) {
  std::error_code ec;
  if (!fs::exists(json, ec)) return std::nullopt;
  try {
    return read_decisions_file(json.string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s: %s\n", json.c_str(), e.what());
    return std::nullopt;
  }
}

// The readings measured again at the paper's size (make readings-report): reports/readings/<name>/,
// each under a heading with its size, its own headings one level down; their size checks (each
// study's baseline against the paper study's ensemble, rows the studies share alike) once, after
// them: every row once, with the studies whose baseline has it (a row two baselines give
// differently: a line for each).
std::string readings_text(const fs::path& report, const PaperEnsemble& ensemble) {
  std::error_code ec;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(report / "readings", ec))
    if (fs::exists(e.path() / section_doc_file, ec) || fs::exists(e.path() / "table.md", ec)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string readings;
  std::vector<DecisionsFile> records;
  const Stamp paper_stamp = read_paper_stamp(report);
  for (const std::string& name : names) {
    const std::optional<SectionDoc> doc = section_doc_in(report, "readings/" + name);
    if (!doc) continue;
    const std::optional<DecisionsFile> record = decisions_record(report / "readings" / name / "decisions.json");
    const std::string size = record && record->particles ? size_label(*record) : "";
    if (record) records.push_back(*record);
    // Its stamp, as a section's (other_sections.hpp); one from another baseline than the paper
    // study's is marked, since the readings are measured against the paper study's samples.
    const Stamp stamp = read_section_stamp(report, {"", "", "readings/" + name + "/decisions.json", "stamp", ""});
    const std::string differs = stamp_difference(stamp, paper_stamp);
    std::string line = stamp_sentence(stamp);
    if (!differs.empty()) line = "⚠ " + line + "; another " + differs + " than the paper study's (" + stamp_text(paper_stamp) + ")";
    // Its own headings one level below its title's.
    readings += "### " + readings_title(name, doc->densities) + " (" + (size.empty() ? "size not recorded" : size) + ")\n\n*" + line + ".*\n\n" +
                render(*doc, {3, "readings/" + name, report / "readings" / name}) + "\n";
  }
  // Their checks against the paper study's ensemble in one table (each row once).
  std::vector<const DecisionsFile*> files;
  for (const DecisionsFile& f : records) files.push_back(&f);
  const std::string check = baseline_check_section(files, ensemble);
  return check.empty() ? readings : readings + check + "\n";
}

}  // namespace

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  if (!in) return "";
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void add_provenance(Values& v, const ReportSources& src, bool have_results, std::size_t missing) {
  v["date"] = utc_day();
  v["results"] = shown_path(src.results);
  v["note"] = src.note;
  v["source"] = src.source.empty() ? "not given" : src.source;
  v["tool_version"] = std::string(dem::software_version) + " (engine source " + dem::engine_source_hash + ")";
  v["have_results"] = have_results ? "yes" : "";
  v["missing_results"] = missing == 0 ? "" : std::to_string(missing);
}

std::vector<std::pair<std::string, Columns>> add_runs(Values& v, const std::vector<Sample>& samples,
                                                      const std::vector<std::string>& densities) {
  std::map<std::string, int> engines;
  MarkdownTable runs_md({"sample", "runs", "steps", "wall time of the runs (s)"});
  double total_wall = 0;
  std::vector<std::pair<std::string, Columns>> energy_series;  // the chosen sample's runs
  const std::string chosen = v.count("sample") ? v["sample"] : "";
  for (const Sample& s : samples) {
    int n = 0;
    double steps = 0, wall = 0;
    for (const std::string& d : densities) {
      std::vector<std::string> files = {(fs::path(s.dir) / (d + "_prepare.h5")).string()};
      for (int t = 1; t <= 5; ++t) files.push_back((fs::path(s.dir) / (d + "_test" + std::to_string(t) + ".h5")).string());
      for (const std::string& f : files) {
        if (!is_complete(f)) continue;
        try {
          dem::h5::Handle h = dem::h5::open_file_read(f);
          if (dem::h5::has_attribute(h, "software_version")) ++engines[dem::h5::get_string_attribute(h, "software_version")];
          if (dem::h5::has_attribute(h, "wall_time_s")) wall += dem::h5::get_double_attribute(h, "wall_time_s");
          Columns c = read_columns(f, "timeseries");
          if (c.count(col::step) && !c.at(col::step).empty()) steps += c.at(col::step).back();
          ++n;
          if ((s.name.empty() ? "the sample" : s.name) == chosen)
            energy_series.emplace_back(d + (f.find("_prepare.h5") != std::string::npos ? "_prepare" : f.substr(f.rfind("_test"), 6)),
                                       std::move(c));
        } catch (const std::exception& e) {
          std::fprintf(stderr, "report: %s: %s, left out\n", f.c_str(), e.what());
        }
      }
    }
    total_wall += wall;
    runs_md.row({s.name.empty() ? "the sample" : s.name, std::to_string(n), fixed(steps, 0), fixed(wall, 0)});
  }
  v["runs_table"] = runs_md.text();
  v["total_wall_s"] = number(std::round(total_wall));
  std::string engine_list;
  for (const auto& [version, count] : engines)
    engine_list += (engine_list.empty() ? "" : ", ") + version + " (" + std::to_string(count) + " runs)";
  v["engines"] = engine_list.empty() ? "unknown" : engine_list;
  return energy_series;
}

void add_settings(Values& v, const std::string& results, bool have_results) {
  const RunSettings settings = have_results ? run_settings(results) : RunSettings{};
  for (const auto& [k, val] : setting_texts(settings)) v["setting." + k] = val;
  put_scaled(v, "setting.mean_stress_kPa", settings.mean_stress_Pa, 1e3);
  put_scaled(v, "setting.stress_rate_MPa_per_s", settings.stress_rate_Pa_per_s, 1e6);
  put_scaled(v, "setting.time_step_prepare_us", settings.time_step_prepare_s, 1e-6);
  put_scaled(v, "setting.time_step_test_us", settings.time_step_test_s, 1e-6);
  if (settings.particles) v["setting.particles_text"] = thousands(*settings.particles);
  // The states the first legs of Test 3's path go to (where the paper leaves their order open).
  if (const auto t3 = settings.tests.find(3); t3 != settings.tests.end() && t3->second.visits.size() >= 5)
    v["setting.test3_visits"] = joined(std::vector<std::string>(t3->second.visits.begin(), t3->second.visits.begin() + 5), ", ");
  put_scaled(v, "max_energy_error_percent", settings.max_energy_error, 0.01);
}

void add_tables(Values& v, const fs::path& report, const std::vector<Row>& paper, const std::string& decisions_results) {
  const auto include = [&](const std::string& key, const fs::path& file) { v[key] = read_text(report / file); };
  // The compact table whose cause cells link to their entries in the report's appendix (without
  // causes, validate writes verdicts.md alone: it has no link).
  include("file.verdicts", fs::exists(report / verdicts_in_report_file) ? verdicts_in_report_file : "verdicts.md");
  include("file.causes", "causes.md");
  include("file.validation", "validation.md");
  include("file.samples", "samples.md");
  include("file.bench", "bench.md");
  v["file.decisions"] = section_text(report, "decisions", 2);
  include("file.convergence", fs::path("convergence") / "table.md");
  include("file.stability", fs::path("stability") / "table.md");
  include("file.literature", fs::path("literature") / "validation.md");
  include("file.literature_verdicts", fs::path("literature") / "verdicts.md");
  include("file.literature_fcc", fs::path("literature") / "fcc" / "validation.md");
  include("file.literature_fcc_verdicts", fs::path("literature") / "fcc" / "verdicts.md");
  v["file.critical_state"] = section_text(report, "critical_state", 2);
  include("file.calibration", fs::path("calibration") / "synthetic_triaxial" / "section.md");
  v["calibration_plot"] = fs::exists(report / "calibration" / "synthetic_triaxial" / "posterior.png") ? "1" : "";
  include("file.calibration_open_choices", fs::path("calibration") / "paper_open_choices" / "section.md");
  v["calibration_open_choices_plot"] = fs::exists(report / "calibration" / "paper_open_choices" / "posterior.png") ? "1" : "";
  v["calibration_open_choices_check"] = open_choices_check_text(report);
  v["calibration_open_choices_paper_size"] = open_choices_paper_size_text(report, paper);
  v["calibration_open_choices_parts"] = open_choices_parts_text(report, paper);
  v["file.liquefaction"] = section_text(report, "liquefaction", 2);
  v["convergence_plot"] = fs::exists(report / "convergence" / "error_vs_time.png") ? "yes" : "";
  // The size the decisions table was measured at: its decisions.json's own record, else (the
  // decisions study) what its results say; never assumed.
  PaperEnsemble ensemble;  // the checks of the studies' baselines need it; without it they are left out, said on stderr
  try {
    ensemble = read_paper_ensemble(report, paper);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s; the checks of the decisions studies' baselines are left out\n", e.what());
  }
  const std::optional<DecisionsFile> decisions = decisions_record(report / "decisions" / "decisions.json");
  v["decisions.size"] = decisions && decisions->particles ? size_label(*decisions) : "";
  v["decisions.check"] = decisions ? baseline_check_section({&*decisions}, ensemble) : "";
  if (v["decisions.size"].empty() && !decisions_results.empty()) {
    const std::size_t n = seeds_in(decisions_results, "baseline");
    const RunSettings ds = run_settings(decisions_results, "baseline_");
    if (n > 0 && ds.particles)
      v["decisions.size"] = thousands(*ds.particles) + " spheres, " + std::to_string(n) + " sample" + (n == 1 ? "" : "s");
  }
  if (v["decisions.size"].empty()) v["decisions.size"] = "size not recorded";
  v["file.readings"] = readings_text(report, ensemble);
}

void add_note_verdicts(Values& v, const PaperEnsemble& judged) {
  const auto find = [&](const std::string& quantity, const std::string& density) -> const RejudgedRow* {
    for (const RejudgedRow& r : judged.rows)
      if (r.row.quantity == quantity && r.density == density) return &r;
    return nullptr;
  };
  for (const NoteVerdict& n : note_verdicts())
    if (const RejudgedRow* r = find(n.quantity, n.density)) v[n.key] = verdict_phrase(r->result);
  // What the dense coordination row counts (Fig. 10's "no change"): the change from the end of one
  // cycle to the end of another, not the cycle before it.
  if (const RejudgedRow* r = find("cn_change_magnitude", "dense"); r && r->result.valued > 1)
    v["fig10.counted_dense"] = "from the end of cycle " + std::to_string(r->row.from_cycle) + " to the end of cycle " +
                               std::to_string(r->row.to_cycle) + " (|Δ| = " + mean_pm_sd(r->result.spread.mean, r->result.spread.sd) +
                               " over the samples)";
}

void add_setup(Values& v, const fs::path& report, const std::string& settings_from) {
  // The study's settings as add_settings put them (from its results' resolved scenes, or as
  // REPORT/study_values.json kept them); a setting not there is left out.
  const auto setting = [&](const std::string& key) -> std::string {
    const auto it = v.find("setting." + key);
    return it == v.end() ? "" : it->second;
  };
  std::optional<RecordedValidation> record;
  try {
    if (fs::exists(report / "validation.json")) record = read_validation_file((report / "validation.json").string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s\n", e.what());
  }
  MarkdownTable md({"", "the study"});
  if (record) {
    std::vector<std::string> densities;
    for (const auto& r : record->rows)
      if (!r.density.empty() && std::find(densities.begin(), densities.end(), r.density) == densities.end()) densities.push_back(r.density);
    const std::vector<std::string>& samples = record->samples;
    std::string names = samples.empty() ? "" : samples.front();
    if (samples.size() > 1) names += "–" + samples.back();
    md.row({"samples", std::to_string(samples.size()) + " per density (" + joined(densities, ", ") + ")" + (names.empty() ? "" : ", " + names)});
  }
  const std::string particles = setting("particles");
  if (!particles.empty() && particles != "0") md.row({"spheres per sample", thousands(particles)});
  const std::string frictions = setting("friction_prepare"), pressure = setting("target_pressure_kPa"), grading = setting("grading_basis");
  if (!pressure.empty() && !frictions.empty())
    md.row({"preparation", "isotropic compression to " + pressure + " kPa, friction " + frictions + " (loose / medium / dense)" +
                               (grading.empty() ? "" : ", grading read by " + grading)});
  const std::string p = setting("mean_stress_kPa"), ratio = setting("stress_ratio"), shear = setting("friction_shear");
  if (!p.empty() && !ratio.empty())
    md.row({"tests", "the five cyclic true-triaxial paths at p = " + p + " kPa, R = " + ratio + (shear.empty() ? "" : ", shearing friction " + shear)});
  if (record)
    md.row({"judged", std::to_string(record->rows.size()) + " rows of `" + record->references.value_or("the reference file") + "` (profile " +
                          (record->profile.empty() ? std::string("not recorded") : record->profile) + "), each on every sample"});
  v["setup.table"] = md.rows() ? md.text() : "";
  v["setup.from"] = !settings_from.empty() ? settings_from + " and `reports/validation.json`"
                                           : "`reports/validation.json` alone (the settings are not here: neither the results nor `reports/" +
                                                 std::string(study_values_file) + "`)";
}

void add_study_settings(Values& v, const std::string& stability_results) {
  // A setting the study's resolved scenes do not give is no key at all: the template quotes these
  // only when the study's results are here, and an unguarded use fails.
  const RunSettings ss = stability_results.empty() ? RunSettings{} : run_settings(stability_results, "", "base");
  v["have_stability"] = ss.empty() ? "" : "yes";
  if (ss.particles) v["stability.particles"] = thousands(*ss.particles);
  if (ss.target_pressure_kPa) v["stability.target_pressure_kPa"] = number(*ss.target_pressure_kPa);
  put_scaled(v, "stability.max_energy_error_percent", ss.max_energy_error, 0.01);
  if (ss.max_time_step_fraction) v["stability.max_time_step_fraction"] = number(*ss.max_time_step_fraction);
  v["stability.closure_onset_percent"] = number(100 * closure_onset_fraction);
  v["stability.closure_limit_percent"] = number(100 * closure_limit);
  v["validation.prediction_percent"] = number(100 * prediction_level);
}

void add_baseline(Values& v, const std::string& baseline_file, const std::vector<Row>& rows, const std::vector<Sample>& samples) {
  if (!baseline_file.empty() && !samples.empty()) {
    const nlohmann::json before = read_json_file(baseline_file);  // errors name the file
    v["baseline.file"] = baseline_file;
    v["baseline.table"] = baseline_table(before, rows, samples);
  }
  if (!samples.empty()) v["state_a.table"] = state_a_table(samples);
  if (!samples.empty()) v["shear_control.table"] = shear_control_table(samples);
}

Values values_from_results(const ReportInputs& in, const std::string& results, const std::string& baseline_file,
                           const std::vector<std::string>& densities) {
  Values v = figure_values(in);
  if (!v.count("sample")) v["sample"] = in.sample.empty() ? "—" : in.sample;
  const auto energy_series = add_runs(v, in.samples, densities);
  add_settings(v, results, true);
  add_baseline(v, baseline_file, in.rows, in.samples);
  std::vector<std::pair<std::string, const Columns*>> runs;
  for (const auto& [name, c] : energy_series) runs.emplace_back(name, &c);
  v["energy.table"] = runs.empty() ? "" : energy_table(runs);
  return v;
}

void add_figures(Values& v, const fs::path& report, const std::string& notes_tsv) {
  std::error_code ec;
  std::string readme = read_text(report / "figures" / "README.md");
  if (!readme.empty() && readme.rfind("# ", 0) == 0) readme = readme.substr(readme.find('\n') + 1);
  v["file.figures_readme"] = readme;  // a hand-written page without links to the figures' files
  std::vector<std::string> pngs, renders;
  for (const auto& e : fs::directory_iterator(report / "figures", ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 4 && name.substr(name.size() - 4) == ".png") {
      if (name.rfind("fig", 0) == 0 && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[3]))) pngs.push_back(name);
      if (name.rfind("render_", 0) == 0) renders.push_back(name);
    }
  }
  std::sort(pngs.begin(), pngs.end());
  // Each figure with its note. The paper's two headline checks (e0 and CN of every sample, q/p
  // against F^s_d/F^s_m) come first, in their own section, and not again.
  const std::vector<std::string> headline = {"fig00_samples.png", "fig00_slopes.png", "fig13_strong_fabric.png", "fig14_strong_fabric_all.png"};
  const auto with_note = [&](const std::string& png) {
    const std::string image = "![" + png.substr(0, png.size() - 4) + "](figures/" + png + ")";
    return "\n" + image + "\n\n" + figure_note(notes_tsv, png, v) + "\n";
  };
  std::string figs, heads;
  for (const std::string& png : pngs)
    (std::find(headline.begin(), headline.end(), png) != headline.end() ? heads : figs) += with_note(png);
  v["figures"] = figs.empty() ? "\n*No figures drawn yet (`reports/make_figures.sh`).*\n" : figs;
  v["headline_figures"] = heads;
  v["figure.fig00"] = std::find(pngs.begin(), pngs.end(), "fig00_samples.png") != pngs.end() ? "yes" : "";
  std::sort(renders.begin(), renders.end());
  std::string r;
  for (const std::string& png : renders) r += "![" + png.substr(0, png.size() - 4) + "](figures/" + png + ")\n";
  v["renders"] = r;
  v["energy.figure"] = fs::exists(report / "figures" / "fig_energy.png") ? "yes" : "";
  v["energy.note"] = figure_note(notes_tsv, "fig_energy.png", v);
}

}  // namespace validation
