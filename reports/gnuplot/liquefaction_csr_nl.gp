# The liquefaction section, figure (a): the cyclic stress ratio against the number of cycles to
# liquefaction N_L of the undrained cyclic tests, each density in its colour: every sample's test
# (small; a test that did not liquefy is a censored point, N_L > N: an open symbol with an arrow to
# the right), and per CSR the median over the samples (large diamond, joined per density; open with
# an arrow when the median itself is censored) with the range of the samples (horizontal bar from
# the least to the largest N_L; an arrow beyond it when the largest is censored).
# Data: csr_nl.dat (compare-runs liquefaction; columns: label, density index, CSR of the name, CSR
# of the scene, N, liquefied 1/0, p0 in kPa, seed), csr_nl_summary.dat (label, density index, CSR,
# samples, liquefied, censored, median low, median high, median censored 1/0, least, least censored,
# largest, largest censored) and values.gp (liq_density_<i>, liq_criteria, liq_samples_max).
# Runs in reports/liquefaction/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1000,850 font ",11" enhanced   # taller: the key sits below
set output 'csr_nl.png'
set title sprintf("Undrained cyclic triaxial tests: cyclic stress ratio against the number of cycles to liquefaction\n(%s; median and range over up to %d samples per CSR)", liq_criteria, liq_samples_max)
set logscale x
set xrange [0.5:200]
set yrange [0:*]
set xlabel "number of cycles N_L"
set ylabel "CSR = q_{amp} / (2 p_0')"
set key below
set offsets graph 0, graph 0, graph 0.08, graph 0   # the highest CSR off the frame
if (liq_run_n == 0) { set yrange [0:0.4]; eval not_run }
d(i) = value(sprintf("liq_density_%d", i))
plot for [i = 1:liq_density_n] "csr_nl_summary.dat" u 7:(column(2) == i ? $3 : 1/0):10:12 w xerrorbars pt -1 lw 1.5 lc rgb density_colour(d(i)) notitle, \
     for [i = 1:liq_density_n] "csr_nl_summary.dat" u (column(2) == i && column(13) == 1 ? $12 : 1/0):3:($12 * 0.5):(0) w vectors head filled lw 1.5 lc rgb density_colour(d(i)) notitle, \
     for [i = 1:liq_density_n] "csr_nl_summary.dat" u 7:(column(2) == i ? $3 : 1/0) w l lw 2 lc rgb density_colour(d(i)) notitle, \
     for [i = 1:liq_density_n] "csr_nl_summary.dat" u (column(2) == i && column(9) == 0 ? $7 : 1/0):3 w p pt 13 ps 2.4 lc rgb density_colour(d(i)) t sprintf("%s: median N_L, range of the samples", d(i)), \
     for [i = 1:liq_density_n] "csr_nl_summary.dat" u (column(2) == i && column(9) == 1 ? $7 : 1/0):3 w p pt 12 ps 2.6 lw 2 lc rgb density_colour(d(i)) t sprintf("%s: median censored, > N (open, arrow)", d(i)), \
     for [i = 1:liq_density_n] "csr_nl_summary.dat" u (column(2) == i && column(9) == 1 ? $7 : 1/0):3:($7 * 0.6):(0) w vectors head filled lw 2.5 lc rgb density_colour(d(i)) notitle, \
     for [i = 1:liq_density_n] "csr_nl.dat" u (column(2) == i && column(6) == 1 ? $5 : 1/0):4 w p pt 7 ps 0.9 lc rgb density_colour(d(i)) t sprintf("%s: one sample, liquefied", d(i)), \
     for [i = 1:liq_density_n] "csr_nl.dat" u (column(2) == i && column(6) == 0 ? $5 : 1/0):4 w p pt 6 ps 1.1 lw 1.5 lc rgb density_colour(d(i)) t sprintf("%s: one sample, not liquefied in N cycles, N_L > N (open)", d(i)), \
     NaN notitle
eval not_run_off
