#!/usr/bin/env bash
# The energy balance of every run of a study (issue 7): a markdown table and a figure.
# Usage: reports/energy/energy.sh [DEM] RESULTS_DIR OUT_DIR
#   writes OUT_DIR/energy.md (the table, included by make_report.sh) and
#   OUT_DIR/figures/fig_energy.{png,gp} with the data of each curve beside it (fig_energy_<run>.dat)
# Columns are those of engine/README.md ("Energy balance"): work_by_cell, dissipated_by_damping,
# dissipated_by_friction (cumulative from each run's first step), elastic_energy_*,
# kinetic_energy_centred and energy_closure_error.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
case $# in
  2) dem=$here/build/bin/dem; results=$1; out=$2 ;;
  3) dem=$1; results=$2; out=$3 ;;
  *) echo "usage: $0 [DEM] RESULTS_DIR OUT_DIR" >&2; exit 2 ;;
esac
[ -x "$dem" ] || { echo "error: engine binary '$dem' not found or not executable" >&2; exit 2; }
[ -d "$results" ] || { echo "error: results folder '$results' does not exist" >&2; exit 2; }
mkdir -p "$out/figures"
figs=$(cd "$out/figures" && pwd)
rm -f "$figs"/fig_energy*
columns="time work_by_cell dissipated_by_damping dissipated_by_friction elastic_energy_normal elastic_energy_tangential kinetic_energy_centred energy_closure_error"

shopt -s nullglob
{
  echo "| run | work by the cell (J) | stored at the end (J) | dissipated by damping | dissipated by sliding | largest closure error | closure error at the end |"
  echo "|---|---|---|---|---|---|---|"
  for f in "$results"/*.h5; do
    run=$(basename "$f" .h5)
    # Only results written by an engine with the energy balance have these columns.
    if ! "$dem" table "$f" $columns > "$figs/fig_energy_$run.dat" 2> /dev/null; then
      rm -f "$figs/fig_energy_$run.dat"
      echo "| $run | (no energy columns: written by an older engine) | | | | | |"
      continue
    fi
    awk -v run="$run" 'NR > 1 && NF == 8 {
        w = $2; d = $3; s = $4; stored = $5 + $6 + $7; e = $8; last = e; if (e > worst) worst = e }
      END {
        printf "| %s | %.4g | %.3g | %.4g J (%.1f %%) | %.4g J (%.1f %%) | %.1e | %.1e |\n", run, w, stored,
               d, (w > 0 ? 100 * d / w : 0), s, (w > 0 ? 100 * s / w : 0), worst, last }' "$figs/fig_energy_$run.dat"
  done
  echo
  echo "Percentages are of the work by the cell; a sample starts each run with the elastic energy of its"
  echo "preparation, so stored + dissipated can exceed the work. Closure error = |E_in − (E_stored + E_dissipated)| / E_in"
  echo "with E_in = energy stored at the first step + work by the cell; a run stops if it exceeds"
  echo "\`numerics.max_energy_error\` (5 %)."
} > "$out/energy.md"

# Figure: the cumulative balance of Test 1 of each density.
{
  cat << GP
set terminal pngcairo size 1500,450 font ",11" enhanced
set output "$figs/fig_energy.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 font ",9"
set multiplot layout 1,3 title "Energy balance of Test 1: the work by the cell against what was dissipated and stored (from the first row after the start; the dashed curve must cover the black one)"
set xlabel "time (s)"
set xtics font ",9"
set ylabel "energy (J)"
GP
  for d in loose medium dense; do
    dat=$figs/fig_energy_${d}_test1.dat
    echo "set title '$d'"
    if [ -s "$dat" ]; then
      cat << GP
stored0 = NaN
first(x) = (stored0 != stored0 ? stored0 = x : 0, stored0)
plot '$dat' every ::2 u 1:2 w l lw 2 lc rgb "#000000" t "work by the cell", \\
     '' every ::2 u 1:3 w l lw 2 lc rgb "#1f77b4" t "dissipated by damping", \\
     '' every ::2 u 1:4 w l lw 2 lc rgb "#d62728" t "dissipated by sliding", \\
     '' every ::2 u 1:(\$5+\$6+\$7-first(\$5+\$6+\$7)) w l lw 2 lc rgb "#2ca02c" t "change of stored energy", \\
     '' every ::2 u 1:(\$3+\$4+\$5+\$6+\$7-stored0) w l lw 2 dt 2 lc rgb "#ff7f0e" t "dissipated + change of stored"
GP
    else
      echo "set xrange [0:1]; set yrange [0:1]; set label 99 'not run' at graph 0.5, 0.5 center; plot NaN notitle; unset label 99; set autoscale"
    fi
  done
  echo "unset multiplot"
} > "$figs/fig_energy.gp"
sed -i "s#$figs/##g" "$figs/fig_energy.gp"   # paths relative to the figure folder, where it runs
(cd "$figs" && gnuplot fig_energy.gp)
