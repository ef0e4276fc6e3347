# Fig. 11: sliding contact fraction N_s/N_c at the end of every cycle, all tests (no cycle 0: the
# first row's sliding flags come from the saved sample, i.e. its preparation friction). Mean and
# band as Fig. 7. Data: fig11_sliding_<density>_test<t>.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig11_sliding.png'
set multiplot layout 1,3 title "Fig. 11  Sliding contact fraction N_s/N_c × 100 % (|f_t| ≥ μ f_n) at the end of each cycle, all tests" . ensemble_note(samples_n) font ",13"
set xlabel "cycle number"; set ylabel "sliding contact fraction N_s/N_c (%)"; set key top right
set offsets 0, 0.3, graph 0.4, 0
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  if (!has_density(d)) { eval not_run; set xrange [0:1]; set yrange [0:1] } else { set xrange [0:*]; set yrange [0:*] }
  plot for [t = 1:5] sprintf("fig11_sliding_%s_test%d.dat", d, t) u 1:($2 - $3):($2 + $3) w filledcurves fs transparent solid 0.12 noborder lc rgb test_colour(t) notitle, \
       for [t = 1:5] sprintf("fig11_sliding_%s_test%d.dat", d, t) u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb test_colour(t) t test_title(d, t)
  eval not_run_off
}
unset multiplot
