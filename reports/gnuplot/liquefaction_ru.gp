# The liquefaction section, figure (b): r_u = 1 - p/p0 against the number of cycles since the start
# of the cyclic stage of every run: the cyclic tests (solid) and the holds with nothing applied
# (dashed, their time divided by the period of their density's cyclic tests). Data: ru.dat
# (compare-runs liquefaction; one block per run: label, cycles, r_u, time) and values.gp (liq_run_<k>,
# liq_run_hold_<k>, liq_run_density_<k>). Runs in reports/liquefaction/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1100,750 font ",11" noenhanced
set output 'ru.png'
set title "Excess pore pressure ratio r_u against cycles (holds dashed: time / period, nothing applied)\nlog axis: the first row, at 0 cycles, is off it"
set logscale x
set xrange [0.01:100]
set yrange [*:1]   # a dilating sample has r_u < 0
set xlabel "number of cycles"
set ylabel "r_u = 1 - p/p0"
set key top left
set arrow 1 from graph 0, first 0.95 to graph 1, first 0.95 nohead dt 3 lc rgb "#777777"
set label 1 "r_u = 0.95" at graph 0.99, first 0.95 right offset 0,0.7 tc rgb "#555555"
if (liq_run_n == 0) { eval not_run }
run(k) = value(sprintf("liq_run_%d", k))
hold(k) = value(sprintf("liq_run_hold_%d", k)) eq "1"
dashes(k) = hold(k) ? 2 : 1   # holds dashed
# Ten colours, one per run (style.gp's block colours are six).
colour(k) = word("#1f77b4 #d62728 #2ca02c #ff7f0e #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf", (k - 1) % 10 + 1)
plot for [k = 1:liq_run_n] "ru.dat" index (k - 1) u ($2 > 0 ? $2 : 1/0):3 w l lw 2 dt dashes(k) lc rgb colour(k) t run(k), \
     NaN notitle
eval not_run_off
