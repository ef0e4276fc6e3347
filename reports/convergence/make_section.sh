#!/usr/bin/env bash
# The convergence study's tables and figure (issue 7, part 2) from its results.
# Usage: reports/convergence/make_section.sh [BIN_DIR] [RESULTS_DIR] [OUT_DIR]
#   BIN_DIR      holds compare-runs (default: build/bin of this repository)
#   RESULTS_DIR  the study's results with the pipeline's runs.tsv (default: results/convergence/paper)
#   OUT_DIR      receives table.md, errors.dat, front.dat, error_vs_time.gp and error_vs_time.png
#                (default: reports/convergence)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/bin}
results=${2:-$here/results/convergence/paper}
out=${3:-$here/reports/convergence}
mkdir -p "$out"
out=$(cd "$out" && pwd)
"$bin/compare-runs" convergence "$results" "$out"
command -v gnuplot > /dev/null || { echo "error: gnuplot not found" >&2; exit 2; }
# The Pareto front in order of wall time, and the reference (error 0: off a log axis) on its own.
awk -F'\t' '!/^#/ && $4 == 1 && $3 > 0' "$out/errors.dat" | sort -t$'\t' -k2,2g > "$out/front.dat"
ref_wall=$(awk -F'\t' '$1 == "reference" { print $2 }' "$out/errors.dat")
cat > "$out/error_vs_time.gp" << GP
set terminal pngcairo size 1100,800 font ",11" enhanced
set output "$out/error_vs_time.png"
set grid lc rgb "#dddddd"
set logscale xy
set key bottom left box opaque font ",10"
set title "Convergence (loose sample, Test 1, 2 cycles): largest relative error against the reference\nover e0, coordination number, ε_v and ε_d at each cycle end and the q/p–F^s_d/F^s_m slope" font ",12"
set xlabel "wall time of the variant's preparation + test (s)"
set ylabel "largest relative error (%)"
set arrow 1 from ${ref_wall:-1}, graph 0 to ${ref_wall:-1}, graph 1 nohead dt 2 lc rgb "#777777"
set label 1 "reference (error 0)" at ${ref_wall:-1}, graph 0.95 right offset -0.5,0 tc rgb "#555555"
# the tolerances of the table: 1, 5 and 10 %
set arrow 2 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb "#2ca02c"
set arrow 3 from graph 0, first 5 to graph 1, first 5 nohead dt 3 lc rgb "#ff7f0e"
set arrow 4 from graph 0, first 10 to graph 1, first 10 nohead dt 3 lc rgb "#d62728"
set label 2 "1 %" at graph 0.01, first 1 offset 0,0.6 tc rgb "#2ca02c"
set label 3 "5 %" at graph 0.01, first 5 offset 0,0.6 tc rgb "#ff7f0e"
set label 4 "10 %" at graph 0.01, first 10 offset 0,0.6 tc rgb "#d62728"
set yrange [0.01:*]
set offsets graph 0.1, graph 0.3, graph 0.1, graph 0.1
# columns of errors.dat: 5 coordination, 6 e0, 11 qp_slope (the quantities two samples agree on
# within 10 %; see the seed2 row of table.md)
max3(a, b, c) = (a > b ? (a > c ? a : c) : (b > c ? b : c))
plot "$out/front.dat" u 2:(100*\$3) w l lw 2 lc rgb "#1f77b4" t "Pareto front (all quantities)", \\
  "$out/errors.dat" u 2:(\$3 > 0 ? 100*\$3 : NaN) w p pt 7 ps 1.2 lc rgb "#000000" t "largest error, all quantities", \\
  "$out/errors.dat" u 2:(\$3 > 0 ? 100*\$3 : NaN):1 w labels offset char 0.8,0.6 left font ",9" noenhanced notitle, \\
  "$out/errors.dat" u 2:(\$3 > 0 ? 100*max3(\$5, \$6, \$11) : NaN) w p pt 6 ps 1.4 lc rgb "#d62728" t "largest error on e0, CN and the q/p slope"
GP
sed -i "s#$out/##g" "$out/error_vs_time.gp"   # paths relative to the section folder, where it runs
(cd "$out" && gnuplot error_vs_time.gp)
echo "convergence section written to $out" >&2
