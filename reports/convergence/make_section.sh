#!/usr/bin/env bash
# The convergence study's tables and figure: from its results when they are here (and then its
# summary.json, committed beside them), else re-drawn from that committed summary.
# Usage: reports/convergence/make_section.sh [BIN_DIR] [RESULTS_DIR] [OUT_DIR] [VALIDATION_JSON]
#   BIN_DIR          holds compare-runs (default: build/bin of this repository)
#   RESULTS_DIR      the study's results with the pipeline's runs.tsv (default: results/convergence/paper)
#   OUT_DIR          receives summary.json (from results only), table.md, errors.dat, front.dat and
#                    error_vs_time.png (drawn by the static reports/gnuplot/convergence_error_vs_time.gp)
#                    (default: reports/convergence)
#   VALIDATION_JSON  the paper study's validation, its inconsistent rows read against the budget
#                    (default: reports/validation.json)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/bin}
results=${2:-$here/results/convergence/paper}
out=${3:-$here/reports/convergence}
validation=${4:-$here/reports/validation.json}
mkdir -p "$out"
out=$(cd "$out" && pwd)
args=()
[ -f "$validation" ] && args+=(--validation "$validation")
if [ -f "$results/runs.tsv" ]; then
  # the pipeline runs one thread per run when it runs as many runs as cores (make convergence)
  "$bin/compare-runs" convergence "$results" "$out" --threads 1 "${args[@]}"
elif [ -f "$out/summary.json" ]; then
  echo "convergence: no results in $results; re-drawn from $out/summary.json" >&2
  "$bin/compare-runs" convergence --summary "$out/summary.json" "$out" "${args[@]}"
else
  echo "convergence: neither results in $results nor $out/summary.json (make convergence)" >&2
  exit 1
fi
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
(cd "$out" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$here/reports/gnuplot/convergence_error_vs_time.gp")
echo "convergence section written to $out" >&2
