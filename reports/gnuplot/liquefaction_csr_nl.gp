# The liquefaction section, figure (a): the cyclic stress ratio against the number of cycles to
# liquefaction N_L of the undrained cyclic tests, each density in its colour; a test that did not
# liquefy is a censored point (N_L > N): an open symbol with an arrow to the right. Data: csr_nl.dat
# (compare-runs liquefaction; columns: label, density index, CSR of the name, CSR of the scene, N,
# liquefied 1/0, p0 in kPa) and values.gp (liq_density_<i>). Runs in reports/liquefaction/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1000,750 font ",11" enhanced
set output 'csr_nl.png'
set title "Undrained cyclic triaxial tests: cyclic stress ratio against the number of cycles to liquefaction\n(r_u ≥ 0.95 or 5 % double-amplitude axial strain)"
set logscale x
set xrange [0.5:200]
set yrange [0:*]
set xlabel "number of cycles N_L"
set ylabel "CSR = q_{amp} / (2 p_0')"
set key top right
if (liq_run_n == 0) { set yrange [0:0.4]; eval not_run }
d(i) = value(sprintf("liq_density_%d", i))
plot for [i = 1:liq_density_n] "csr_nl.dat" u (column(2) == i && column(6) == 1 ? $5 : 1/0):4 w lp pt 7 ps 1.5 lw 1.5 lc rgb density_colour(d(i)) t sprintf("%s: liquefied", d(i)), \
     for [i = 1:liq_density_n] "csr_nl.dat" u (column(2) == i && column(6) == 0 ? $5 : 1/0):4 w p pt 6 ps 1.8 lw 2 lc rgb density_colour(d(i)) t sprintf("%s: not liquefied in N cycles, N_L > N (open, arrow)", d(i)), \
     for [i = 1:liq_density_n] "csr_nl.dat" u (column(2) == i && column(6) == 0 ? $5 : 1/0):4:($5 * 0.6):(0) w vectors head filled lw 2 lc rgb density_colour(d(i)) notitle, \
     NaN notitle
eval not_run_off
