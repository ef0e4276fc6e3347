#!/usr/bin/env bash
# Figures 3-14 of the paper from the cyclic-test results (SPEC sections 3 and 4).
# Usage: [ENSEMBLE=DIR] reports/make_figures.sh [DEM] RESULTS_DIR FIG_DIR
#   DEM          the engine binary (default: build/bin/dem of this repository)
#   RESULTS_DIR  holds <density>_test<N>.h5, density in {loose, medium, dense}, N in 1..5: one sample
#                (of an ensemble, the sample the figures of single runs show)
#   ENSEMBLE     optional: the per-cycle statistics of an ensemble (build/bin/ensemble-cycles);
#                Figures 7, 10 and 11 then show the ensemble mean with a band of one standard deviation
#   FIG_DIR      receives figNN_*.png, the data file of every curve (figNN_<density>_test<N>.dat ...)
#                and the gnuplot script of every figure (figNN_*.gp)
# Missing results (not run yet, or still running as .h5.partial) are noted on stderr; their curves are
# left out (the legend says "not run") and a panel with no data at all says "not run".
# Every file this script owns in FIG_DIR (fig03* ... fig14*) is deleted first, so no stale data remains.
# See reports/figures/README.md for what each figure shows and which columns it uses.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
case $# in
  2) dem=$here/build/bin/dem; results=$1; figs=$2 ;;
  3) dem=$1; results=$2; figs=$3 ;;
  *) echo "usage: $0 [DEM] RESULTS_DIR FIG_DIR" >&2; exit 2 ;;
esac
[ -x "$dem" ] || { echo "error: engine binary '$dem' not found or not executable" >&2; exit 2; }
[ -d "$results" ] || { echo "error: results folder '$results' does not exist" >&2; exit 2; }
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
mkdir -p "$figs"
figs=$(cd "$figs" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
note() { echo "note: $*" >&2; }

densities=(loose medium dense)
tests=(1 2 3 4 5)
letters=(A B C D E F)
# Colours: tests (black, orange, purple, teal, brown); densities as in Fig. 2 (red, green, blue).
declare -A tcol=([1]="#000000" [2]="#ff7f0e" [3]="#9467bd" [4]="#17a2b8" [5]="#8c564b")
declare -A dcol=([loose]="#d62728" [medium]="#2ca02c" [dense]="#1f77b4")
declare -A cn_paper=([loose]=4.09 [medium]=4.88 [dense]=5.94)   # paper, before shearing

rm -f "$figs"/fig0[3-9]* "$figs"/fig1[0-4]*

# ---------------------------------------------------------------------------------------------
# Read every result once: time series -> $tmp/<d><t>.ts, legs -> $tmp/<d><t>.legs, plus a sed
# script per table that turns column names into awk fields ($N), so that `pick` can be given
# conditions and expressions written with the column names of engine/README.md.
declare -A have=()
for d in "${densities[@]}"; do
  for t in "${tests[@]}"; do
    f=$results/${d}_test$t.h5
    if [ -f "$f" ]; then
      if "$dem" table "$f" > "$tmp/$d$t.ts" 2> "$tmp/err" && "$dem" table "$f" --legs > "$tmp/$d$t.legs" 2>> "$tmp/err"; then
        have[$d$t]=1
        for kind in ts legs; do
          head -n 1 "$tmp/$d$t.$kind" | tr -s ' \t' '\n\n' |
            awk 'NF && $0 != "#" { n++; printf "s/\\<%s\\>/$%d/g\n", $0, n }' > "$tmp/$d$t.$kind.sed"
        done
      else
        note "cannot read $f ($(head -c 200 "$tmp/err")), skipped"
      fi
    elif [ -f "$f.partial" ]; then
      note "$f is still running (.partial), skipped"
    else
      note "$f not found, skipped"
    fi
  done
done
[ ${#have[@]} -gt 0 ] || note "no results at all in $results: every panel will say 'not run'"

# pick KEY KIND COND EXPR... : rows of table KEY.KIND (ts or legs) where COND holds, printing EXPRs.
pick() {
  local key=$1 kind=$2 cond=$3
  shift 3
  local IFS=,
  local prog="NR > 1 && ($cond) { print $* }"
  awk -v OFS='\t' -v OFMT='%.9g' -v CONVFMT='%.9g' "$(sed -f "$tmp/$key.$kind.sed" <<< "$prog")" "$tmp/$key.$kind"
}
# last cycle present in a result
last_cycle() { pick "$1" ts 1 cycle | awk 'BEGIN { m = 0 } $1 > m { m = $1 } END { print m }'; }
has_rows() { [ -s "$1" ] && grep -qv '^#' "$1"; }

# ---------------------------------------------------------------------------------------------
# gnuplot helpers. A panel is written as: settings, then `plot` with the elements collected in
# PLOT; `add` adds a data curve, or a "not run" legend entry if the data file has no rows.
PLOT=()
ANY=0
panel_reset() { PLOT=(); ANY=0; }
add() {   # add FILE USING WITH TITLE
  if has_rows "$1"; then PLOT+=("'$1' u $2 $3 t \"$4\""); ANY=1
  else PLOT+=("NaN $3 t \"$4: not run\""); fi
}
add_raw() { PLOT+=("$1"); }   # always-present element (reference lines ...)
add_notitle() { has_rows "$1" && { PLOT+=("'$1' u $2 $3 notitle"); ANY=1; }; return 0; }   # FILE USING WITH; nothing if absent
add_data() { has_rows "$1" && { PLOT+=("'$1' u $2 $3 t \"$4\""); ANY=1; }; return 0; }   # nothing if absent
# emit the plot command of the current panel; an empty panel says "not run" and gets ranges [0:1]
# unless called as `panel_plot fixed` (the panel's ranges are already fixed)
panel_plot() {
  local IFS=$'\n'
  if [ "$ANY" = 0 ]; then
    echo "set label 99 'not run' at graph 0.5, 0.4 center front font ',18' tc rgb '#888888'"
    [ "${1:-}" = fixed ] || echo "set xrange [0:1]; set yrange [0:1]"
  fi
  local nokey=0
  [ ${#PLOT[@]} -gt 0 ] || { PLOT=("NaN notitle"); nokey=1; echo "set key off"; }
  local body
  body=$(printf '%s, \\\n  ' "${PLOT[@]}")
  echo "plot ${body%, \\*}"
  echo "unset label 99"
  [ $nokey = 0 ] || echo "set key on"
}
preamble() {   # preamble OUT.png WIDTH HEIGHT
  cat << GP
set terminal pngcairo size $2,$3 font ",11" enhanced
set output "$1"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
GP
}
# π-plane decorations: principal axes (1 up, 2 lower-left, 3 lower-right), square frame
pi_axes() {   # pi_axes HALF_WIDTH
  local r=$1
  cat << GP
set size ratio -1
set xrange [-$r:$r]; set yrange [-$r:$r]
set arrow 1 from 0,0 to 0,0.83*$r head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 2 from 0,0 to -0.83*$r*0.8660254,-0.83*$r*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 3 from 0,0 to 0.83*$r*0.8660254,-0.83*$r*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set label 1 "σ_1" at 0,0.9*$r center font ",12" tc rgb "#555555"
set label 2 "σ_2" at -0.87*$r*0.8660254,-0.93*$r*0.5 right font ",12" tc rgb "#555555"
set label 3 "σ_3" at 0.87*$r*0.8660254,-0.93*$r*0.5 left font ",12" tc rgb "#555555"
GP
}
pi_axes_off() { echo "unset arrow 1; unset arrow 2; unset arrow 3; unset label 1; unset label 2; unset label 3; set size noratio"; }
run_gp() {   # run_gp NAME : runs $figs/NAME.gp, reports failures without stopping the other figures
  # Paths in the script relative to the figure folder (it runs there): nothing of the machine that
  # drew it ends up in the committed scripts.
  sed -i "s#$figs/##g" "$figs/$1.gp"
  if ! (cd "$figs" && gnuplot "$1.gp") 2> "$tmp/gp.err"; then
    echo "error: gnuplot failed for $1:" >&2; cat "$tmp/gp.err" >&2; FAILED=1
  elif grep -v -e 'Skipping data file' -e '^$' -e 'warning: empty' "$tmp/gp.err" | grep -q .; then
    sed 's/^/  gnuplot: /' "$tmp/gp.err" >&2
  fi
}
FAILED=0

# ---------------------------------------------------------------------------------------------
# Fig. 3: stress paths in the normalised π-plane, target (from /legs) and measured (every row).
# Target of test t from the first available density (the targets do not depend on the density).
for t in "${tests[@]}"; do
  for d in "${densities[@]}"; do
    [ -n "${have[$d$t]:-}" ] || continue
    # x_from y_from dx dy (one row per distinct leg), A = origin; p = mean of the leg's targets
    pick "$d$t" legs 1 target_1 target_2 target_3 |
      awk 'BEGIN { x = 0; y = 0; r2 = sqrt(2); r6 = sqrt(6); print "# x_from\ty_from\tdx\tdy  (target legs, normalised pi-plane, A = origin)" }
           { p = ($1 + $2 + $3) / 3; nx = ($3 - $2) / (r2 * p); ny = (2 * $1 - $2 - $3) / (r6 * p)
             k = sprintf("%.4f %.4f %.4f %.4f", x, y, nx, ny)
             if (!(k in seen)) { seen[k] = 1; printf "%.6f\t%.6f\t%.6f\t%.6f\n", x, y, nx - x, ny - y }
             x = nx; y = ny }' > "$figs/fig03_test${t}_target.dat"
    break
  done
  for d in "${densities[@]}"; do
    [ -n "${have[$d$t]:-}" ] || continue
    { echo "# pi_stress_x pi_stress_y cycle (every row, $d test $t)"; pick "$d$t" ts 1 pi_stress_x pi_stress_y cycle; } > "$figs/fig03_${d}_test$t.dat"
  done
done
{
  preamble "$figs/fig03_stress_paths.png" 1650 1130
  R=0.3
  # named states (SPEC section 3, R = 1.24): TC radius 0.1815, TE radius 0.1690
  echo 'set multiplot layout 2,3 title "Fig. 3  Stress paths on the normalised π-plane (p = 100 kPa, σ_{max}/σ_{min} = 1.24): target (grey, arrows) and measured\nx = (σ_3 − σ_2)/(√2 p),  y = (2σ_1 − σ_2 − σ_3)/(√6 p); measured: from the axis stresses σ_{11}, σ_{22}, σ_{33}" font ",13"'
  cat << 'GP'
set xlabel "(σ_3 − σ_2)/(√2 p)"; set ylabel "(2σ_1 − σ_2 − σ_3)/(√6 p)"
set key top right font ",9" samplen 1.5
set label 11 "TC1" at 0,0.1815 offset 1.2,0.5 font ",9" front
set label 12 "TC2" at -0.1572,-0.0908 offset -1.5,-1 right font ",9" front
set label 13 "TC3" at 0.1572,-0.0908 offset 1.5,-1 left font ",9" front
set label 14 "TE1" at 0,-0.1690 offset 1,-0.8 font ",9" front
set label 15 "TE2" at 0.1464,0.0845 offset 1,0.5 left font ",9" front
set label 16 "TE3" at -0.1464,0.0845 offset -1,0.5 right font ",9" front
set label 17 "A" at 0,0 offset 0.8,-0.8 font ",9" front
GP
  pi_axes $R
  titles=("(A) Test 1: triangle, 5 cycles counter-clockwise then 5 clockwise" "(B) Test 2: loading–unloading on axes 1, 2, 3" \
          "(C) Test 3: compression and extension on each axis" "(D) Test 4: Mohr–Coulomb hexagon" \
          "(E) Test 5: A↔TC1 ×10, A↔TC3 ×10, ×5, ×5 (caption: ‘Tests 1–5’)")
  for i in 0 1 2 3 4; do
    t=${tests[$i]}
    echo "set title \"${titles[$i]}\" font \",11\""
    panel_reset
    tf=$figs/fig03_test${t}_target.dat
    add_data "$tf" '1:2:3:4' 'w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa"' 'target path'
    for d in "${densities[@]}"; do
      add "$figs/fig03_${d}_test$t.dat" '1:2' "w l lw 1.3 lc rgb \"${dcol[$d]}\"" "$d"
    done
    panel_plot fixed
  done
  echo 'set title "(E′) all five target paths overlaid" font ",11"'
  panel_reset
  # Test 5's legs are a subset of Test 2's, which are a subset of Test 3's: draw wide to narrow
  declare -A tlw=([3]=7 [2]=4 [5]=1.5 [1]=2 [4]=2)
  for t in 3 2 5 1 4; do
    add_notitle "$figs/fig03_test${t}_target.dat" '1:2:3:4' "w vectors head filled size graph 0.03,20 lw ${tlw[$t]} lc rgb \"${tcol[$t]}\""
  done
  for t in "${tests[@]}"; do
    if has_rows "$figs/fig03_test${t}_target.dat"; then PLOT+=("NaN w l lw ${tlw[$t]} lc rgb \"${tcol[$t]}\" t \"Test $t\"")
    else PLOT+=("NaN w l lw 2 lc rgb \"${tcol[$t]}\" t \"Test $t: not run\""); fi
  done
  panel_plot fixed
  echo "unset multiplot"
} > "$figs/fig03_stress_paths.gp"
run_gp fig03_stress_paths

# ---------------------------------------------------------------------------------------------
# Per-density line figures with all five tests: fig_by_density NAME ORDER(d d d) XLABEL YLABEL
#   XRANGE YRANGE TITLE KEYPOS EXTRA-SETTINGS ; data files $figs/NAME_<d>_test<t>.dat must exist
#   already for the results present. Curves use columns 1:2.
fig_by_density() {
  local name=$1 order=$2 xl=$3 yl=$4 xr=$5 yr=$6 title=$7 keypos=$8 extra=$9 style=${10:-w l lw 1.4}
  local i=0 d t
  {
    preamble "$figs/$name.png" 1800 620
    echo "set multiplot layout 1,3 title \"$title\" font \",13\""
    echo "set xlabel \"$xl\"; set ylabel \"$yl\"; set key $keypos"
    echo "$extra"
    for d in $order; do
      echo "set xrange $xr; set yrange $yr"
      echo "set title \"(${letters[$i]}) $d\" font \",12\""
      panel_reset
      for t in "${tests[@]}"; do
        [ -z "${BAND:-}" ] || add_notitle "$figs/${name}_${d}_test$t.dat" '1:($2-$3):($2+$3)' "w filledcurves fs transparent solid 0.12 noborder lc rgb \"${tcol[$t]}\""
        add "$figs/${name}_${d}_test$t.dat" '1:2' "$style lc rgb \"${tcol[$t]}\"" "Test $t"
      done
      for r in "${REFS[@]}"; do if [ -n "$r" ]; then add_raw "$r"; fi; done
      if [ "$ANY" = 1 ] && [ -n "${DREF[$d]:-}" ]; then add_raw "${DREF[$d]}"; fi
      panel_plot
      i=$((i + 1))
    done
    echo "unset multiplot"
  } > "$figs/$name.gp"
  run_gp "$name"
}
REFS=("")         # reference lines drawn in every panel
declare -A DREF   # a reference line for one density's panel, drawn when that density has data

# Fig. 4: q against p, every row, all tests. Panel order of the caption: (A) dense (B) medium (C) loose.
for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  { echo "# p_kPa q_kPa (every row)"; pick "$d$t" ts 1 'p/1000' 'q/1000'; } > "$figs/fig04_q_p_${d}_test$t.dat"
done; done
REFS=("22.222 w l dt 2 lw 1 lc rgb '#777777' t 'target q at TC (22.2 kPa)'" "20.690 w l dt 3 lw 1 lc rgb '#777777' t 'target q at TE (20.7 kPa)'")
fig_by_density fig04_q_p "dense medium loose" "mean stress p (kPa)" "deviator stress q (kPa)" "[90:110]" "[0:30]" \
  "Fig. 4  Deviator stress q against mean stress p, all cycles of all tests (q from the principal values of the full stress tensor)" \
  "bottom right" "" "w lp lw 1 pt 7 ps 0.35"
REFS=("")

# Fig. 5: q/p against εd (Eq. 4), first 5 cycles (cycle 0 = the A→TC1 leg of Tests 1 and 4 included).
for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  { echo "# eps_d_percent(Eq.4) q_over_p (cycle <= 5)"; pick "$d$t" ts 'cycle <= 5' '100*deviatoric_strain' q_over_p; } > "$figs/fig05_qp_epsd_${d}_test$t.dat"
done; done
fig_by_density fig05_qp_epsd "loose medium dense" \
  "ε_d (%)  (paper Eq. 4)" "stress ratio q/p" \
  "[0:*]" "[0:0.3]" "Fig. 5  Stress ratio q/p against deviatoric strain ε_d, first 5 cycles of all tests (strains from the start of shearing)\\nε_d of paper Eq. 4: √(2/3 [(ε_1−ε_2)^2 + (ε_2−ε_3)^2 + (ε_1−ε_3)^2]) = √3 × the usual equivalent strain" \
  "bottom right" ""

# Fig. 6: εv against σ1/σ3 (Tests 1, 4, 5) and against q/p (Tests 2, 3), first 5 cycles.
for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  case $t in
    2|3) { echo "# q_over_p eps_v_percent (cycle <= 5)"; pick "$d$t" ts 'cycle <= 5' q_over_p '100*volumetric_strain'; } > "$figs/fig06_epsv_${d}_test$t.dat" ;;
    *)   { echo "# sigma1_over_sigma3 eps_v_percent (cycle <= 5)"; pick "$d$t" ts 'cycle <= 5' sigma1_over_sigma3 '100*volumetric_strain'; } > "$figs/fig06_epsv_${d}_test$t.dat" ;;
  esac
done; done
{
  preamble "$figs/fig06_epsv.png" 1800 1050
  echo 'set multiplot layout 2,3 title "Fig. 6  Volumetric strain ε_v = 1 − V/V_0 (compression +), first 5 cycles: against σ_1/σ_3 for Tests 1, 4, 5 (top) and against q/p for Tests 2, 3 (bottom)" font ",13"'
  echo 'set ylabel "ε_v (%)"; set key top left; set offsets 0, 0, graph 0.25, 0'
  for row in 1 2; do
    i=0
    for d in "${densities[@]}"; do
      panel_reset
      if [ $row = 1 ]; then
        echo 'set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set xrange [0.75:1.3]; set yrange [*:*]'
        echo "set title \"(${letters[$i]}) $d: Tests 1, 4, 5 against σ_1/σ_3\" font \",12\""
        for t in 1 4 5; do add "$figs/fig06_epsv_${d}_test$t.dat" '1:2' "w l lw 1.4 lc rgb \"${tcol[$t]}\"" "Test $t"; done
      else
        echo 'set xlabel "stress ratio q/p"; set xrange [0:0.3]; set yrange [*:*]'
        echo "set title \"(${letters[$i]}) $d: Tests 2, 3 against q/p\" font \",12\""
        for t in 2 3; do add "$figs/fig06_epsv_${d}_test$t.dat" '1:2' "w l lw 1.4 lc rgb \"${tcol[$t]}\"" "Test $t"; done
      fi
      panel_plot
      i=$((i + 1))
    done
  done
  echo "unset multiplot"
} > "$figs/fig06_epsv.gp"
run_gp fig06_epsv

# Figs. 7, 10, 11 of an ensemble: its per-cycle mean and standard deviation (ensemble-cycles) as the
# curve and its band; the title says how many samples.
ensemble_note=""
if [ -n "${ENSEMBLE:-}" ]; then
  n=$(awk 'FNR > 2 { if ($4 > m) m = $4 } END { print m + 0 }' "$ENSEMBLE"/epsv_percent_*.dat 2>/dev/null || echo 0)
  ensemble_note=" — mean of $n samples, band ± 1 standard deviation"
fi
BAND=""   # set to draw bands (columns mean, sd) in fig_by_density
ensemble_data() {   # ensemble_data QUANTITY FIGNAME: copies the ensemble's files, or returns 1
  [ -n "${ENSEMBLE:-}" ] || return 1
  local d t
  for d in "${densities[@]}"; do for t in "${tests[@]}"; do
    [ -f "$ENSEMBLE/${1}_${d}_test$t.dat" ] && cp "$ENSEMBLE/${1}_${d}_test$t.dat" "$figs/${2}_${d}_test$t.dat"
  done; done
  return 0
}

# Fig. 7: εv at the end of every cycle; cycle 0 = start of shearing (εv = 0 by definition).
ensemble_data epsv_percent fig07_epsv_cycles || for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  { echo "# cycle eps_v_percent (cycle 0: first row, then cycle_end rows)"; pick "$d$t" ts 'NR == 2 || cycle_end == 1' 'NR == 2 ? 0 : cycle' '100*volumetric_strain'; } > "$figs/fig07_epsv_cycles_${d}_test$t.dat"
done; done
BAND=${ENSEMBLE:+1}
fig_by_density fig07_epsv_cycles "loose medium dense" "cycle number (0 = start of shearing)" "ε_v (%) at the end of the cycle" \
  "[0:*]" "[*:*]" "Fig. 7  Volumetric strain ε_v (compression +) at the end of each cycle, all tests$ensemble_note" \
  "top left" "set offsets 0, 0.3, graph 0.25, 0" "w lp lw 1.4 pt 7 ps 0.7"
BAND=""

# Fig. 8: Test 5, εv against σ1/σ3 over all its cycles, coloured by block (axis of the loaded leg).
# Block of a cycle: a new block starts whenever the loaded axis (largest target) changes.
blockinfo=$tmp/blocks
for d in "${densities[@]}"; do
  [ -n "${have[${d}5]:-}" ] || continue
  pick "${d}5" legs 1 cycle target_1 target_2 target_3 |
    awk '{ a = 1; if ($3 > $2 && $3 >= $4) a = 2; if ($4 > $2 && $4 > $3) a = 3
           if ($2 != $3 || $3 != $4) axis[$1] = a; if ($1 > m) m = $1 }
         END { b = 0; prev = 0; for (c = 1; c <= m; c++) { if (axis[c] != prev) { b++; prev = axis[c] } print c, b, axis[c] } }' > "$blockinfo.$d"
  { echo "# sigma1_over_sigma3 eps_v_percent cycle; one gnuplot index per block of cycles loading the same axis"
    pick "${d}5" ts 1 cycle sigma1_over_sigma3 '100*volumetric_strain' |
      awk 'NR == FNR { blk[$1] = $2; ax[$1] = $3; next }
           { c = ($1 < 1) ? 1 : $1; b = blk[c]
             if (b != cur) { if (cur) printf "\n\n"
                             printf "# block %d: axis %d, from cycle %d\n", b, ax[c], c
                             if (cur) print lastx "\t" lasty "\t" lastc   # continue from the previous block
                             cur = b }
             print $2 "\t" $3 "\t" $1; lastx = $2; lasty = $3; lastc = $1 }' "$blockinfo.$d" -
  } > "$figs/fig08_test5_${d}.dat"
done
{
  preamble "$figs/fig08_test5_epsv.png" 1800 620
  echo 'set multiplot layout 1,3 title "Fig. 8  Test 5: volumetric strain ε_v (compression +) against σ_1/σ_3 over all cycles, coloured by block of cycles" font ",13"'
  echo 'set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set ylabel "ε_v (%)"; set key top left; set xrange [0.75:1.3]; set yrange [*:*]; set offsets 0, 0, graph 0.3, 0'
  bcol=("#1f77b4" "#d62728" "#2ca02c" "#ff7f0e" "#9467bd" "#8c564b")
  i=0
  for d in "${densities[@]}"; do
    echo "set title \"(${letters[$i]}) $d, Test 5\" font \",12\""
    panel_reset
    f=$figs/fig08_test5_$d.dat
    if [ -f "$f" ]; then
      nb=$(awk 'END { print $2 + 0 }' "$blockinfo.$d")
      for ((b = 1; b <= nb; b++)); do
        range=$(awk -v b=$b '$2 == b { if (!f) f = $1; l = $1; a = $3 } END { printf "cycles %d–%d: A↔TC%d (steps %d–%d)", f, l, a, 2*b-1, 2*b }' "$blockinfo.$d")
        add "$f" "1:2 index $((b - 1))" "w l lw 1.4 lc rgb \"${bcol[$(((b - 1) % 6))]}\"" "$range"
      done
    else
      add "$f" '1:2' 'w l' "Test 5"
    fi
    panel_plot
    i=$((i + 1))
  done
  echo "unset multiplot"
} > "$figs/fig08_test5_epsv.gp"
run_gp fig08_test5_epsv

# ---------------------------------------------------------------------------------------------
# Fig. 9: strain increment vectors of cycles 1 and 5 on the π-plane, one arrow per leg, starting at
# the measured stress point at the end of the leg. The arrow is the leg's strain increment
# (pi_strain_increment_x/y at its leg_end row) times a scale S chosen per density and test (the same
# for both cycles) so that the longest arrow is about 0.12; S is printed in the panel.
# If the result has fewer than 5 cycles (quick profile), its last cycle is drawn instead and the
# panel says so.
declare -A scale cyc2
for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  lc=$(last_cycle "$d$t"); c2=$((lc < 5 ? lc : 5)); cyc2[$d$t]=$c2
  for c in 1 "$c2"; do
    { echo "# stress_x stress_y deps_x deps_y leg step_in_cycle (leg_end rows of cycle $c; strain increments as fractions)"
      pick "$d$t" ts "leg_end == 1 && cycle == $c" pi_stress_x pi_stress_y pi_strain_increment_x pi_strain_increment_y leg |
        awk '{ n++; print $0 "\t" n }'
    } > "$figs/fig09_${d}_test${t}_cycle$c.dat"
    { echo "# pi_stress_x pi_stress_y (every row of cycle $c, and the leg_end row before it)"
      pick "$d$t" ts "cycle == $c || (cycle == $c - 1 && leg_end == 1)" pi_stress_x pi_stress_y; } > "$figs/fig09_${d}_test${t}_cycle${c}_path.dat"
  done
  scale[$d$t]=$(cat "$figs/fig09_${d}_test${t}_cycle1.dat" "$figs/fig09_${d}_test${t}_cycle$c2.dat" |
    awk '!/^#/ { l = sqrt($3 * $3 + $4 * $4); if (l > m) m = l }
         END { if (m <= 0) { print 1; exit } s = 0.12 / m; e = 10 ^ int(log(s) / log(10) - (s < 1)); f = s / e
               printf "%g\n", (f >= 5 ? 5 : f >= 2 ? 2 : 1) * e }')
done; done
fig09_panel() {   # fig09_panel DENSITY TEST WHICH(1|2) LABEL
  local d=$1 t=$2 which=$3 label=$4 c s
  panel_reset
  if [ -z "${have[$d$t]:-}" ]; then
    echo "set title \"${label:+$label }$d, Test $t, cycle $([ "$which" = 1 ] && echo 1 || echo 5)\" font \",11\""
    panel_plot fixed
    return
  fi
  c=1; [ "$which" = 2 ] && c=${cyc2[$d$t]}
  local extra=""
  [ "$which" = 2 ] && [ "$c" != 5 ] && extra=" (only $c cycles run)"
  s=${scale[$d$t]}
  echo "set title \"${label:+$label }$d, Test $t, cycle $c$extra\\narrows: Δε × $s  (0.1 on the axes = $(awk -v s="$s" 'BEGIN { printf "%.3g", 10 / s }') % strain)\" font \",11\""
  add_data "$figs/fig03_test${t}_target.dat" '1:2:3:4' 'w vectors nohead lw 3 lc rgb "#dddddd"' 'target path'
  add_data "$figs/fig09_${d}_test${t}_cycle${c}_path.dat" '1:2' "w l lw 1 lc rgb \"${dcol[$d]}\"" 'measured stress'
  add_data "$figs/fig09_${d}_test${t}_cycle$c.dat" "1:2:(\$3*$s):(\$4*$s)" 'w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000"' 'strain increment of a leg'
  add_data "$figs/fig09_${d}_test${t}_cycle$c.dat" "(\$1+\$3*$s):(\$2+\$4*$s):6" 'w labels offset char 0.6,0.6 font ",9" tc rgb "#000000"' ''
  panel_plot fixed
}
{
  preamble "$figs/fig09_strain_increments.png" 1800 1480
  echo 'set multiplot layout 3,4 title "Fig. 9  Strain increment vectors on the normalised π-plane, cycles 1 and 5: one arrow per leg (numbered in order), drawn from the measured stress at the end of the leg\n(A) loose Test 1, (B) dense Test 1, (C) loose Test 2, (D) dense Test 2, (E) loose Test 4, (F) dense Test 4;  1 = 1st cycle, 2 = 5th cycle" font ",13"'
  echo 'set xlabel "π-plane x  (stress: /p;  Δε: × scale)" font ",10"; set ylabel "π-plane y" font ",10"; set key bottom right font ",8"'
  pi_axes 0.33
  k=0
  for t in 1 2 4; do
    for d in loose dense; do
      L=${letters[$k]}
      fig09_panel "$d" "$t" 1 "($L""1)"
      fig09_panel "$d" "$t" 2 "($L""2)"
      k=$((k + 1))
    done
  done
  echo "unset multiplot"
} > "$figs/fig09_strain_increments.gp"
run_gp fig09_strain_increments
# the same for every test of each density (beyond the paper's selection)
for d in "${densities[@]}"; do
  {
    preamble "$figs/fig09_all_tests_$d.png" 2250 1000
    echo "set multiplot layout 2,5 title \"Fig. 9 (all tests, $d)  Strain increment vectors on the normalised π-plane, one arrow per leg, from the measured stress at the end of the leg: cycle 1 (top), cycle 5 (bottom)\" font \",13\""
    echo 'set xlabel "x" font ",10"; set ylabel "y" font ",10"; set key bottom right font ",8"'
    pi_axes 0.33
    for which in 1 2; do
      for t in "${tests[@]}"; do fig09_panel "$d" "$t" "$which" ""; done
    done
    echo "unset multiplot"
  } > "$figs/fig09_all_tests_$d.gp"
  run_gp "fig09_all_tests_$d"
done

# ---------------------------------------------------------------------------------------------
# Figs. 10, 11: coordination number and sliding fraction at the end of every cycle (Fig. 10: cycle 0 = start).
ensemble_data coordination fig10_coordination && ensemble_data sliding_percent fig11_sliding || for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  { echo "# cycle coordination_number (cycle 0: first row, then cycle_end rows)"; pick "$d$t" ts 'NR == 2 || cycle_end == 1' 'NR == 2 ? 0 : cycle' coordination_number; } > "$figs/fig10_coordination_${d}_test$t.dat"
  # no cycle 0 here: the first row's sliding flags come from the saved sample (its preparation
  # friction, e.g. 0.2 for medium), not from a step with the shearing friction
  { echo "# cycle sliding_percent (cycle_end rows)"; pick "$d$t" ts 'cycle_end == 1' cycle '100*sliding_fraction'; } > "$figs/fig11_sliding_${d}_test$t.dat"
done; done
# Fig. 10: each panel also shows the paper's value before shearing for its density.
for d in "${densities[@]}"; do DREF[$d]="${cn_paper[$d]} w l dt 2 lw 1.5 lc rgb '#777777' t 'paper, before shearing (${cn_paper[$d]})'"; done
BAND=${ENSEMBLE:+1}
fig_by_density fig10_coordination "${densities[*]}" "cycle number (0 = start of shearing)" "coordination number" \
  "[0:*]" "[*:*]" "Fig. 10  Coordination number 2N_c/N_p (rattlers included) at the end of each cycle, all tests$ensemble_note" "top right" \
  "set offsets 0, 0.3, graph 0.4, graph 0.05" "w lp lw 1.4 pt 7 ps 0.7"
DREF=()
REFS=("")
fig_by_density fig11_sliding "loose medium dense" "cycle number" "sliding contact fraction N_s/N_c (%)" \
  "[0:*]" "[0:*]" "Fig. 11  Sliding contact fraction N_s/N_c × 100 % (|f_t| ≥ μ f_n) at the end of each cycle, all tests$ensemble_note" "top right" "set offsets 0, 0.3, graph 0.4, 0" "w lp lw 1.4 pt 7 ps 0.7"
BAND=""

# ---------------------------------------------------------------------------------------------
# Figs. 12-14: q/p against the fabric ratios, first 5 cycles, with the 1:1 line; square axes.
for d in "${densities[@]}"; do for t in "${tests[@]}"; do
  [ -n "${have[$d$t]:-}" ] || continue
  { echo "# fabric_ratio(F_d/F_m) q_over_p (cycle <= 5)"; pick "$d$t" ts 'cycle <= 5' fabric_ratio q_over_p; } > "$figs/fig12_fabric_${d}_test$t.dat"
  { echo "# strong_fabric_ratio(F^s_d/F^s_m) q_over_p (cycle <= 5)"; pick "$d$t" ts 'cycle <= 5' strong_fabric_ratio q_over_p; } > "$figs/fig13_strong_fabric_${d}_test$t.dat"
done; done
axis_max() {   # largest value in columns 1-2 of the given files, ×1.05, at least 0.3, rounded up to 0.05
  { cat "$@" 2> /dev/null || true; } | awk '!/^#/ && NF { if ($1 > m) m = $1; if ($2 > m) m = $2 } END { m *= 1.05; if (m < 0.3) m = 0.3; printf "%.2f\n", int(m / 0.05 + 0.999) * 0.05 }'
}
for n in 12 13; do
  if [ $n = 12 ]; then name=fig12_fabric; xl="F_d/F_m (all contacts, Eq. 8)"; ttl="Fig. 12  Stress ratio q/p against the fabric ratio F_d/F_m of all contacts, first 5 cycles of all tests"
  else name=fig13_strong_fabric; xl="F^s_d/F^s_m (strong contacts, Eqs. 9–10)"; ttl="Fig. 13  Stress ratio q/p against the strong-contact fabric ratio F^s_d/F^s_m, first 5 cycles of all tests"; fi
  m=$(axis_max "$figs/${name}"_*.dat)
  {
    preamble "$figs/$name.png" 1800 660
    echo "set multiplot layout 1,3 title \"$ttl\" font \",13\""
    echo "set xlabel \"$xl\"; set ylabel \"stress ratio q/p\"; set key top left; set size ratio -1"
    i=0
    for d in "${densities[@]}"; do
      echo "set xrange [0:$m]; set yrange [0:$m]; set title \"(${letters[$i]}) $d\" font \",12\""
      panel_reset
      for t in "${tests[@]}"; do add "$figs/${name}_${d}_test$t.dat" '1:2' "w l lw 1.2 lc rgb \"${tcol[$t]}\"" "Test $t"; done
      add_raw "x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'"
      panel_plot fixed
      i=$((i + 1))
    done
    echo "unset multiplot"
  } > "$figs/$name.gp"
  run_gp "$name"
done
# Fig. 14: Fig. 13 of the three densities together.
m=$(axis_max "$figs"/fig13_strong_fabric_*.dat)
{
  preamble "$figs/fig14_strong_fabric_all.png" 900 860
  echo "set title \"Fig. 14  q/p against F^s_d/F^s_m, all densities and tests, first 5 cycles\" font \",13\""
  echo "set xlabel \"F^s_d/F^s_m (strong contacts, Eqs. 9–10)\"; set ylabel \"stress ratio q/p\"; set key top left; set size ratio -1"
  echo "set xrange [0:$m]; set yrange [0:$m]"
  panel_reset
  for d in "${densities[@]}"; do
    first=1
    for t in "${tests[@]}"; do
      f=$figs/fig13_strong_fabric_${d}_test$t.dat
      if has_rows "$f"; then
        if [ $first = 1 ]; then add "$f" '1:2' "w l lw 1 lc rgb \"${dcol[$d]}\"" "$d (Tests $(for u in "${tests[@]}"; do [ -n "${have[$d$u]:-}" ] && printf '%s ' "$u"; done | sed 's/ $//; s/ /, /g'))"; first=0
        else add_notitle "$f" '1:2' "w l lw 1 lc rgb \"${dcol[$d]}\""; fi
      fi
    done
    [ $first = 1 ] && PLOT+=("NaN w l lc rgb \"${dcol[$d]}\" t \"$d: not run\"")
  done
  add_raw "x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'"
  panel_plot fixed
} > "$figs/fig14_strong_fabric_all.gp"
run_gp fig14_strong_fabric_all

echo "figures written to $figs" >&2
exit $FAILED
