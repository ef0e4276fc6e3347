#include "plan/plan_cost.hpp"

#include <algorithm>
#include <limits>

namespace pipeline {

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

}  // namespace pipeline
