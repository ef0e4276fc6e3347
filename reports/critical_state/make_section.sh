#!/usr/bin/env bash
# The critical-state study's table and figures from its results.
# Usage: reports/critical_state/make_section.sh [BIN_DIR|-] [RESULTS_DIR] [OUT_DIR]
#   BIN_DIR      holds compare-runs (default, or "-": build/bin of this repository)
#   RESULTS_DIR  the study's results with the pipeline's runs.tsv (default: results/critical_state/paper)
#   OUT_DIR      receives table.md, critical_state.dat, pi_plane.dat, values.gp and phi_mu.png,
#                e_cn_mu.png, pi_plane.png (drawn by the static reports/gnuplot/critical_state_*.gp)
#                (default: reports/critical_state)
# A study that has not run (no runs.tsv) is said so and is not an error: the report says so too.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:--}
[ "$bin" != - ] || bin=$here/build/bin
results=${2:-$here/results/critical_state/paper}
out=${3:-$here/reports/critical_state}
if [ ! -f "$results/runs.tsv" ]; then
  echo "critical-state: no results in $results yet (make critical-state)" >&2
  exit 0
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
"$bin/compare-runs" critical-state "$results" "$out"   # table.md, critical_state.dat, pi_plane.dat, values.gp
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
for figure in phi_mu e_cn_mu pi_plane; do
  (cd "$out" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$here/reports/gnuplot/critical_state_$figure.gp")
done
echo "critical-state section written to $out" >&2
