#include "report/report_values.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/hdf5.hpp"
#include "judge/decisions_file.hpp"
#include "report/open_choices_check.hpp"
#include "report/other_sections.hpp"
#include "sections/variants.hpp"
#include "source_hash.hpp"
#include "study/format.hpp"
#include "study/json_file.hpp"
#include "study/markdown_table.hpp"
#include "study/paths.hpp"
#include "study/settings.hpp"
#include "version.hpp"
#include "study/columns.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

// A number from a settings value scaled: "100000" / 1e3 -> "100".
std::string scaled(const std::map<std::string, std::string>& kv, const std::string& key, double factor) {
  const auto it = kv.find(key);
  if (it == kv.end()) return "?";
  try {
    return number(std::stod(it->second) / factor);
  } catch (const std::exception&) {
    return "?";
  }
}

std::string value_or(const std::map<std::string, std::string>& kv, const std::string& key, const std::string& otherwise) {
  const auto it = kv.find(key);
  return it == kv.end() ? otherwise : it->second;
}

// A section's table.md with its figures' paths made relative to the report; a figure that was not
// drawn is said so.
std::string section_table(const fs::path& report, const std::string& dir) {
  std::istringstream in(read_text(report / dir / "table.md"));
  static const std::regex image(R"(^!\[(.*)\]\(([^/\)]+\.png)\)$)");
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, image))
      out += fs::exists(report / dir / m[2].str()) ? "![" + m[1].str() + "](" + dir + "/" + m[2].str() + ")\n"
                                                   : "*Figure `" + dir + "/" + m[2].str() + "` not drawn.*\n";
    else
      out += line + "\n";
  }
  return out;
}

// The number of samples (seeds) a study's runs.tsv lists for one variant.
std::size_t seeds_in(const std::string& dir, const std::string& variant) {
  std::ifstream runs(fs::path(dir) / "runs.tsv");
  std::set<std::string> seeds;
  for (std::string line; std::getline(runs, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, '\t');) f.push_back(x);
    if (f.size() >= 9 && f[0] == variant && f[2] == "-") seeds.insert(f[8]);
  }
  return seeds.size();
}

// The size a decisions table was measured at: its decisions.json's own record, "" if it has none.
std::string recorded_size(const fs::path& json, const std::vector<Row>& paper) {
  std::error_code ec;
  try {
    if (fs::exists(json, ec)) {
      const DecisionsFile f = read_decisions_file(json.string(), paper);
      if (f.particles) return size_label(f);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s: %s\n", json.c_str(), e.what());
  }
  return "";
}

// The size check of a readings study's table.md ("### Size check..." to the next "### " or the
// end), taken out of `table`: {heading line, text before its table, its table's lines}.
struct SizeCheck {
  std::string heading, intro;
  std::vector<std::string> header, rows;
};
SizeCheck take_size_check(std::string& table) {
  SizeCheck c;
  const std::size_t at = table.find("### Size check");
  if (at == std::string::npos || (at > 0 && table[at - 1] != '\n')) return c;
  std::size_t end = table.find("\n### ", at);
  end = end == std::string::npos ? table.size() : end + 1;
  std::istringstream in(table.substr(at, end - at));
  table.erase(at, end - at);
  std::getline(in, c.heading);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("|", 0) == 0) (c.header.size() < 2 ? c.header : c.rows).push_back(line);
    else if (c.header.empty()) c.intro += line + "\n";
  }
  return c;
}

// The readings measured again at the paper's size (make readings-report): reports/readings/<name>/,
// each under a heading with its size, its own headings one level down; their size checks (each
// study's baseline against the paper study's ensemble, rows the studies share alike) once, after
// them: every row once, with the studies whose baseline has it (a row two baselines give
// differently: a line for each).
std::string readings_text(const fs::path& report, const std::vector<Row>& paper) {
  std::error_code ec;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(report / "readings", ec))
    if (fs::exists(e.path() / "table.md", ec)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string readings, check_heading, check_intro;
  std::vector<std::string> check_header;
  std::vector<std::pair<std::string, std::vector<std::string>>> check_rows;  // a table line, its studies
  const Stamp paper_stamp = read_paper_stamp(report);
  for (const std::string& name : names) {
    const std::string size = recorded_size(report / "readings" / name / "decisions.json", paper);
    // A study named by its densities (readings_medium_dense) is "of the medium and dense
    // samples", another by its name.
    const bool by_density = std::regex_match(name, std::regex("(loose|medium|dense)(_(loose|medium|dense))*"));
    const std::string title = by_density ? "Readings of the " + std::regex_replace(name, std::regex("_"), " and ") + " sample" +
                                               (name.find('_') != std::string::npos ? "s" : "")
                                         : "Readings: " + std::regex_replace(name, std::regex("_"), " ");
    std::string table = section_table(report, "readings/" + name);
    const SizeCheck c = take_size_check(table);
    if (!c.heading.empty() && check_heading.empty()) check_heading = c.heading, check_intro = c.intro, check_header = c.header;
    for (const std::string& line : c.rows) {
      auto it = std::find_if(check_rows.begin(), check_rows.end(), [&](const auto& r) { return r.first == line; });
      if (it == check_rows.end()) check_rows.push_back({line, {name}});
      else it->second.push_back(name);
    }
    // Its stamp, as a section's (other_sections.hpp); one from another baseline than the paper
    // study's is marked, since the readings are measured against the paper study's samples.
    const Stamp stamp = read_section_stamp(report, {"", "", "readings/" + name + "/decisions.json", "stamp", ""});
    const std::string differs = stamp_difference(stamp, paper_stamp);
    std::string line = stamp_sentence(stamp);
    if (!differs.empty()) line = "⚠ " + line + "; another " + differs + " than the paper study's (" + stamp_text(paper_stamp) + ")";
    readings += "### " + title + " (" + (size.empty() ? "size not recorded" : size) + ")\n\n*" + line + ".*\n\n" +
                std::regex_replace(table, std::regex("(^|\n)### "), "$1#### ") + "\n";
  }
  if (check_rows.empty() || check_header.size() < 2) return readings;
  // The rows in the reference file's order.
  const auto place = [&](const std::string& line) {
    for (std::size_t i = 0; i < paper.size(); ++i)
      if (line.rfind("| " + cell(paper[i].name) + " |", 0) == 0) return i;
    return paper.size();
  };
  std::stable_sort(check_rows.begin(), check_rows.end(), [&](const auto& a, const auto& b) { return place(a.first) < place(b.first); });
  readings += check_heading + "\n" + check_intro + "Each row once, with the readings studies whose baseline has it.\n\n" +
              check_header[0] + " studies |\n" + check_header[1] + "---|\n";
  for (const auto& [line, studies] : check_rows) readings += line + " " + joined(studies, ", ") + " |\n";
  return readings + "\n";
}

// key = value lines of a gnuplot values.gp (figure-data's record of the study's settings); a key
// given twice: its last value, as gnuplot reads it; quotes taken off.
std::map<std::string, std::string> gnuplot_values(const fs::path& file) {
  std::map<std::string, std::string> out;
  std::istringstream in(read_text(file));
  static const std::regex line_re(R"re(^([A-Za-z_][A-Za-z0-9_]*) = "?([^"]*)"?$)re");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, line_re)) out[m[1].str()] = m[2].str();
  }
  return out;
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
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  v["date"] = date;
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
  const auto settings = have_results ? run_settings(results) : std::map<std::string, std::string>{};
  for (const auto& [k, val] : settings) v["setting." + k] = val;
  v["setting.mean_stress_kPa"] = scaled(settings, "mean_stress_Pa", 1e3);
  v["setting.stress_rate_MPa_per_s"] = scaled(settings, "stress_rate_Pa_per_s", 1e6);
  v["setting.time_step_prepare_us"] = scaled(settings, "time_step_prepare_s", 1e-6);
  v["setting.time_step_test_us"] = scaled(settings, "time_step_test_s", 1e-6);
  v["setting.particles_text"] = thousands(value_or(settings, "particles", ""));
  {
    static const std::regex visits(R"((TC1, A, [A-Z0-9]+, A, [A-Z0-9]+))");
    std::smatch m;
    const std::string path = value_or(settings, "test3_path", "");
    v["setting.test3_visits"] = std::regex_search(path, m, visits) ? m[1].str() : "?";
  }
  for (const char* k : {"grading_basis", "damping_form", "damping_translational", "hold_unbalanced_force_ratio", "hold_stress_tolerance",
                        "max_strain_rate_per_s", "friction_shear_loose", "friction_shear_medium", "friction_shear_dense", "stress_ratio",
                        "lattice", "target_pressure_kPa", "friction_prepare", "friction_shear", "max_energy_error"})
    if (!v.count(std::string("setting.") + k)) v[std::string("setting.") + k] = "?";
  v["max_energy_error_percent"] = scaled(settings, "max_energy_error", 0.01);
}

void add_tables(Values& v, const fs::path& report, const std::vector<Row>& paper, const std::string& decisions_results) {
  const auto include = [&](const std::string& key, const fs::path& file) { v[key] = read_text(report / file); };
  // The compact table links each cause to causes.md#cause-N; in the report, to its entry in the appendix.
  v["file.verdicts"] = std::regex_replace(read_text(report / "verdicts.md"), std::regex(R"(\]\(causes\.md#)"), "](#");
  include("file.causes", "causes.md");
  include("file.validation", "validation.md");
  include("file.samples", "samples.md");
  include("file.bench", "bench.md");
  v["file.decisions"] = fs::exists(report / "decisions" / "table.md")
                            ? std::regex_replace(read_text(report / "decisions" / "table.md"), std::regex(R"(\]\((tornado[^)]*)\))"), "](decisions/$1)")
                            : "";
  include("file.convergence", fs::path("convergence") / "table.md");
  include("file.stability", fs::path("stability") / "table.md");
  include("file.literature", fs::path("literature") / "validation.md");
  include("file.literature_verdicts", fs::path("literature") / "verdicts.md");
  include("file.literature_fcc", fs::path("literature") / "fcc" / "validation.md");
  include("file.literature_fcc_verdicts", fs::path("literature") / "fcc" / "verdicts.md");
  v["file.critical_state"] = fs::exists(report / "critical_state" / "table.md") ? section_table(report, "critical_state") : "";
  include("file.calibration", fs::path("calibration") / "synthetic_triaxial" / "section.md");
  v["calibration_plot"] = fs::exists(report / "calibration" / "synthetic_triaxial" / "posterior.png") ? "1" : "";
  include("file.calibration_open_choices", fs::path("calibration") / "paper_open_choices" / "section.md");
  v["calibration_open_choices_plot"] = fs::exists(report / "calibration" / "paper_open_choices" / "posterior.png") ? "1" : "";
  v["calibration_open_choices_check"] = open_choices_check_text(report);
  v["file.liquefaction"] = fs::exists(report / "liquefaction" / "table.md") ? section_table(report, "liquefaction") : "";
  v["convergence_plot"] = fs::exists(report / "convergence" / "error_vs_time.png") ? "yes" : "";
  // The size the decisions table was measured at: its decisions.json's own record, else (the
  // decisions study) what its results say; never assumed.
  v["decisions.size"] = recorded_size(report / "decisions" / "decisions.json", paper);
  if (v["decisions.size"].empty() && !decisions_results.empty()) {
    const std::size_t n = seeds_in(decisions_results, "baseline");
    const auto ds = run_settings(decisions_results, "baseline_");
    if (n > 0 && ds.count("particles"))
      v["decisions.size"] = thousands(ds.at("particles")) + " spheres, " + std::to_string(n) + " sample" + (n == 1 ? "" : "s");
  }
  if (v["decisions.size"].empty()) v["decisions.size"] = "size not recorded";
  v["file.readings"] = readings_text(report, paper);
}

void add_setup(Values& v, const fs::path& report, const std::string& settings_from) {
  const bool have_results = !settings_from.empty();
  // The study's settings: from its results' resolved scenes (add_settings), else from what
  // figure-data recorded of them in reports/figures/values.gp; a setting neither gives is left out.
  const std::map<std::string, std::string> gp = gnuplot_values(report / "figures" / "values.gp");
  const auto setting = [&](const std::string& key, const std::string& gp_key) -> std::string {
    if (have_results) {
      const auto it = v.find("setting." + key);
      return it == v.end() || it->second == "?" ? "" : it->second;
    }
    const auto it = gp.find(gp_key);
    return it == gp.end() || it->second == "?" ? "" : it->second;
  };
  nlohmann::json record;
  try {
    if (fs::exists(report / "validation.json")) record = read_json_file((report / "validation.json").string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s\n", e.what());
  }
  MarkdownTable md({"", "the study"});
  if (record.is_object() && record.contains("samples") && record.contains("rows")) {
    std::vector<std::string> densities;
    for (const auto& r : record.at("rows")) {
      const std::string d = r.value("density", "");
      if (!d.empty() && std::find(densities.begin(), densities.end(), d) == densities.end()) densities.push_back(d);
    }
    const auto& samples = record.at("samples");
    std::string names = samples.empty() ? "" : samples.front().get<std::string>();
    if (samples.size() > 1) names += "–" + samples.back().get<std::string>();
    md.row({"samples", std::to_string(samples.size()) + " per density (" + joined(densities, ", ") + ")" + (names.empty() ? "" : ", " + names)});
  }
  const std::string particles = setting("particles", "particles");
  if (!particles.empty() && particles != "0") md.row({"spheres per sample", thousands(particles)});
  std::string frictions = setting("friction_prepare", "");
  if (frictions.empty() && gp.count("friction_prepare_loose") && gp.count("friction_prepare_medium") && gp.count("friction_prepare_dense"))
    frictions = gp.at("friction_prepare_loose") + " / " + gp.at("friction_prepare_medium") + " / " + gp.at("friction_prepare_dense");
  const std::string pressure = setting("target_pressure_kPa", "target_pressure_kPa"), grading = setting("grading_basis", "grading_basis");
  if (!pressure.empty() && !frictions.empty())
    md.row({"preparation", "isotropic compression to " + pressure + " kPa, friction " + frictions + " (loose / medium / dense)" +
                               (grading.empty() ? "" : ", grading read by " + grading)});
  const std::string p = setting("mean_stress_kPa", "mean_stress_kPa"), ratio = setting("stress_ratio", "stress_ratio"),
                    shear = setting("friction_shear", "friction_shear");
  if (!p.empty() && !ratio.empty())
    md.row({"tests", "the five cyclic true-triaxial paths at p = " + p + " kPa, R = " + ratio + (shear.empty() ? "" : ", shearing friction " + shear)});
  if (record.is_object() && record.contains("total"))
    md.row({"judged", std::to_string(record.value("total", 0)) + " rows of `" + record.value("references", std::string("the reference file")) + "` (profile " +
                          record.value("profile", std::string("not recorded")) + "), each on every sample"});
  v["setup.table"] = md.rows() ? md.text() : "";
  v["setup.from"] = have_results ? settings_from + " and `reports/validation.json`"
                                 : "`reports/validation.json` and `reports/figures/values.gp`, which `validate` and `figure-data` wrote from the results";
}

void add_study_settings(Values& v, const std::string& stability_results) {
  // A setting the study's resolved scenes do not give is no key at all (no "?" placeholder): the
  // template quotes these only when the study's results are here, and an unguarded use fails.
  const auto put = [&](const std::string& key, const std::string& value) {
    if (!value.empty() && value != "?") v[key] = value;
  };
  const auto ss = stability_results.empty() ? std::map<std::string, std::string>{} : run_settings(stability_results, "", "base");
  v["have_stability"] = ss.empty() ? "" : "yes";
  put("stability.particles", ss.count("particles") ? thousands(ss.at("particles")) : "");
  put("stability.target_pressure_kPa", value_or(ss, "target_pressure_kPa", ""));
  put("stability.max_energy_error_percent", scaled(ss, "max_energy_error", 0.01));
  put("stability.max_time_step_fraction", value_or(ss, "max_time_step_fraction", ""));
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
  v["file.figures_readme"] = std::regex_replace(readme, std::regex(R"(\]\((fig[^)]*)\))"), "](figures/$1)");
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
