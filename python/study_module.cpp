// Study in cyclic_triax._engine: a study planned and run by the pipeline's library (what
// `pipeline STUDY.yaml [--plan]` calls: pipeline/plan, pipeline/exec) and judged by validate's
// (validation/judge/judge_study.hpp); cyclic_triax/study.py builds the Python class on it.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "exec/scheduler.hpp"
#include "judge/judge_study.hpp"
#include "judge/rows.hpp"
#include "judge/verdicts.hpp"
#include "module.hpp"
#include "plan/plan_cost.hpp"
#include "plan/run_plan.hpp"
#include "study/ensemble.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace {

// A study's runs planned as `pipeline STUDY --profile P [--variant V]... [--out DIR]` plans them,
// its resolved scenes and runs.tsv written (as --plan writes them), under the results folder's
// lock (held by the returned lock until it goes).
struct Planned {
  pipeline::Study study;
  std::string profile, out, version;
  std::vector<pipeline::PlannedRun> runs;
  std::optional<double> recorded_throughput;
  std::unique_ptr<dem::FileLock> lock;
};

Planned plan(const std::string& file, const std::string& profile, const std::vector<std::string>& variants,
             const std::string& out, const std::string& dem) {
  Planned p;
  p.version = pipeline::engine_version(dem);
  if (p.version.empty()) ct_python::raise(ct_python::run_error, "cannot run the engine '" + dem + " --source-hash'");
  p.study = pipeline::load_study(file);
  if (!variants.empty()) pipeline::keep_variants(p.study, variants);
  const pipeline::Profile& prof = profile.empty() ? p.study.default_profile() : p.study.profile(profile);
  p.profile = prof.name;
  p.out = fs::absolute(out.empty() ? fs::path(p.study.output) / prof.name : fs::path(out)).lexically_normal().string();
  p.runs = pipeline::join_studies({{p.study.name, pipeline::plan_study(p.study, prof, p.out, p.version)}});
  p.recorded_throughput = pipeline::use_recorded_costs(p.runs);
  p.lock = pipeline::lock_results_folder(p.out);
  pipeline::write_scenes(p.runs);
  pipeline::write_manifest(p.runs, p.study, p.out, p.version);
  return p;
}

// A study file's names: what Study shows before anything is planned.
py::dict study_info(const std::string& file) {
  const pipeline::Study s = pipeline::load_study(file);
  py::dict d;
  d["file"] = s.file, d["name"] = s.name, d["output"] = s.output, d["default_profile"] = s.default_profile().name;
  py::list profiles, densities, tests, variants;
  for (const auto& p : s.profiles) profiles.append(p.name);
  for (const auto& x : s.densities) densities.append(x.name);
  for (const auto& t : s.tests) tests.append(t.name);
  for (const auto& v : s.variants) variants.append(v.name);
  d["profiles"] = profiles, d["densities"] = densities, d["tests"] = tests, d["variants"] = variants;
  return d;
}

// `pipeline --plan`'s numbers (plan_cost.hpp summarize_plan), with the throughput chosen as it
// chooses it (`throughput` given: its --throughput).
py::dict study_plan(const std::string& file, const std::string& profile, const std::vector<std::string>& variants,
                    const std::string& out, const std::string& dem, std::optional<double> throughput) {
  if (throughput && !(*throughput >= 1e3 && *throughput <= 1e12))
    ct_python::raise(ct_python::config_error, "throughput must be in [1000, 1e+12] particle-steps/s, got " + std::to_string(*throughput));
  const Planned p = plan(file, profile, variants, out, dem);
  const pipeline::PlanSummary s = pipeline::summarize_plan(
      p.runs, pipeline::plan_throughput(throughput, p.recorded_throughput, fs::path(p.study.output).parent_path().string(), p.version));
  py::list runs;
  for (std::size_t i = 0; i < p.runs.size(); ++i) {
    const pipeline::PlannedRun& r = p.runs[i];
    py::dict d;
    d["name"] = r.name, d["action"] = s.action[i], d["particle_steps"] = r.cost, d["cost_basis"] = r.cost_basis;
    d["to_run"] = s.cost[i], d["spheres"] = r.spheres, d["density"] = r.density, d["test"] = r.test;
    d["variants"] = r.variants, d["seed"] = r.seed, d["scene_file"] = r.scene_file, d["result"] = r.result;
    runs.append(d);
  }
  py::list chain;
  for (int k : s.critical.runs) chain.append(p.runs[static_cast<std::size_t>(k)].name);
  py::dict wall;
  for (const auto& [cores, seconds] : s.wall_time_s) wall[py::int_(cores)] = seconds;
  py::dict d;
  d["study"] = p.study.name, d["profile"] = p.profile, d["results"] = p.out, d["engine"] = p.version;
  d["runs"] = runs, d["to_run"] = s.to_run, d["particle_steps"] = s.particle_steps;
  d["critical_path"] = chain, d["critical_path_particle_steps"] = s.critical.cost;
  d["throughput"] = s.throughput.particle_steps_per_s, d["throughput_from"] = s.throughput.from;
  d["wall_time_s"] = wall;
  return d;
}

// `pipeline STUDY -j jobs --threads threads` with the local executor, the GIL released while it runs.
py::dict study_run(const std::string& file, const std::string& profile, const std::vector<std::string>& variants,
                   const std::string& out, const std::string& dem, int jobs, int threads) {
  if (jobs < 1 || jobs > 256) ct_python::raise(ct_python::config_error, "jobs must be in [1, 256], got " + std::to_string(jobs));
  if (threads < 1 || threads > 256) ct_python::raise(ct_python::config_error, "threads must be in [1, 256], got " + std::to_string(threads));
  const Planned p = plan(file, profile, variants, out, dem);
  pipeline::Outcome o;
  {
    py::gil_scoped_release release;
    o = pipeline::execute(p.runs, dem, jobs, threads);
  }
  py::dict d;
  d["results"] = p.out, d["profile"] = p.profile;
  d["ran"] = o.ran, d["reused"] = o.reused, d["failed"] = o.failed, d["blocked"] = o.blocked, d["copied"] = o.copied;
  d["stopped"] = o.stopped, d["skipped"] = o.skipped, d["wall_time"] = o.wall_time_s;
  return d;
}

py::object optional_number(const std::optional<double>& x) { return x ? py::object(py::float_(*x)) : py::object(py::none()); }

// validate --results DIR --references FILE --profile P, judged by the same functions
// (read_references, judge_study), returned as data: each row with its verdict, the counts and what
// is missing. Nothing is written.
py::dict study_validate(const std::string& results, const std::string& references, const std::string& profile) {
  if (!fs::is_directory(results))
    ct_python::raise(ct_python::config_error, "results '" + results + "' " + (fs::exists(results) ? "is not a folder" : "does not exist") +
                                                  " (a study's results folder: run the study first)");
  const validation::References refs = validation::read_references(references, profile);
  if (!refs.profiles.empty() && !refs.profiles.count(profile) && profile != "paper") {
    std::string known = "paper (every row as written)";
    for (const std::string& p : refs.profiles) known += ", " + p;
    ct_python::raise(ct_python::config_error, "profile '" + profile + "': no row of " + references + " has it; its profiles: " + known);
  }
  std::optional<validation::StudyResults> read;
  std::vector<validation::Judged> judged;
  {
    py::gil_scoped_release release;
    judged = validation::judge_study(results, refs.rows, read);
  }
  const validation::VerdictCounts count = validation::count_verdicts(judged);
  py::list rows;
  for (const validation::Judged& j : judged) {
    const validation::RowResult& r = j.result;
    py::dict d;
    d["name"] = j.row.name, d["quantity"] = j.row.quantity, d["check"] = j.row.check, d["rule"] = j.row.rule;
    d["verdict"] = validation::to_string(r.verdict), d["must_pass"] = j.row.must_pass;
    d["reference"] = j.row.reference, d["tolerance"] = j.row.tolerance;
    d["statement"] = validation::statement(j.row);
    // As validation.json has them (verdicts.cpp json_row): no mean without a value, no sd without two.
    d["mean"] = r.valued > 0 ? py::object(py::float_(r.spread.mean)) : py::object(py::none());
    d["sd"] = r.valued > 1 ? py::object(py::float_(r.spread.sd)) : py::object(py::none());
    d["low"] = optional_number(r.spread.low), d["high"] = optional_number(r.spread.high);
    d["samples"] = r.valued, d["holds"] = r.holds, d["warnings"] = r.warnings;
    py::list values;
    for (const auto& s : r.samples) values.append(optional_number(s.measured.value));
    d["values"] = values;
    rows.append(d);
  }
  py::dict d;
  d["rows"] = rows, d["label"] = refs.label;
  d["consistent"] = count.of(validation::Verdict::Consistent), d["inconsistent"] = count.of(validation::Verdict::Inconsistent);
  d["not_judged"] = count.of(validation::Verdict::NotJudged), d["must_pass_inconsistent"] = count.must_pass_failed;
  d["samples"] = read->samples(), d["missing_results"] = read->missing(), d["missing_samples"] = read->missing_samples();
  return d;
}

}  // namespace

namespace ct_python {

void bind_study(py::module_& m) {
  m.def("study_info", &study_info, py::arg("file"));
  m.def("study_plan", &study_plan, py::arg("file"), py::arg("profile"), py::arg("variants"), py::arg("out"), py::arg("dem"),
        py::arg("throughput"));
  m.def("study_run", &study_run, py::arg("file"), py::arg("profile"), py::arg("variants"), py::arg("out"), py::arg("dem"),
        py::arg("jobs"), py::arg("threads"));
  m.def("study_validate", &study_validate, py::arg("results"), py::arg("references"), py::arg("profile"));
}

}  // namespace ct_python
