#include "plan/plan_cost.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <string>
#include <limits>

#include "io/hdf5.hpp"
#include "plan/reuse.hpp"
#include "plan/runs_manifest.hpp"

namespace pipeline {

std::optional<ResultCost> result_cost(const std::string& result) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(result);
    dem::h5::Handle state = dem::h5::open_group(f, "state");
    ResultCost c;
    c.particle_steps = static_cast<double>(dem::h5::get_int_attribute(state, "step")) *
                       static_cast<double>(dem::h5::shape(state, "radius").at(0));
    if (dem::h5::has_attribute(f, "wall_time_s")) c.wall_s = dem::h5::get_double_attribute(f, "wall_time_s");
    return c;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<double> use_recorded_costs(std::vector<PlannedRun>& runs) {
  struct Family {
    double steps = 0;  // summed over its recorded runs
    int recorded = 0;
    std::string first;  // the first of them
  };
  const auto key = [](const PlannedRun& r) {
    std::string k = r.family + "\n" + std::to_string(r.spheres);
    for (const std::string& v : r.variants) k += "\n" + v;
    return k;
  };
  std::map<std::string, Family> families;
  std::vector<std::optional<ResultCost>> recorded(runs.size());
  double particle_steps = 0, wall_s = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::error_code ec;
    if (runs[i].spheres <= 0 || !std::filesystem::is_regular_file(runs[i].result, ec)) continue;
    recorded[i] = result_cost(runs[i].result);
    if (!recorded[i]) continue;
    Family& f = families[key(runs[i])];
    f.steps += recorded[i]->particle_steps / runs[i].spheres, ++f.recorded;
    if (f.first.empty()) f.first = runs[i].name;
    if (recorded[i]->wall_s && *recorded[i]->wall_s > 0) particle_steps += recorded[i]->particle_steps, wall_s += *recorded[i]->wall_s;
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (recorded[i]) {
      runs[i].cost = recorded[i]->particle_steps, runs[i].cost_basis = "recorded";
    } else if (const auto f = families.find(key(runs[i])); f != families.end()) {
      runs[i].cost = runs[i].spheres * f->second.steps / f->second.recorded, runs[i].cost_basis = "as " + f->second.first;
    }
  }
  if (wall_s > 0) return particle_steps / wall_s;
  return std::nullopt;
}

std::optional<MachineThroughput> recorded_throughput_under(const std::string& root, const std::string& engine_version) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return std::nullopt;
  MachineThroughput m;
  double particle_steps = 0, wall_s = 0;
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it.depth() >= 3) it.disable_recursion_pending();
    if (it->path().filename() != "runs.tsv" || !it->is_regular_file(ec)) continue;
    RunsManifest manifest;
    try {
      manifest = read_runs_manifest(it->path());
    } catch (const std::exception&) {
      continue;  // not a manifest the pipeline wrote: nothing recorded there
    }
    if (manifest.engine_source != engine_version) continue;
    int counted = 0;
    for (const ManifestEntry& e : manifest.entries) {
      const std::optional<ResultCost> cost = result_cost(e.result);
      if (!cost || !cost->wall_s || *cost->wall_s <= 0) continue;
      particle_steps += cost->particle_steps, wall_s += *cost->wall_s, ++counted;
    }
    m.runs += counted, m.studies += counted > 0;
  }
  if (wall_s <= 0) return std::nullopt;
  m.particle_steps_per_s = particle_steps / wall_s;
  return m;
}

std::vector<double> run_costs(const std::vector<PlannedRun>& runs, const std::vector<bool>& todo) {
  std::vector<double> cost(runs.size(), 0.0);
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (todo[i] && runs[i].copy_of < 0) cost[i] = runs[i].cost;
  return cost;
}

CriticalPath critical_path(const std::vector<PlannedRun>& runs, const std::vector<double>& cost) {
  // Runs come after the run they start from (plan_study, join_studies), so one pass suffices;
  // the loop below does not rely on it: it follows depends_on to the root.
  CriticalPath best;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    CriticalPath p;
    for (int k = static_cast<int>(i); k >= 0; k = runs[static_cast<std::size_t>(k)].depends_on) {
      p.cost += cost[static_cast<std::size_t>(k)];
      if (cost[static_cast<std::size_t>(k)] > 0) p.runs.insert(p.runs.begin(), k);
      if (p.runs.size() > runs.size()) break;  // a cycle cannot be planned; never loop for ever
    }
    if (p.cost > best.cost) best = p;
  }
  return best;
}

double estimated_wall_time_s(const std::vector<PlannedRun>& runs, const std::vector<double>& cost, int cores,
                             double throughput) {
  const std::size_t n = runs.size();
  // The particle-steps still behind each run: its own and its longest chain of dependants.
  std::vector<double> tail(cost);
  for (std::size_t pass = 0; pass < n; ++pass) {  // relax until stable (chains are short)
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      const int d = runs[i].depends_on;
      if (d >= 0 && tail[static_cast<std::size_t>(d)] < cost[static_cast<std::size_t>(d)] + tail[i]) {
        tail[static_cast<std::size_t>(d)] = cost[static_cast<std::size_t>(d)] + tail[i];
        changed = true;
      }
    }
    if (!changed) break;
  }
  std::vector<double> end(n, -1);  // when each run ends; -1: not started
  std::vector<double> busy;         // end times of the runs on the cores
  double now = 0;
  std::size_t done = 0;
  while (done < n) {
    // Start ready runs, longest tail first, while a core is free.
    while (static_cast<int>(busy.size()) < cores) {
      int pick = -1;
      for (std::size_t i = 0; i < n; ++i) {
        if (end[i] >= 0) continue;
        const int d = runs[i].depends_on;
        if (d >= 0 && !(end[static_cast<std::size_t>(d)] >= 0 && end[static_cast<std::size_t>(d)] <= now)) continue;
        if (pick < 0 || tail[i] > tail[static_cast<std::size_t>(pick)]) pick = static_cast<int>(i);
      }
      if (pick < 0) break;
      end[static_cast<std::size_t>(pick)] = now + cost[static_cast<std::size_t>(pick)] / throughput;
      busy.push_back(end[static_cast<std::size_t>(pick)]);
      ++done;
    }
    if (busy.empty()) break;  // nothing can start (a dependency that never runs): stop
    // Advance to the next end.
    const auto next = std::min_element(busy.begin(), busy.end());
    now = *next;
    busy.erase(next);
  }
  double last = 0;
  for (double e : end) last = std::max(last, e);
  return last;
}

PlanThroughput plan_throughput(std::optional<double> given, std::optional<double> recorded, const std::string& results_root,
                               const std::string& engine_version) {
  if (given) return {*given, "--throughput"};
  if (recorded) return {*recorded, "the finished runs' recorded particle-steps over their wall time"};
  if (const auto machine = recorded_throughput_under(results_root, engine_version))
    return {machine->particle_steps_per_s,
            "none of these runs has finished yet: what " + std::to_string(machine->runs) + " finished runs of this engine in " +
                std::to_string(machine->studies) + " results folders beside them recorded, particle-steps over wall time"};
  return {default_throughput,
          "the engine's, measured by make bench on this project's 2-core machine (reports/bench.md: 8,000 "
          "spheres, one run per core); set yours with --throughput"};
}

PlanSummary summarize_plan(const std::vector<PlannedRun>& runs, const PlanThroughput& throughput) {
  PlanSummary s;
  s.throughput = throughput;
  std::vector<bool> todo(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PlannedRun& r = runs[i];
    s.action.push_back(up_to_date(r.result, r.hash)                        ? "reuse"
                       : r.may_fail && recorded_stop(r.result, r.hash)     ? "stopped"
                       : r.copy_of >= 0                                    ? "copy"
                                                                           : "run");
    todo[i] = s.action.back() == "run";
    s.to_run += todo[i] ? 1 : 0;
  }
  s.cost = run_costs(runs, todo);
  for (double c : s.cost) s.particle_steps += c;
  s.critical = critical_path(runs, s.cost);
  for (int cores : {1, 2, 16, 64})
    s.wall_time_s.emplace_back(cores, estimated_wall_time_s(runs, s.cost, cores, throughput.particle_steps_per_s));
  return s;
}

}  // namespace pipeline
