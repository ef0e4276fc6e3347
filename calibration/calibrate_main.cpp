// calibrate: infers scene parameters from references (curves of a lab test, or a reference file's
// rows) by running parameter sets of a study through the pipeline (calibration/README.md).
//   calibrate CALIBRATION.yaml [--profile P] [-j N] [--threads T] [--executor local|slurm] [--plan] [--truth FILE]
//             [--ledger-engine] [--ledger-verify K] [--ledger-only]
//   calibrate lab-curve --x COLUMN --y COLUMN --at X1,X2,... --out FILE.csv RESULT.h5...
//   calibrate truth CALIBRATION.yaml RESULT.h5 --out FILE.json
//   calibrate variant CALIBRATION.yaml [--set NAME]
//   calibrate rekey CALIBRATION.yaml --references-then OLD.yaml
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "calibrate.hpp"
#include "config/study_config.hpp"
#include "ledger.hpp"
#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "io/atomic_file.hpp"
#include "io/failure.hpp"
#include "posterior_report.hpp"
#include "sets.hpp"
#include "study/ensemble.hpp"
#include "study/json_file.hpp"
#include "study/series.hpp"

namespace {
namespace fs = std::filesystem;
using calibration::CurvePoint;

// Writes `text` to `file` whole (io/atomic_file.hpp), its folder made if missing.
void write_whole(const std::string& file, const std::string& text) {
  if (fs::path(file).has_parent_path()) fs::create_directories(fs::path(file).parent_path());
  dem::write_file_atomically(file, text);
}

int parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  return -1;
}

// A synthetic lab curve: y at each x, mean and sd over the given results (specimens).
int lab_curve(int argc, char** argv) {
  std::string x, y, out;
  std::vector<double> at;
  std::vector<std::string> results;
  CLI::App app{"calibrate lab-curve: a reference curve made by the engine (a demonstration's synthetic lab data): y at "
               "each x on each result's last stage, their mean and sd over the results (the specimens), and with 3 or more "
               "each specimen's y (specimen_1, ...)"};
  app.add_option("--x", x, "the time-series column along the curve (e.g. strain_3)")->required();
  app.add_option("--y", y, "the time-series column (e.g. q_over_p)")->required();
  app.add_option("--at", at, "the x values of the points")->required()->delimiter(',');
  app.add_option("--out", out, "the CSV written")->required();
  app.add_option("results", results, "the result files (the specimens)")->required();
  if (const int rc = parse(app, argc, argv); rc >= 0) return rc;
  calibration::CurveRow row;
  row.x = x, row.y = y;
  for (const double v : at) row.points.push_back({v, 0, 0});
  std::vector<std::vector<double>> ys(at.size());
  for (const std::string& r : results) {
    const validation::TestResult t = validation::load_test(r, "test");
    const auto values = calibration::curve_on_run(row, t);
    for (std::size_t j = 0; j < at.size(); ++j) {
      if (!values[j]) throw dem::ConfigError(r + ": its " + x + " never reaches " + validation::format_number(at[j]) + " on its last stage");
      ys[j].push_back(*values[j]);
    }
  }
  std::ostringstream s;
  s << "# made by the engine (calibrate lab-curve): " << y << " against " << x << ", mean and sd over " << results.size()
    << " specimen(s):";
  for (const std::string& r : results) s << " " << fs::path(r).parent_path().filename().string() << "/" << fs::path(r).filename().string();
  // With 3 specimens or more, each one's y too: the calibration takes their correlation from point to point.
  const bool each = results.size() >= 3;
  s << "\n" << x << "," << y << ",sd";
  for (std::size_t i = 0; each && i < results.size(); ++i) s << ",specimen_" << i + 1;
  s << "\n";
  for (std::size_t j = 0; j < at.size(); ++j) {
    const validation::Spread sp = validation::spread(ys[j]);
    s << validation::format_number(at[j]) << "," << validation::format_number(sp.mean) << "," << validation::format_number(sp.sd);
    for (std::size_t i = 0; each && i < ys[j].size(); ++i) s << "," << validation::format_number(ys[j][i]);
    s << "\n";
  }
  write_whole(out, s.str());
  std::printf("%s: %zu points over %zu specimen(s)\n", out.c_str(), at.size(), results.size());
  return 0;
}

// The true parameters of a synthetic reference, read from the scene a result ran.
int truth(int argc, char** argv) {
  std::string file, result, out;
  CLI::App app{"calibrate truth: the calibration's parameters as a result's scene set them (the hidden truth of a "
               "synthetic reference), as JSON for calibrate --truth"};
  app.add_option("calibration", file, "the calibration file")->required();
  app.add_option("result", result, "a result made with the true parameters")->required();
  app.add_option("--out", out, "the JSON written")->required();
  if (const int rc = parse(app, argc, argv); rc >= 0) return rc;
  const calibration::Calibration c = calibration::read_calibration(file);
  nlohmann::json j;
  j["from"] = fs::relative(fs::absolute(result), fs::absolute(out).parent_path()).string();
  for (const auto& [name, value] : calibration::parameters_of_result(c, result)) j["parameters"][name] = value;
  write_whole(out, j.dump(1) + "\n");
  std::printf("%s: %s\n", out.c_str(), j["parameters"].dump().c_str());
  return 0;
}

// A posterior that has not settled (the calibration still iterating, or stopped by max_iterations)
// gives a set all the same, with a warning on stderr naming what is missing.
void warn_if_unsettled(const nlohmann::json& j, const calibration::Calibration& c, const std::string& posterior) {
  if (j.value("converged", false)) return;
  const int done = static_cast<int>(j.value("iterations", nlohmann::json::array()).size());
  const std::size_t sets = j.value("sets", nlohmann::json::array()).size();
  const std::string why = j.value("stop_reason", std::string("no stop reason recorded"));
  if (done < c.max_iterations)
    std::fprintf(stderr, "calibrate variant: warning: %s is of an unfinished calibration: %d of at most %d iterations done, up to %d "
                 "more (%d sets) still to run (%s); this set is the best of the %zu scored so far\n", posterior.c_str(), done,
                 c.max_iterations, c.max_iterations - done, (c.max_iterations - done) * c.batch, why.c_str(), sets);
  else
    std::fprintf(stderr, "calibrate variant: warning: %s is of a calibration whose posterior did not settle (%s); this set is the "
                 "best of the %zu scored, not of a settled posterior\n", posterior.c_str(), why.c_str(), sets);
}

// One set of a finished calibration as a study variant (YAML), to run it elsewhere: at another
// size, on more samples (e.g. the best set at the paper's size).
int variant(int argc, char** argv) {
  std::string file, set_name;
  CLI::App app{"calibrate variant: a set of a finished calibration (default: its best) as a study variant, one YAML line "
               "for a study's variants: list"};
  app.add_option("calibration", file, "the calibration file")->required();
  app.add_option("--set", set_name, "the set's name in posterior.json (default: best_set)");
  if (const int rc = parse(app, argc, argv); rc >= 0) return rc;
  const calibration::Calibration c = calibration::read_calibration(file);
  const std::string posterior = (fs::path(c.report) / "posterior.json").string();
  const nlohmann::json j = validation::read_json_file(posterior);
  warn_if_unsettled(j, c, posterior);
  if (set_name.empty()) {
    if (!j.contains("best_set") || !j["best_set"].contains("name")) throw dem::ConfigError(posterior + ": best_set.name is missing");
    set_name = j["best_set"]["name"].get<std::string>();
  }
  const auto sets = j.value("sets", nlohmann::json::array());
  const auto found = std::find_if(sets.begin(), sets.end(), [&](const nlohmann::json& s) { return s.value("name", "") == set_name; });
  if (found == sets.end()) throw dem::ConfigError(posterior + ": no set named '" + set_name + "'");
  calibration::ParameterSet s;
  s.name = set_name;
  s.u.resize(static_cast<Eigen::Index>(c.parameters.size()));
  for (std::size_t k = 0; k < c.parameters.size(); ++k) {
    const calibration::Parameter& p = c.parameters[k];
    if (!(*found)["values"].contains(p.name) || !(*found)["values"][p.name].is_number())
      throw dem::ConfigError(posterior + ": set " + set_name + " has no value of " + p.name + " (another calibration file?)");
    s.u(static_cast<Eigen::Index>(k)) = p.unit_of((*found)["values"][p.name].get<double>());
  }
  std::printf("%s\n", pipeline::variant_yaml(calibration::variant_of(c, s)).c_str());
  return 0;
}

// A calibration's ledgers of schema 1 rekeyed to the references as parsed (ledger.hpp: rekey_ledger).
int rekey(int argc, char** argv) {
  std::string file, then_file;
  CLI::App app{"calibrate rekey: a ledger of scored sets written before ledgers were keyed on the references as parsed (schema 1, "
               "keyed on the files' bytes) rekeyed, once the references it was scored against parse as the calibration's do now"};
  app.add_option("calibration", file, "the calibration file")->required();
  app.add_option("--references-then", then_file, "the reference file the ledgers were scored against (e.g. checked out from version control)")
      ->required();
  if (const int rc = parse(app, argc, argv); rc >= 0) return rc;
  const calibration::Calibration c = calibration::read_calibration(file);
  const std::string profile = c.sizes.empty() ? pipeline::load_study(c.study).default_profile().name : c.sizes.back().profile;
  const calibration::References then = calibration::read_references(then_file, profile);
  const calibration::References now = calibration::read_references(c.references, profile);
  std::vector<std::string> ledgers{(fs::path(c.report) / "scored_sets.json").string()};
  for (std::size_t k = 1; k < c.sizes.size(); ++k) ledgers.push_back((fs::path(c.report) / ("scored_sets." + c.sizes[k].profile + ".json")).string());
  for (const std::string& ledger : ledgers)
    if (fs::exists(ledger)) std::printf("calibrate rekey: %s: %d sets rekeyed\n", ledger.c_str(), calibration::rekey_ledger(ledger, then, now));
  return 0;
}

int calibrate(int argc, char** argv) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string file, truth_file;
  calibration::RunOptions o;
  o.jobs = cores;
  int threads = 0;
  CLI::App app{"calibrate: infers scene parameters from references (curves, or a reference file's rows): draws parameter "
               "sets, runs them through the pipeline (finished runs reused), weights them by their misfit, until the "
               "posterior stops moving; writes posterior.json, section.md and the figures' data to the report folder"};
  app.add_option("calibration", file, "the calibration file (YAML)")->required();
  app.add_option("--profile", o.profile, "the study's profile (default: paper if declared, else the first)");
  app.add_option("-j", o.jobs, "runs at once (default: the number of cores)")->check(CLI::Range(1, 256));
  app.add_option("--threads", threads, "threads inside each run (default: cores / runs at once)")->check(CLI::Range(1, 256));
  app.add_option("--executor", o.executor, "local or slurm (the study's slurm: options)")->check(CLI::IsMember({"local", "slurm"}));
  app.add_flag("--plan", o.plan_only, "replay the iterations the ledgers and finished runs cover, then print what the next one runs and what max_iterations would cost; run nothing, write nothing");
  app.add_option("--truth", truth_file, "a demonstration's true parameters (calibrate truth), set beside the posterior once it is final");
  app.add_option("--dem", o.dem, "the engine (default: dem beside this program)");
  app.add_flag("--ledger-engine", o.ledger_engine,
               "take the ledgers' scores of sets whose scenes are unchanged even if another engine scored them (the report names "
               "that engine and how many sets it scored)");
  app.add_option("--ledger-verify", o.ledger_verify,
                 "take the ledgers' sets whose runs hash otherwise here (their scenes' text or engine changed) once this many of "
                 "them, spread over each ledger, run again here score bit for bit as the ledger has them (the report says which "
                 "and how many were taken); a difference stops the calibration")
      ->check(CLI::Range(1, 1000));
  app.add_flag("--ledger-only", o.ledger_only, "run nothing: every set from the ledgers (a replay); a set they lack is an error");
  app.footer("calibrate lab-curve --help and calibrate truth --help: the demonstration's synthetic references; calibrate variant --help: "
             "a finished calibration's set as a study variant.");
  if (const int rc = parse(app, argc, argv); rc >= 0) return rc;
  o.threads = threads > 0 ? threads : std::max(1, cores / o.jobs);
  if (o.dem.empty()) o.dem = (fs::canonical("/proc/self/exe").parent_path() / "dem").string();
  const calibration::Calibration c = calibration::read_calibration(file);
  std::map<std::string, double> truth_values;
  if (!truth_file.empty()) {
    const nlohmann::json t = validation::read_json_file(truth_file);
    for (const auto& p : c.parameters) {
      if (!t.contains("parameters") || !t["parameters"].contains(p.name) || !t["parameters"][p.name].is_number())
        throw dem::ConfigError(truth_file + ": parameters." + p.name + " is missing or not a number");
      truth_values[p.name] = t["parameters"][p.name].get<double>();
    }
  }
  // One calibration at a time in a report folder, from its first run to its last report.
  std::unique_ptr<dem::FileLock> lock;
  if (!o.plan_only)
    lock = pipeline::lock_folder(c.report, ".calibrate.lock", "calibrate",
                                 "two would each write its ledger of scored sets and its posterior, and one would be lost");
  o.after_iteration = [&](const calibration::Outcome& so_far) {
    calibration::write_report(so_far, {});
    std::printf("[calibrate] the posterior so far in %s/posterior.json\n", c.report.c_str());
    std::fflush(stdout);
  };
  const std::optional<calibration::Outcome> outcome = calibration::run_calibration(c, o);
  if (!outcome) return 0;
  calibration::write_report(*outcome, truth_values);
  std::printf("[calibrate] %s: %s; posterior in %s/posterior.json\n", c.name.c_str(), outcome->stop_reason.c_str(), c.report.c_str());
  return 0;
}

int tool_main(int argc, char** argv) {
  try {
    if (argc > 1 && std::string(argv[1]) == "lab-curve") return lab_curve(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "truth") return truth(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "variant") return variant(argc - 1, argv + 1);
    if (argc > 1 && std::string(argv[1]) == "rekey") return rekey(argc - 1, argv + 1);
    return calibrate(argc, argv);
  } catch (const dem::ConfigError& e) {
    std::fprintf(stderr, "calibrate: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "calibrate: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) { return dem::guarded_main("calibrate", [&] { return tool_main(argc, argv); }); }
