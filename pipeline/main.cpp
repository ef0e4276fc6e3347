// pipeline: runs a study (every density x test) with the dem engine, reusing finished results.
//   pipeline STUDY.yaml... [--profile NAME] [--out DIR] [-j N] [--threads T] [--dem PATH] [--plan]
//            [--executor local|slurm]   (arguments through CLI11; --help lists them)
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "config/study_config.hpp"
#include "config/study_copy.hpp"
#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "exec/slurm.hpp"
#include "plan/plan_cost.hpp"
#include "plan/run_plan.hpp"
#include "io/failure.hpp"

namespace {

const char* footer =
    "A run whose result is complete with the same input hash (resolved scene, engine version and the\n"
    "sample it starts from) is reused, so an interrupted study continues where it stopped. Several\n"
    "study files share the -j slots: one study's runs fill the cores while another's last runs finish.\n"
    "Paths on the command line are relative to the current folder; paths in a study file to that file.\n"
    "pipeline new MY.yaml --from paper: a study of your own, copied from a shipped one (pipeline new --help).";

// `pipeline new OUT.yaml --from STUDY [--force] [--output DIR] [--variant YAML]...`: a copy of a
// shipped study (or of any study file) whose paths resolve from OUT's folder, named after OUT's
// stem, its results in DIR, with the variants given (config/study_copy.hpp).
int new_study(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::string to, from;
  bool force = false;
  pipeline::CopyChanges changes;
  CLI::App app{"pipeline new: writes a study of your own, a copy of a shipped study (or of any study file) whose paths "
               "resolve from the new file's folder, named after the new file, with its results in results/NAME beside it"};
  app.add_option("study", to, "the new study file (.yaml)")->required();
  app.add_option("--from", from, "a shipped study's name (paper, decisions, ...) or a study file")->required();
  app.add_flag("--force", force, "replace an existing file");
  app.add_option("--output", changes.output, "its results folder, a path from the current folder (default: results/NAME beside it)");
  app.add_option("--variant", changes.variants,
                 "a variant of its own, one YAML mapping (e.g. the line `calibrate variant` prints); may be given several times")
      ->allow_extra_args(false);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  const fs::path bin = fs::canonical("/proc/self/exe").parent_path();
  try {
    const std::string source = pipeline::find_study(
        from, {(bin / "../share/cyclic-triax/pipeline/studies").lexically_normal().string(), PIPELINE_SOURCE_STUDIES});
    pipeline::write_study_copy(source, to, force, changes);
    std::printf("%s: a copy of %s (name %s); try: pipeline %s --plan\n", to.c_str(), source.c_str(),
                fs::path(to).stem().string().c_str(), to.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}

// The executor the study files name (pipeline --executor wins): local if none does; files that
// name different ones are refused, since one call runs all their runs together.
std::string chosen_executor(const std::vector<pipeline::Study>& studies) {
  std::string chosen, by;
  for (const pipeline::Study& s : studies) {
    if (!s.executor) continue;
    if (!chosen.empty() && *s.executor != chosen)
      throw dem::ConfigError(s.file + ": executor: " + *s.executor + ", but " + by + " says " + chosen +
                             "; run them apart or choose one with --executor local|slurm");
    chosen = *s.executor, by = s.file;
  }
  return chosen.empty() ? "local" : chosen;
}

std::string duration_text(double s) {
  char buf[64];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

// `--plan`: each run with what it will do and its estimated particle-steps, then what the runs
// still to do cost: the critical path and the wall time on 1, 2, 16 and 64 cores (summarize_plan).
void print_plan(const std::vector<pipeline::PlannedRun>& runs, const pipeline::PlanThroughput& throughput) {
  const pipeline::PlanSummary plan = pipeline::summarize_plan(runs, throughput);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const pipeline::PlannedRun& r = runs[i];
    std::printf("%-24s %-9s %.3g particle-steps (%s)  %s\n", r.name.c_str(), plan.action[i].c_str(), r.cost,
                r.cost_basis.c_str(), r.scene_file.c_str());
  }
  std::printf("\nto run: %.3g particle-steps in %d of %zu runs (reused results and copies cost nothing)\n", plan.particle_steps,
              plan.to_run, runs.size());
  const double per_s = throughput.particle_steps_per_s;
  std::string chain;
  for (int k : plan.critical.runs) chain += (chain.empty() ? "" : " -> ") + runs[static_cast<std::size_t>(k)].name;
  std::printf("critical path (the longest chain of runs, each starting from the one before): %.3g particle-steps, "
              "%s: %s\n", plan.critical.cost, duration_text(plan.critical.cost / per_s).c_str(),
              chain.empty() ? "nothing to run" : chain.c_str());
  std::printf("estimated wall time, one run per core at %.3g particle-steps/s:", per_s);
  for (const auto& [cores, seconds] : plan.wall_time_s)
    std::printf(" %d core%s %s;", cores, cores > 1 ? "s" : "", duration_text(seconds).c_str());
  std::printf("\n(throughput: %s; particle-steps: recorded, a finished run's own; as RUN, those of a finished run of "
              "the same scene (another sample); model, a stress stage from its hold criteria (pipeline/plan/run_plan.cpp), "
              "a liquefaction at its stage's duration)\n",
              throughput.from.c_str());
}

}  // namespace

// The tool; main runs it under guarded_main (a file system error names its path, exit 1).
int tool_main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc > 1 && std::string(argv[1]) == "new") return new_study(argc - 1, argv + 1);
  std::vector<std::string> study_files;
  std::string profile, out, dem;  // profile "": each study's paper profile if it declares one, else its first
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int jobs = cores;
  int threads = 0;  // 0: cores / jobs
  bool plan_only = false;
  std::string executor;  // "": the studies' executor key, else local
  double throughput = pipeline::default_throughput;
  CLI::App app{"pipeline: plans and runs the studies (every density x test x variant x seed) with dem"};
  app.add_option("studies", study_files, "the study files (YAML)")->required();
  app.add_option("--profile", profile, "a profile the studies declare (default: paper if declared, else the first)");
  app.add_option("--out", out, "results folder (default: the study's output/PROFILE; with one study file only)");
  CLI::Option* jobs_opt = app.add_option("-j", jobs, "runs at once (default: the number of cores)")->check(CLI::Range(1, 256));
  CLI::Option* threads_opt = app.add_option("--threads", threads,
      "threads inside each run (default: cores / runs at once, at least 1; results do not depend on it)")
      ->check(CLI::Range(1, 256));
  std::vector<std::string> only;
  app.add_option("--variant", only,
      "run only this variant of the study (repeat for several; with one study file): the others' results stay as they are, "
      "and runs.tsv lists only these");
  app.add_option("--dem", dem, "the engine (default: dem beside this program)");
  app.add_flag("--plan", plan_only,
      "write the resolved scenes, list the runs with their particle-steps, the critical path and the wall time "
      "on 1, 2, 16 and 64 cores; run nothing");
  CLI::Option* throughput_opt =
      app.add_option("--throughput", throughput,
                     "particle-steps per second of one run on one core, for --plan's estimates, 1e3 to 1e12 particle-steps/s "
                     "(default: what the finished runs in the results folder recorded, else the engine's make bench figure)");
  app.add_option("--executor", executor,
      "local: runs here as child processes; slurm: one sbatch job per run, options in the study's slurm: mapping "
      "(default: the study's executor: key, else local)")
      ->check(CLI::IsMember({"local", "slurm"}));
  app.footer(footer);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (!(throughput >= 1e3 && throughput <= 1e12)) {  // 1e-300 gave estimates of 63 digits
    std::fprintf(stderr, "pipeline: --throughput %g particle-steps/s is outside 1000 to 1e+12 particle-steps/s (one run on one "
                 "core; the default, %g, is the engine's on 8,000 spheres)\n", throughput, pipeline::default_throughput);
    return 2;
  }
  const bool local_slots_given = jobs_opt->count() > 0 || threads_opt->count() > 0;
  if (threads == 0) threads = std::max(1, cores / jobs);
  if (study_files.size() > 1 && !out.empty()) {
    std::fprintf(stderr, "pipeline: --out names the results folder of one study; give one study file with it\n");
    return 2;
  }
  if (study_files.size() > 1 && !only.empty()) {
    std::fprintf(stderr, "pipeline: --variant names variants of one study; give one study file with it\n");
    return 2;
  }
  if (std::error_code ec; !out.empty() && fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    std::fprintf(stderr, "pipeline: --out '%s' is not a folder (the results folder of the study: made if missing)\n", out.c_str());
    return 2;
  }
  if (dem.empty()) dem = (fs::canonical("/proc/self/exe").parent_path() / "dem").string();
  const std::string version = pipeline::engine_version(dem);  // no shell sees the path
  if (version.empty()) { std::fprintf(stderr, "pipeline: cannot run the engine '%s --source-hash'\n", dem.c_str()); return 2; }
  try {
    // Every study is planned (its scenes checked) and the studies joined (no two runs writing one
    // result) before anything is written or run.
    std::vector<pipeline::Study> studies;
    std::vector<std::string> outs;
    std::vector<pipeline::StudyPlan> plans;
    std::vector<std::string> profiles;
    for (const std::string& study_file : study_files) {
      pipeline::Study& study = studies.emplace_back(pipeline::load_study(study_file));
      if (!only.empty()) pipeline::keep_variants(study, only);
      const pipeline::Profile& p = profile.empty() ? study.default_profile() : study.profile(profile);
      profiles.push_back(p.name);
      const std::string& study_out = outs.emplace_back(
          fs::absolute(out.empty() ? fs::path(study.output) / p.name : fs::path(out)).lexically_normal().string());
      plans.push_back({study.name, pipeline::plan_study(study, p, study_out, version)});
    }
    std::vector<pipeline::PlannedRun> runs = pipeline::join_studies(plans);
    const std::optional<double> recorded_throughput = pipeline::use_recorded_costs(runs);
    if (executor.empty()) executor = chosen_executor(studies);
    std::vector<std::unique_ptr<dem::FileLock>> locks;  // one pipeline per results folder, until this one ends
    for (const std::string& o : outs) locks.push_back(pipeline::lock_results_folder(o));
    for (std::size_t i = 0; i < plans.size(); ++i) {
      pipeline::write_scenes(plans[i].runs);
      // A plan runs nothing, so it lists no runs: a runs.tsv is what tells the other tools (validate,
      // compare-runs, report) that a study ran here, and one written by a plan made the report take
      // a folder of scenes for the study's results.
      if (!plan_only) pipeline::write_manifest(plans[i].runs, studies[i], outs[i], version);
      if (!plan_only)
        std::printf("[pipeline] study '%s', profile %s, engine %s, results in %s\n", studies[i].name.c_str(),
                    profiles[i].c_str(), version.c_str(), outs[i].c_str());
    }
    if (plan_only) {
      print_plan(runs, pipeline::plan_throughput(throughput_opt->count() > 0 ? std::optional<double>(throughput) : std::nullopt,
                                                 recorded_throughput,
                                                 fs::path(studies.front().output).parent_path().string(), version));
      return 0;
    }
    pipeline::Outcome o;
    if (executor == "slurm") {
      if (local_slots_given)
        std::printf("[pipeline] -j and --threads are the local executor's: with slurm the cluster decides how many runs "
                    "run at once, each with slurm.cpus_per_run threads\n");
      // Run i gets its own study's options (join_studies keeps each study's runs together, in order).
      std::vector<pipeline::SlurmOptions> options;
      for (std::size_t k = 0; k < plans.size(); ++k) options.insert(options.end(), plans[k].runs.size(), studies[k].slurm);
      o = pipeline::slurm::execute(runs, options, fs::absolute(dem).lexically_normal().string());
    } else {
      o = pipeline::execute(runs, dem, jobs, threads);
    }
    if (o.interrupted) return 130;
    std::printf("[pipeline] done in %.1f min: %d ran, %d reused, %d failed, %d blocked", o.wall_time_s / 60, o.ran,
                o.reused, o.failed, o.blocked);
    if (o.copied > 0) std::printf(", %d copied (the same inputs as another run)", o.copied);
    if (o.stopped + o.skipped > 0)  // may_fail runs: outcomes, not failures
      std::printf("; %d stopped with a message and %d skipped, as allowed (may_fail)", o.stopped, o.skipped);
    std::printf("\n");
    return o.failed + o.blocked > 0 ? 1 : 0;
  } catch (const pipeline::slurm::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const dem::ConfigError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

int main(int argc, char** argv) { return dem::guarded_main("pipeline", [&] { return tool_main(argc, argv); }); }
