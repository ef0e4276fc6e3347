# Fig. 13: q/p against the strong-contact fabric ratio F^s_d/F^s_m (paper Eqs. 9-10), first 5
# cycles, with the paper's relation (slope paper_slope of reference_data/paper.yaml); square axes
# (fig13_max). Data: fig13_strong_fabric_<density>_test<t>.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,660 font ",11" enhanced
set output 'fig13_strong_fabric.png'
set multiplot layout 1,3 title "Fig. 13  Stress ratio q/p against the strong-contact fabric ratio F^s_d/F^s_m, first 5 cycles of all tests" font ",13"
set xlabel "F^s_d/F^s_m (strong contacts, Eqs. 9–10)"; set ylabel "stress ratio q/p"; set key top left; set size ratio -1
set xrange [0:fig13_max]; set yrange [0:fig13_max]
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  if (!has_density(d)) { eval not_run }
  plot for [t = 1:5] sprintf("fig13_strong_fabric_%s_test%d.dat", d, t) u 1:2 w l lw 1.2 lc rgb test_colour(t) t test_title(d, t), \
       paper_slope * x w l dt 2 lw 1.5 lc rgb "#777777" t sprintf("paper: slope %g", paper_slope)
  eval not_run_off
}
unset multiplot
