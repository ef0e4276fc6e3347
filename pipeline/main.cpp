// pipeline: runs a study (every density x test) with the dem engine, reusing finished results.
//   pipeline STUDY.yaml... [--profile paper|quick] [--out DIR] [-j N] [--threads T] [--dem PATH] [--plan]
//            [--executor local|slurm]
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "exec/scheduler.hpp"
#include "exec/slurm.hpp"
#include "plan/run_plan.hpp"

namespace {

const char* usage =
    "usage: pipeline STUDY.yaml... [--profile paper|quick] [--out DIR] [-j N] [--threads T] [--dem PATH] [--plan]\n"
    "                [--executor local|slurm]\n"
    "  --profile  study size (default paper)        --out  results folder (default: the study's output/PROFILE;\n"
    "                                                      with one study file only)\n"
    "  -j         runs at once (default: cores)     --dem  the engine (default: dem beside this program)\n"
    "  --threads  threads inside each run (default: cores / runs at once, at least 1; results do not depend on it)\n"
    "  --plan     write the resolved scenes and list the runs, run nothing\n"
    "  --executor local: runs here as child processes (default); slurm: one sbatch job per run, options\n"
    "             in the study's slurm: mapping (default: the study's executor: key, else local)\n"
    "A run whose result is complete with the same input hash (resolved scene, engine version and the\n"
    "sample it starts from) is reused, so an interrupted study continues where it stopped. Several\n"
    "study files share the -j slots: one study's runs fill the cores while another's last runs finish.\n";

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

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<std::string> study_files;
  std::string profile = "paper", out, dem;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int jobs = cores;
  int threads = 0;  // 0: cores / jobs
  bool plan_only = false;
  std::string executor;  // "": the studies' executor key, else local
  bool local_slots_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") { std::fputs(usage, stdout); return 0; }
    if (a == "--profile" && i + 1 < argc) profile = argv[++i];
    else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--dem" && i + 1 < argc) dem = argv[++i];
    else if (a == "--executor" && i + 1 < argc) {
      executor = argv[++i];
      if (executor != "local" && executor != "slurm") {
        std::fprintf(stderr, "pipeline: --executor must be local or slurm, got '%s'\n", executor.c_str());
        return 2;
      }
    } else if (a == "-j" && i + 1 < argc) {
      local_slots_given = true;
      try { jobs = std::stoi(argv[++i]); } catch (const std::exception&) { jobs = 0; }
      if (jobs < 1 || jobs > 256) { std::fprintf(stderr, "pipeline: -j must be an integer in [1, 256]\n"); return 2; }
    } else if (a == "--threads" && i + 1 < argc) {
      local_slots_given = true;
      try { threads = std::stoi(argv[++i]); } catch (const std::exception&) { threads = 0; }
      if (threads < 1 || threads > 256) { std::fprintf(stderr, "pipeline: --threads must be an integer in [1, 256]\n"); return 2; }
    } else if (a == "--plan") plan_only = true;
    else if (!a.empty() && a[0] != '-') study_files.push_back(a);
    else { std::fprintf(stderr, "pipeline: unexpected argument '%s'\n%s", a.c_str(), usage); return 2; }
  }
  if (threads == 0) threads = std::max(1, cores / jobs);
  if (study_files.empty()) { std::fprintf(stderr, "pipeline: need a study file\n%s", usage); return 2; }
  if (study_files.size() > 1 && !out.empty()) {
    std::fprintf(stderr, "pipeline: --out names the results folder of one study; give one study file with it\n");
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
    for (const std::string& study_file : study_files) {
      const pipeline::Study& study = studies.emplace_back(pipeline::load_study(study_file));
      const std::string& study_out = outs.emplace_back(
          fs::absolute(out.empty() ? fs::path(study.output) / profile : fs::path(out)).lexically_normal().string());
      plans.push_back({study.name, pipeline::plan_study(study, study.profile(profile), study_out, version)});
    }
    const std::vector<pipeline::PlannedRun> runs = pipeline::join_studies(plans);
    if (executor.empty()) executor = chosen_executor(studies);
    std::vector<std::unique_ptr<dem::FileLock>> locks;  // one pipeline per results folder, until this one ends
    for (const std::string& o : outs) locks.push_back(pipeline::lock_results_folder(o));
    for (std::size_t i = 0; i < plans.size(); ++i) {
      pipeline::write_scenes(plans[i].runs);
      pipeline::write_manifest(plans[i].runs, studies[i], outs[i]);
      if (!plan_only)
        std::printf("[pipeline] study '%s', profile %s, engine %s, results in %s\n", studies[i].name.c_str(),
                    profile.c_str(), version.c_str(), outs[i].c_str());
    }
    if (plan_only) {
      for (const auto& r : runs)
        std::printf("%-24s %-9s %.3g particle-steps  %s\n", r.name.c_str(),
                    pipeline::up_to_date(r.result, r.hash)                       ? "reuse"
                    : r.may_fail && pipeline::recorded_stop(r.result, r.hash) ? "stopped"
                    : r.copy_of >= 0                                             ? "copy"
                                                                                : "run",
                    r.cost, r.scene_file.c_str());
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
