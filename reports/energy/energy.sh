#!/usr/bin/env bash
# The energy balance table of the runs of one sample (issue 7), from the data files figure-data
# wrote beside the figures (fig_energy_<run>.dat; reports/make_figures.sh). The figure itself is
# reports/gnuplot/fig_energy.gp.
# Usage: reports/energy/energy.sh FIG_DIR [MAX_ENERGY_ERROR] > energy.md
#   MAX_ENERGY_ERROR: the runs' numerics.max_energy_error (figure-data settings), quoted in the text
# Columns of the data files (engine/README.md, "Energy balance"): time, work_by_cell,
# dissipated_by_damping, dissipated_by_friction (cumulative from each run's first step),
# elastic_energy_normal, elastic_energy_tangential, kinetic_energy_centred, energy_closure_error.
set -euo pipefail
[ $# = 1 ] || [ $# = 2 ] || { echo "usage: $0 FIG_DIR [MAX_ENERGY_ERROR] > energy.md" >&2; exit 2; }
figs=$1
limit=$(awk -v x="${2:-}" 'BEGIN { if (x == "") print "its limit"; else printf "%g %%", 100 * x }')
shopt -s nullglob
files=("$figs"/fig_energy_*.dat)
echo "| run | work by the cell (J) | stored at the end (J) | dissipated by damping | dissipated by sliding | largest closure error | closure error at the end |"
echo "|---|---|---|---|---|---|---|"
[ ${#files[@]} -gt 0 ] || echo "| (no run with an energy balance) | | | | | | |"
for f in "${files[@]}"; do
  run=$(basename "$f" .dat); run=${run#fig_energy_}
  awk -v run="$run" '!/^#/ && NF == 8 {
      w = $2; d = $3; s = $4; stored = $5 + $6 + $7; e = $8; last = e; if (e > worst) worst = e }
    END {
      printf "| %s | %.4g | %.3g | %.4g J (%.1f %%) | %.4g J (%.1f %%) | %.1e | %.1e |\n", run, w, stored,
             d, (w > 0 ? 100 * d / w : 0), s, (w > 0 ? 100 * s / w : 0), worst, last }' "$f"
done
echo
echo "Percentages are of the work by the cell; a sample starts each run with the elastic energy of its"
echo "preparation, so stored + dissipated can exceed the work. Closure error = |E_in − (E_stored + E_dissipated)| / E_in"
echo "with E_in = energy stored at the first step + work by the cell; a run stops if it exceeds"
echo "\`numerics.max_energy_error\` ($limit)."
