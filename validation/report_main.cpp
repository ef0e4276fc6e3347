// report: writes the study report (REPORT_DIR/index.md) from a study's results, the validation
// output, the figures, the other studies' tables, the resolved scenes and reference_data/. The text
// is reports/templates/index.md with its {{keys}} filled; every number is computed here
// (validation/report.hpp) or by the tool that wrote the table included (validate, figure-data,
// compare-runs). The figure notes are reports/templates/figure_notes.tsv, filled from the data the
// figures plot and the verdicts of the validation rows about them.
//   report --results DIR --references FILE --out REPORT_DIR [--profile NAME] [--sample NAME]
//          [--templates DIR] [--baseline FILE] [--convergence DIR] [--decisions DIR] [--stability DIR]
//          [--source TEXT] [--note TEXT] [--previous FILE]
// REPORT_DIR holds what the other tools wrote (validation.md, verdicts.md, figures/, samples.md,
// decisions/, convergence/, stability/, critical_state/, liquefaction/, bench.md); a part that is
// missing is said so in its section. --baseline: an earlier baseline's validation.json, compared
// row by row. Exit status: 0; 1 if the report cannot be written, a template names an unknown key
// or a result file is there but cannot be read; 2 for bad arguments or a --results that is not a
// folder (one that does not exist is accepted with --previous).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "compare.hpp"
#include "decisions_file.hpp"
#include "ensemble.hpp"
#include "format.hpp"
#include "io/atomic_file.hpp"
#include "json_file.hpp"
#include "io/hdf5.hpp"
#include "markdown_table.hpp"
#include "report.hpp"
#include "settings.hpp"
#include "source_hash.hpp"
#include "version.hpp"
#include "io/failure.hpp"

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> densities = {"loose", "medium", "dense"};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  if (!in) return "";
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string shown(const std::string& p) {
  const fs::path rel = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  return rel.empty() || rel.string().rfind("..", 0) == 0 ? fs::absolute(p).lexically_normal().string() : rel.string();
}

// A number from a settings value scaled: "100000" / 1e3 -> "100".
std::string scaled(const std::map<std::string, std::string>& kv, const std::string& key, double factor) {
  const auto it = kv.find(key);
  if (it == kv.end()) return "?";
  try {
    return validation::number(std::stod(it->second) / factor);
  } catch (const std::exception&) {
    return "?";
  }
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

// The number of samples (seeds) and runs a study's runs.tsv lists for one variant.
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

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  std::map<std::string, std::string> opt = {{"--profile", "paper"}, {"--templates", "reports/templates"}};
  CLI::App app{"report: writes the study report REPORT_DIR/index.md from a study's results, the validation output, the figures, "
               "the other studies' tables, the resolved scenes and reference_data/ (the text: TEMPLATES/index.md, every number "
               "computed)"};
  app.name("report");
  const auto option = [&](const std::string& name, const std::string& what) { return app.add_option(name, opt[name], what); };
  option("--results", "the study's results folder (its runs.tsv)")->required();
  option("--references", "the reference file (reference_data/paper.yaml)")->required();
  option("--out", "REPORT_DIR: holds what the other tools wrote (validation.md, figures/, ...); index.md goes there")->required();
  option("--profile", "the reference file's profile of the rows")->capture_default_str();
  option("--sample", "the sample whose runs the single-run figures show (e.g. seed1)");
  option("--templates", "the folder of index.md and figure_notes.tsv")->capture_default_str();
  option("--baseline", "an earlier baseline's validation.json, compared row by row");
  option("--convergence", "the convergence study's results folder (its settings for the text)");
  option("--decisions", "the decisions study's results folder (its settings for the text)");
  option("--stability", "the stability study's results folder (its settings for the text)");
  option("--source", "what the report was made from (e.g. the commit)");
  option("--note", "a note printed at the top of the report");
  option("--previous", "an earlier report: each section whose inputs are not here (e.g. the paper study's results) is taken "
                       "from it, and the header names those sections and that report's date");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help, or the error naming the option
    return rc == 0 ? 0 : 2;      // bad arguments: exit 2, as always
  }
  for (const char* k : {"--results", "--references", "--out"})
    if (opt[k].empty()) {
      std::fprintf(stderr, "report: %s must not be empty\n", k);
      return 2;
    }
  const std::string results = opt["--results"], out = opt["--out"];
  std::error_code ec;
  // Nothing to report on is an error: --results must be a folder; one that does not exist only
  // with --previous (a machine without that study's results keeps its sections from that report).
  if (const std::string bad = validation::folder_problem(results);
      !bad.empty() && !(bad == "does not exist" && !opt["--previous"].empty())) {
    std::fprintf(stderr, "report: --results '%s' %s (a study's results folder: seed<N>/ folders or one sample's results%s)\n",
                 results.c_str(), bad.c_str(), bad == "does not exist" ? "; --previous FILE keeps the sections without results" : "");
    return 2;
  }
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    std::fprintf(stderr, "report: --out '%s' is not a folder\n", out.c_str());
    return 2;
  }
  try {
    fs::create_directories(out);
    const fs::path report = out;
    validation::ReportInputs in;
    in.paper = validation::load_references(opt["--references"], "paper");
    in.rows = validation::load_references(opt["--references"], opt["--profile"]);
    std::vector<std::string> missing;
    const bool have_results = fs::is_directory(results, ec);
    if (have_results) in.samples = validation::load_samples(results, densities, missing);
    if (validation::report_unreadable("report", missing)) return 1;  // lost, not merely not run
    in.sample = opt["--sample"];
    validation::Values v = validation::figure_values(in);
    if (!v.count("sample")) v["sample"] = "—", v["samples_n"] = "0";

    // Header and provenance.
    {
      const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
      char date[32];
      std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
      v["date"] = date;
    }
    v["results"] = shown(results);
    v["note"] = opt["--note"];
    v["source"] = opt["--source"].empty() ? "not given" : opt["--source"];
    v["tool_version"] = std::string(dem::software_version) + " (engine source " + dem::engine_source_hash + ")";
    v["have_results"] = have_results && !in.samples.empty() ? "yes" : "";
    v["missing_results"] = missing.empty() ? "" : std::to_string(missing.size());

    // What was run: per sample, the runs, their steps and wall time; the engines that wrote them.
    std::map<std::string, int> engines;
    validation::MarkdownTable runs_md({"sample", "runs", "steps", "wall time of the runs (s)"});
    double total_wall = 0;
    std::vector<std::pair<std::string, validation::Columns>> energy_series;  // the chosen sample's runs
    const std::string chosen = v.count("sample") ? v["sample"] : "";
    for (const validation::Sample& s : in.samples) {
      int n = 0;
      double steps = 0, wall = 0;
      for (const std::string& d : densities) {
        std::vector<std::string> files = {(fs::path(s.dir) / (d + "_prepare.h5")).string()};
        for (int t = 1; t <= 5; ++t) files.push_back((fs::path(s.dir) / (d + "_test" + std::to_string(t) + ".h5")).string());
        for (const std::string& f : files) {
          if (!validation::is_complete(f)) continue;
          try {
            dem::h5::Handle h = dem::h5::open_file_read(f);
            if (dem::h5::has_attribute(h, "software_version")) ++engines[dem::h5::get_string_attribute(h, "software_version")];
            if (dem::h5::has_attribute(h, "wall_time_s")) wall += dem::h5::get_double_attribute(h, "wall_time_s");
            validation::Columns c = validation::read_columns(f, "timeseries");
            if (c.count("step") && !c.at("step").empty()) steps += c.at("step").back();
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
      runs_md.row({s.name.empty() ? "the sample" : s.name, std::to_string(n), validation::fixed(steps, 0), validation::fixed(wall, 0)});
    }
    v["runs_table"] = runs_md.text();
    v["total_wall_s"] = validation::number(std::round(total_wall));
    std::string engine_list;
    for (const auto& [version, count] : engines)
      engine_list += (engine_list.empty() ? "" : ", ") + version + " (" + std::to_string(count) + " runs)";
    v["engines"] = engine_list.empty() ? "unknown" : engine_list;

    // The settings the runs used, from their resolved scenes.
    const auto settings = have_results ? validation::run_settings(results) : std::map<std::string, std::string>{};
    for (const auto& [k, val] : settings) v["setting." + k] = val;
    v["setting.mean_stress_kPa"] = scaled(settings, "mean_stress_Pa", 1e3);
    v["setting.stress_rate_MPa_per_s"] = scaled(settings, "stress_rate_Pa_per_s", 1e6);
    v["setting.time_step_prepare_us"] = scaled(settings, "time_step_prepare_s", 1e-6);
    v["setting.time_step_test_us"] = scaled(settings, "time_step_test_s", 1e-6);
    v["setting.particles_text"] = validation::thousands(settings.count("particles") ? settings.at("particles") : "");
    {
      static const std::regex visits(R"((TC1, A, [A-Z0-9]+, A, [A-Z0-9]+))");
      std::smatch m;
      const std::string path = settings.count("test3_path") ? settings.at("test3_path") : "";
      v["setting.test3_visits"] = std::regex_search(path, m, visits) ? m[1].str() : "?";
    }
    for (const char* k : {"grading_basis", "damping_form", "damping_translational", "hold_unbalanced_force_ratio", "hold_stress_tolerance",
                          "max_strain_rate_per_s", "friction_shear_loose", "friction_shear_medium", "friction_shear_dense", "stress_ratio",
                          "lattice", "target_pressure_kPa", "friction_prepare", "friction_shear", "max_energy_error"})
      if (!v.count(std::string("setting.") + k)) v[std::string("setting.") + k] = "?";
    v["max_energy_error_percent"] = scaled(settings, "max_energy_error", 0.01);

    // The tables other tools wrote.
    const auto include = [&](const std::string& key, const fs::path& file) { v[key] = read_text(report / file); };
    include("file.verdicts", "verdicts.md");
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
    v["file.liquefaction"] = fs::exists(report / "liquefaction" / "table.md") ? section_table(report, "liquefaction") : "";
    v["convergence_plot"] = fs::exists(report / "convergence" / "error_vs_time.png") ? "yes" : "";
    // The size each decisions table was measured at: its decisions.json's own record, else (the
    // decisions study) what its results say; never assumed.
    const auto recorded_size = [&](const fs::path& json) -> std::string {
      try {
        if (fs::exists(json, ec)) {
          const validation::DecisionsFile f = validation::read_decisions_file(json.string(), in.paper);
          if (f.particles) return validation::size_label(f);
        }
      } catch (const std::exception& e) {
        std::fprintf(stderr, "report: %s: %s\n", json.c_str(), e.what());
      }
      return "";
    };
    v["decisions.size"] = recorded_size(report / "decisions" / "decisions.json");
    if (v["decisions.size"].empty() && !opt["--decisions"].empty()) {
      const std::size_t n = seeds_in(opt["--decisions"], "baseline");
      const auto ds = validation::run_settings(opt["--decisions"], "baseline_");
      if (n > 0 && ds.count("particles"))
        v["decisions.size"] = validation::thousands(ds.at("particles")) + " spheres, " + std::to_string(n) + " sample" + (n == 1 ? "" : "s");
    }
    if (v["decisions.size"].empty()) v["decisions.size"] = "size not recorded";
    // The readings measured again at the paper's size (make readings-report): reports/readings/<name>/.
    {
      std::vector<std::string> names;
      for (const auto& e : fs::directory_iterator(report / "readings", ec))
        if (fs::exists(e.path() / "table.md", ec)) names.push_back(e.path().filename().string());
      std::sort(names.begin(), names.end());
      std::string readings;
      for (const std::string& name : names) {
        const std::string size = recorded_size(report / "readings" / name / "decisions.json");
        // Its groups one level down, under this heading: a study named by its densities
        // (readings_medium_dense) is "of the medium and dense samples", another by its name.
        const bool by_density = std::regex_match(name, std::regex("(loose|medium|dense)(_(loose|medium|dense))*"));
        const std::string title = by_density ? "Readings of the " + std::regex_replace(name, std::regex("_"), " and ") + " sample" +
                                                   (name.find('_') != std::string::npos ? "s" : "")
                                             : "Readings: " + std::regex_replace(name, std::regex("_"), " ");
        readings += "### " + title + " (" + (size.empty() ? "size not recorded" : size) + ")\n\n" +
                    std::regex_replace(section_table(report, "readings/" + name), std::regex("(^|\n)### "), "$1#### ") + "\n";
      }
      v["file.readings"] = readings;
    }
    {
      const auto cs = opt["--convergence"].empty() ? std::map<std::string, std::string>{}
                                                   : validation::run_settings(opt["--convergence"], "reference_");
      v["have_convergence"] = cs.empty() ? "" : "yes";  // its results are here (else report --previous keeps the section)
      v["convergence.particles"] = validation::thousands(cs.count("particles") ? cs.at("particles") : "");
      v["convergence.time_step_us"] = scaled(cs, "time_step_test_s", 1e-6);
      v["convergence.stress_rate_MPa_per_s"] = scaled(cs, "stress_rate_Pa_per_s", 1e6);
      v["convergence.test1_cycles"] = cs.count("test1_cycles") ? cs.at("test1_cycles") : "?";
      const auto ss = opt["--stability"].empty() ? std::map<std::string, std::string>{}
                                                 : validation::run_settings(opt["--stability"], "", "base");
      v["have_stability"] = ss.empty() ? "" : "yes";
      v["stability.particles"] = validation::thousands(ss.count("particles") ? ss.at("particles") : "");
      v["stability.target_pressure_kPa"] = ss.count("target_pressure_kPa") ? ss.at("target_pressure_kPa") : "?";
      v["stability.max_energy_error_percent"] = scaled(ss, "max_energy_error", 0.01);
      v["stability.max_time_step_fraction"] = ss.count("max_time_step_fraction") ? ss.at("max_time_step_fraction") : "?";
      v["stability.closure_onset_percent"] = validation::number(100 * validation::closure_onset_fraction);
      v["stability.closure_limit_percent"] = validation::number(100 * validation::closure_limit);
      v["validation.prediction_percent"] = validation::number(100 * validation::prediction_level);
    }

    // The earlier baseline (orthorhombic cell) row by row, and q/p at state A of every sample.
    if (!opt["--baseline"].empty() && !in.samples.empty()) {
      const nlohmann::json before = validation::read_json_file(opt["--baseline"]);  // errors name the file
      v["baseline.file"] = opt["--baseline"];
      v["baseline.table"] = validation::baseline_table(before, in.rows, in.samples);
    }
    if (!in.samples.empty()) v["state_a.table"] = validation::state_a_table(in.samples);
    if (!in.samples.empty()) v["shear_control.table"] = validation::shear_control_table(in.samples);

    // Figures: the README's table, every figure with its note.
    const std::string notes = read_text(fs::path(opt["--templates"]) / "figure_notes.tsv");
    if (notes.empty()) throw std::runtime_error(opt["--templates"] + "/figure_notes.tsv is missing or empty");
    {
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
      std::string figs;
      for (const std::string& png : pngs)
        figs += "\n![" + png.substr(0, png.size() - 4) + "](figures/" + png + ")\n\n" + validation::figure_note(notes, png, v) + "\n";
      v["figures"] = figs.empty() ? "\n*No figures drawn yet (`reports/make_figures.sh`).*\n" : figs;
      std::sort(renders.begin(), renders.end());
      std::string r;
      for (const std::string& png : renders) r += "![" + png.substr(0, png.size() - 4) + "](figures/" + png + ")\n";
      v["renders"] = r;
      v["energy.figure"] = fs::exists(report / "figures" / "fig_energy.png") ? "yes" : "";
    }
    // The energy balance of the chosen sample's runs, and the note on the energy figure.
    {
      std::vector<std::pair<std::string, const validation::Columns*>> runs;
      for (const auto& [name, c] : energy_series) runs.emplace_back(name, &c);
      v["energy.table"] = runs.empty() ? "" : validation::energy_table(runs);
      v["energy.note"] = validation::figure_note(notes, "fig_energy.png", v);
    }

    const std::string tmpl = read_text(fs::path(opt["--templates"]) / "index.md");
    if (tmpl.empty()) throw std::runtime_error(opt["--templates"] + "/index.md is missing or empty");
    std::string text = validation::fill(tmpl, v);
    // Sections whose inputs are not here (the paper study's results, on a machine that ran only
    // some studies) from the previous report, said so in the header.
    if (!opt["--previous"].empty()) {
      const std::string previous = read_text(opt["--previous"]);
      if (previous.empty()) throw std::runtime_error("--previous '" + opt["--previous"] + "' is missing or empty");
      validation::check_previous_report(previous, text, "--previous '" + opt["--previous"] + "'");
      std::vector<std::string> kept;
      validation::keep_sections_without_inputs(text, previous, kept);
      if (!kept.empty()) {
        std::smatch m;
        v["kept_from"] = std::regex_search(previous, m, std::regex(R"(Generated on (\S+))")) ? m[1].str() : "date not written";
        v["kept"] = "\"" + validation::joined(kept, "\", \"") + "\"";
        kept.clear();
        text = validation::keep_sections_without_inputs(validation::fill(tmpl, v), previous, kept);
      }
    }
    dem::write_file_atomically((report / "index.md").string(), text);
    std::fprintf(stderr, "report written to %s (%zu sample(s) of %s%s)\n", (report / "index.md").c_str(), in.samples.size(),
                 shown(results).c_str(), missing.empty() ? "" : (", " + std::to_string(missing.size()) + " result files missing").c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "report: %s\n", dem::describe_failure(e).c_str());
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) { return dem::guarded_main("report", [&] { return tool_main(argc, argv); }); }
