# The convergence study's figure: each setting's largest relative error against the converged
# values (with its 95 % interval) against the core-seconds of one sample's preparation + test,
# one colour per density, its Pareto front as a line, and the tolerances of the table (1, 5, 10 %).
# Data: errors.dat and front.dat (build/bin/compare-runs convergence; columns: density, setting,
# core-seconds, largest relative error, its half-width, on the front, the quantity). Runs in
# reports/convergence/ (compare-runs convergence --draw, make convergence-report).
load 'style.gp'
set terminal pngcairo size 1100,800 font ",11" enhanced
set output 'error_vs_time.png'
set logscale xy
set key top right box opaque font ",10"
set title "Convergence (Test 1, 2 cycles): largest relative error of each setting against the converged values\nover the quantities whose converged value is known to better than 10 % (table); bars: 95 % intervals" font ",12"
set xlabel "core-seconds of one sample (preparation + test)"
set ylabel "largest relative error against the converged value (%)"
set arrow 2 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb "#2ca02c"
set arrow 3 from graph 0, first 5 to graph 1, first 5 nohead dt 3 lc rgb "#ff7f0e"
set arrow 4 from graph 0, first 10 to graph 1, first 10 nohead dt 3 lc rgb "#d62728"
set label 2 "1 %" at graph 0.01, first 1 offset 0,0.6 tc rgb "#2ca02c"
set label 3 "5 %" at graph 0.01, first 5 offset 0,0.6 tc rgb "#ff7f0e"
set label 4 "10 %" at graph 0.01, first 10 offset 0,0.6 tc rgb "#d62728"
set offsets graph 0.1, graph 0.3, graph 0.1, graph 0.1
floor = 0.01                       # the axis' lowest value (%): an interval reaching 0 is drawn to it
low(e, h) = (100*(e - h) > floor ? 100*(e - h) : floor)
set yrange [floor:*]
plot for [d in "loose dense"] "errors.dat" u (strcol(1) eq d ? $3 : NaN):(100*$4):(low($4, $5)):(100*($4 + $5)) \
       w yerrorbars pt 7 ps 1.2 lc rgb (d eq "loose" ? "#1f77b4" : "#d62728") t d, \
     for [d in "loose dense"] "front.dat" u (strcol(1) eq d ? $3 : NaN):(100*$4) w l lw 2 \
       lc rgb (d eq "loose" ? "#1f77b4" : "#d62728") t d." Pareto front", \
     "errors.dat" u 3:(100*$4):2 w labels offset char 0.8,0.6 left font ",9" noenhanced notitle
