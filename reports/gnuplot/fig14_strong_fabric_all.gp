# Fig. 14: Fig. 13 of the three densities together (colour = density), with the paper's relation.
# Data: fig13_strong_fabric_<density>_test<t>.dat; the tests present, fig14_tests_<density>.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 900,860 font ",11" enhanced
set output 'fig14_strong_fabric_all.png'
set title "Fig. 14  q/p against F^s_d/F^s_m, all densities and tests, first 5 cycles" font ",13"
set xlabel "F^s_d/F^s_m (strong contacts, Eqs. 9–10)"; set ylabel "stress ratio q/p"; set key top left; set size ratio -1
set xrange [0:fig13_max]; set yrange [0:fig13_max]
density_title(d) = has_density(d) ? sprintf("%s (Tests %s)", d, value("fig14_tests_" . d)) : d . ": not run"
plot for [d in densities] for [t = 1:5] sprintf("fig13_strong_fabric_%s_test%d.dat", d, t) u 1:2 w l lw 1 lc rgb density_colour(d) notitle, \
     for [d in densities] NaN w l lw 1 lc rgb density_colour(d) t density_title(d), \
     paper_slope * x w l dt 2 lw 1.5 lc rgb "#777777" t sprintf("paper: slope %g", paper_slope)
