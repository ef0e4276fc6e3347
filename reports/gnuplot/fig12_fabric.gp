# Fig. 12: q/p against the fabric ratio F_d/F_m of all contacts (paper Eq. 8), first 5 cycles, with
# the 1:1 line; square axes of equal ranges (fig12_max). Data: fig12_fabric_<density>_test<t>.dat.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,660 font ",11" enhanced
set output 'fig12_fabric.png'
set multiplot layout 1,3 title "Fig. 12  Stress ratio q/p against the fabric ratio F_d/F_m of all contacts, first 5 cycles of all tests" font ",13"
set xlabel "F_d/F_m (all contacts, Eq. 8)"; set ylabel "stress ratio q/p"; set key top left; set size ratio -1
set xrange [0:fig12_max]; set yrange [0:fig12_max]
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  if (!has_density(d)) { eval not_run }
  plot for [t = 1:5] sprintf("fig12_fabric_%s_test%d.dat", d, t) u 1:2 w l lw 1.2 lc rgb test_colour(t) t test_title(d, t), \
       x w l dt 2 lw 1.5 lc rgb "#777777" t "1:1"
  eval not_run_off
}
unset multiplot
