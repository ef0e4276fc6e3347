#!/usr/bin/env bash
# The report's figures (Figs. 1-14 and the energy balance) from a study's results: build/bin/figure-data
# writes the data of every figure into FIG_DIR (figNN_*.dat, columns named with units, and values.gp:
# the numbers the scripts read, the paper's from reference_data/paper.yaml), then gnuplot draws each
# figure with its static script in reports/gnuplot/ (all load reports/gnuplot/style.gp).
# Usage: reports/make_figures.sh BIN_DIR RESULTS_DIR FIG_DIR [SAMPLE]
#   BIN_DIR      holds figure-data (build/bin)
#   RESULTS_DIR  a study's results: an ensemble (seed<N>/ folders) or one sample's folder
#   SAMPLE       the sample whose runs the single-run figures show (default: the first, seed1);
#                Figures 7, 10 and 11 show the mean and spread of every sample
# Missing results are noted on stderr and their curves left out ("Test N: not run" in the key).
# Every file this script owns in FIG_DIR (fig[0-9]*, fig_energy*, values.gp) is deleted first.
# Exit status 1 if figure-data or gnuplot failed on a figure (the other figures are still drawn).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
case $# in
  3|4) bin=$1; results=$2; figs=$3; sample=${4:-} ;;
  *) echo "usage: $0 BIN_DIR RESULTS_DIR FIG_DIR [SAMPLE]" >&2; exit 2 ;;
esac
[ -x "$bin/figure-data" ] || { echo "error: '$bin/figure-data' not found (make tools)" >&2; exit 2; }
[ -d "$results" ] || { echo "error: results folder '$results' does not exist" >&2; exit 2; }
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
mkdir -p "$figs"
rm -f "$figs"/fig[0-9]* "$figs"/fig_energy* "$figs"/values.gp
"$bin/figure-data" figures "$results" "$figs" ${sample:+--sample "$sample"} --references "$here/reference_data/paper.yaml"
err=$(mktemp)
trap 'rm -f "$err"' EXIT
status=0
for gp in "$here"/reports/gnuplot/fig*.gp; do
  # Each script runs in the figure folder; GNUPLOT_LIB finds style.gp and panel_fig09.gp.
  if ! (cd "$figs" && GNUPLOT_LIB="$here/reports/gnuplot" gnuplot "$gp") 2> "$err"; then
    echo "error: gnuplot failed for $(basename "$gp"):" >&2; cat "$err" >&2; status=1
  else  # warnings but those of curves and panels without data (runs not run)
    grep -v -e 'Skipping data file' -e 'No valid data points' -e '^ *$' -e 'warning: empty' -e 'empty . range' "$err" | sed "s/^/  gnuplot ($(basename "$gp")): /" >&2 || true
  fi
done
echo "figures written to $figs" >&2
exit $status
