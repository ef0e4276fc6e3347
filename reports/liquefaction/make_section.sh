#!/usr/bin/env bash
# The liquefaction studies' table and figures from their results (the loose and the medium sample).
# Usage: reports/liquefaction/make_section.sh [BIN_DIR|-] [OUT_DIR] [RESULTS_DIR...]
#   BIN_DIR      holds compare-runs (default, or "-": build/bin of this repository)
#   OUT_DIR      receives table.md, csr_nl.dat, csr_nl_summary.dat, ru.dat, values.gp and csr_nl.png, ru.png (drawn by
#                the static reports/gnuplot/liquefaction_*.gp) (default: reports/liquefaction)
#   RESULTS_DIR  the studies' results, each with the pipeline's runs.tsv (default:
#                results/liquefaction_loose/paper results/liquefaction_medium/paper)
# Folders without a runs.tsv (a study that has not run) are left out and said so; with none left
# the section is not written, and that is not an error: the report says so.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:--}
[ "$bin" != - ] || bin=$here/build/bin
out=${2:-$here/reports/liquefaction}
shift $(($# < 2 ? $# : 2))
[ $# -gt 0 ] || set -- "$here/results/liquefaction_loose/paper" "$here/results/liquefaction_medium/paper"
folders=()
for dir in "$@"; do
  if [ -f "$dir/runs.tsv" ]; then folders+=("$dir"); else echo "liquefaction: no results in $dir yet (make liquefaction)" >&2; fi
done
[ ${#folders[@]} -gt 0 ] || exit 0
mkdir -p "$out"
out=$(cd "$out" && pwd)
"$bin/compare-runs" liquefaction "$out" "${folders[@]}"   # table.md, csr_nl.dat, csr_nl_summary.dat, ru.dat, values.gp
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
for figure in csr_nl ru; do
  (cd "$out" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$here/reports/gnuplot/liquefaction_$figure.gp")
done
echo "liquefaction section written to $out" >&2
