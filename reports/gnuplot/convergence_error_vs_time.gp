# The convergence study's figure: the largest relative error of each variant against the wall time
# of its runs, with the Pareto front, the reference's wall time and the tolerances of the table
# (1, 5, 10 %). Data: errors.dat and front.dat (build/bin/compare-runs convergence; columns:
# variant, wall time, largest relative error, on the Pareto front, the error of each quantity). Runs in
# reports/convergence/ (reports/convergence/make_section.sh).
load 'style.gp'
set terminal pngcairo size 1100,800 font ",11" enhanced
set output 'error_vs_time.png'
set logscale xy
set key bottom left box opaque font ",10"
set title "Convergence (loose sample, Test 1, 2 cycles): largest relative error against the reference\nover e0, coordination number, ε_v and ε_d at each cycle end and the q/p–F^s_d/F^s_m slope" font ",12"
set xlabel "wall time of the variant's preparation + test (s)"
set ylabel "largest relative error (%)"
# The reference (error 0: off a log axis) as a vertical line at its wall time.
stats 'errors.dat' u (strcol(1) eq "reference" ? $2 : NaN) nooutput
ref_wall = STATS_max
set arrow 1 from ref_wall, graph 0 to ref_wall, graph 1 nohead dt 2 lc rgb "#777777"
set label 1 "reference (error 0)" at ref_wall, graph 0.95 right offset -0.5,0 tc rgb "#555555"
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
plot "front.dat" u 2:(100*$3) w l lw 2 lc rgb "#1f77b4" t "Pareto front (all quantities)", \
  "errors.dat" u 2:($3 > 0 ? 100*$3 : NaN) w p pt 7 ps 1.2 lc rgb "#000000" t "largest error, all quantities", \
  "errors.dat" u 2:($3 > 0 ? 100*$3 : NaN):1 w labels offset char 0.8,0.6 left font ",9" noenhanced notitle, \
  "errors.dat" u 2:($3 > 0 ? 100*max3($5, $6, $11) : NaN) w p pt 6 ps 1.4 lc rgb "#d62728" t "largest error on e0, CN and the q/p slope"
