#!/usr/bin/env bash
# The convergence study's tables and figure from its results.
# Usage: reports/convergence/make_section.sh [BIN_DIR] [RESULTS_DIR] [OUT_DIR]
#   BIN_DIR      holds compare-runs (default: build/bin of this repository)
#   RESULTS_DIR  the study's results with the pipeline's runs.tsv (default: results/convergence/paper)
#   OUT_DIR      receives table.md, errors.dat, front.dat and error_vs_time.png (drawn by the static
#                reports/gnuplot/convergence_error_vs_time.gp)
#                (default: reports/convergence)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/bin}
results=${2:-$here/results/convergence/paper}
out=${3:-$here/reports/convergence}
mkdir -p "$out"
out=$(cd "$out" && pwd)
"$bin/compare-runs" convergence "$results" "$out"   # table.md, errors.dat, front.dat
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
rm -f "$out/error_vs_time.gp"   # the script is static now: reports/gnuplot/convergence_error_vs_time.gp
(cd "$out" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$here/reports/gnuplot/convergence_error_vs_time.gp")
echo "convergence section written to $out" >&2
