#!/usr/bin/env bash
# Figures 1 and 2 of the paper from the prepared samples (data files are written beside the PNGs).
#   Fig. 1: grading curve, target (SPEC section 1) and realised in the dense sample (by count and by mass).
#   Fig. 2: (A) the lattice before compression, (B-D) the loose, medium and dense samples, in 3-D.
# Usage: reports/samples/figures.sh [DEM] [SAMPLES_DIR] [FIG_DIR]
# SAMPLE: the file name of a sample in SAMPLES_DIR, %s standing for loose/medium/dense (default
# the issue-3 names %s_n20_s1_viscous.h5; the study's are %s_prepare.h5). LATTICE: where the
# one-step lattice result is kept (default SAMPLES_DIR/lattice.h5).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
samples=${2:-$here/results/samples}
figs=${3:-$here/reports/figures}
pattern=${SAMPLE:-%s_n20_s1_viscous.h5}
sample() { printf "$samples/$pattern" "$1"; }
mkdir -p "$figs"

# Realised percent finer by mass, sorted by diameter (mm), from a result's final particles.
realised() {
  "$dem" state "$1" | awk 'NR > 1 { d = 2000 * $4; print d, d * d * d }' | sort -g |
    awk '{ d[NR] = $1; m[NR] = $2; total += $2 } END { for (i = 1; i <= NR; i++) { c += m[i]; print d[i], 100 * c / total, 100 * i / NR } }'
}
printf '3.0 0\n3.7 50\n4.5 100\n' > "$figs/fig01_grading_target.dat"
rm -f "$figs/fig01_grading_mass_basis.dat" "$figs/fig01_grading_number_basis.dat"   # the names of an earlier reading
realised "$(sample dense)" > "$figs/fig01_grading_sample.dat"
basis=$(h5dump -a scene_yaml "$(sample dense)" 2>/dev/null | grep -o 'basis: [a-z]*' | head -1 | cut -d' ' -f2)
[ "$basis" = mass ] && read_by="mass" || read_by="count"
gnuplot <<GP
set terminal pngcairo size 900,650 font ",12"
set output "$figs/fig01_grading.png"
set title "Fig. 1  Grain size distribution (d_{min} = 3 mm, d_{50} = 3.7 mm, d_{max} = 4.5 mm)"
set xlabel "diameter d (mm)"; set ylabel "percent finer (%)"
set xrange [2.9:4.6]; set yrange [0:105]; set grid; set key left top Left reverse box opaque font ",10"
plot "$figs/fig01_grading_target.dat" w lp lw 3 pt 7 ps 1.5 lc rgb "black" t "target curve (SPEC, read by $read_by)", \
     "$figs/fig01_grading_sample.dat" u 1:3 w l lw 2 lc rgb "#d62728" t "dense sample $(basename "$samples"), percent finer by count", \
     "$figs/fig01_grading_sample.dat" u 1:2 w l lw 2 dt 2 lc rgb "#1f77b4" t "the same sample, percent finer by mass"
GP

# Fig. 2: the lattice (a one-step run of the preparation scene) and the three samples.
lattice=${LATTICE:-$samples/lattice.h5}
[ -f "$lattice" ] || "$dem" run "$here/scenes/prepare_dense.yaml" --out "$lattice" --quiet --set name=lattice \
  --set 'stages=[{name: lattice, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0e-6}]'
"$dem" state "$lattice" | awk 'NR > 1 { print 1000 * $1, 1000 * $2, 1000 * $3, 1000 * $4 }' > "$figs/fig02_lattice.dat"
for d in loose medium dense; do
  if [ -f "$(sample "$d")" ]; then
    "$dem" state "$(sample "$d")" | awk 'NR > 1 { print 1000 * $1, 1000 * $2, 1000 * $3, 1000 * $4 }' > "$figs/fig02_$d.dat"
  else
    echo "note: no $d sample yet, its panel stays empty" >&2; echo "0 0 0 0" > "$figs/fig02_$d.dat"
  fi
done
gnuplot <<GP
set terminal pngcairo size 1400,1200 font ",12"
set output "$figs/fig02_samples.png"
set multiplot layout 2,2 title "Fig. 2  Samples before (A) and after isotropic compression to 100 kPa: (B) loose, (C) medium, (D) dense\n8,000 spheres, point size proportional to diameter, axis 1 vertical"
set view 65, 35, 1, 1; set ticslevel 0; unset key
set xlabel "x_2 (mm)"; set ylabel "x_3 (mm)"; set zlabel "x_1 (mm)" rotate
set xrange [0:100]; set yrange [0:100]; set zrange [0:100]
set title "(A) lattice, 100 mm cube"
splot "$figs/fig02_lattice.dat" u 2:3:1:(\$4 * 0.35) w p pt 7 ps variable lc rgb "#7f7f7f"
set xrange [0:75]; set yrange [0:75]; set zrange [0:75]
set title "(B) loose (mu = 0.5 during compression)"
splot "$figs/fig02_loose.dat" u 2:3:1:(\$4 * 0.45) w p pt 7 ps variable lc rgb "#d62728"
set title "(C) medium (mu = 0.2)"
splot "$figs/fig02_medium.dat" u 2:3:1:(\$4 * 0.45) w p pt 7 ps variable lc rgb "#2ca02c"
set title "(D) dense (mu = 0)"
splot "$figs/fig02_dense.dat" u 2:3:1:(\$4 * 0.45) w p pt 7 ps variable lc rgb "#1f77b4"
unset multiplot
GP
echo "figures written to $figs"
