# Fig. 7: ε_v at the end of every cycle, all tests; cycle 0 is the start of shearing (ε_v = 0).
# The ensemble's mean over its samples with a band of one standard deviation (one sample: its
# values). Data: fig07_epsv_cycles_<density>_test<t>.dat (figure-data: cycle, mean, sd, n, min, max).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig07_epsv_cycles.png'
set multiplot layout 1,3 title "Fig. 7  Volumetric strain ε_v (compression +) at the end of each cycle, all tests" . ensemble_note(samples_n) font ",13"
set xlabel "cycle number (0 = start of shearing)"; set ylabel "ε_v (%) at the end of the cycle"; set key top left
set offsets 0, 0.3, graph 0.25, 0
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  if (!has_density(d)) { eval not_run; set xrange [0:1]; set yrange [0:1] } else { set xrange [0:*]; set yrange [*:*] }
  plot for [t = 1:5] sprintf("fig07_epsv_cycles_%s_test%d.dat", d, t) u 1:($2 - $3):($2 + $3) w filledcurves fs transparent solid 0.12 noborder lc rgb test_colour(t) notitle, \
       for [t = 1:5] sprintf("fig07_epsv_cycles_%s_test%d.dat", d, t) u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb test_colour(t) t test_title(d, t)
  eval not_run_off
}
unset multiplot
