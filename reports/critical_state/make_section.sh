#!/usr/bin/env bash
# The critical-state study's table and figures from its results, with the ensemble at μ = 0.5 and
# the rate convergence when their studies have run.
# Usage: reports/critical_state/make_section.sh [BIN_DIR|-] [RESULTS_DIR] [OUT_DIR] [ENSEMBLE_DIR] [RATES_DIR]
#   BIN_DIR      holds compare-runs (default, or "-": build/bin of this repository)
#   RESULTS_DIR  the study's results with the pipeline's runs.tsv (default: results/critical_state/paper)
#   OUT_DIR      receives table.md, critical_state.dat, pi_plane.dat, ensemble.dat, rates.dat,
#                rates_qs.dat, values.gp and phi_mu.png, e_cn_mu.png, pi_plane.png, rates.png (drawn
#                by the static reports/gnuplot/critical_state_*.gp) (default: reports/critical_state)
#   ENSEMBLE_DIR pipeline/studies/critical_state_ensemble.yaml's results, passed as --ensemble when it
#                has a runs.tsv (default: results/critical_state_ensemble/paper)
#   RATES_DIR    pipeline/studies/critical_state_rates.yaml's results, passed as --rates when it has
#                a runs.tsv (default: results/critical_state_rates/paper); the literature's rows
#                (reference_data/literature.yaml) are passed beside it, so that the quasi-static φ is
#                set beside the reference a row judges at the study's rate
# A study that has not run (no runs.tsv) is said so and is not an error: the report says so too.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:--}
[ "$bin" != - ] || bin=$here/build/bin
results=${2:-$here/results/critical_state/paper}
out=${3:-$here/reports/critical_state}
ensemble=${4:-$here/results/critical_state_ensemble/paper}
rates=${5:-$here/results/critical_state_rates/paper}
if [ ! -f "$results/runs.tsv" ]; then
  echo "critical-state: no results in $results yet (make critical-state)" >&2
  exit 0
fi
extra=()
if [ -f "$ensemble/runs.tsv" ]; then extra+=(--ensemble "$ensemble"); else echo "critical-state: no ensemble results in $ensemble yet (make critical-state)" >&2; fi
if [ -f "$rates/runs.tsv" ]; then extra+=(--rates "$rates" --references "$here/reference_data/literature.yaml"); else echo "critical-state: no rates results in $rates yet (make critical-state)" >&2; fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out/rates.png"   # drawn again below only with --rates (table.md links it only then)
"$bin/compare-runs" critical-state "$results" "$out" ${extra[@]+"${extra[@]}"}   # table.md, *.dat, values.gp
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
figures="phi_mu e_cn_mu pi_plane"
[ -f "$rates/runs.tsv" ] && figures="$figures rates"
for figure in $figures; do
  (cd "$out" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$here/reports/gnuplot/critical_state_$figure.gp")
done
echo "critical-state section written to $out" >&2
