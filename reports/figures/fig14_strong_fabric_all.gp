set terminal pngcairo size 900,860 font ",11" enhanced
set output "fig14_strong_fabric_all.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set title "Fig. 14  q/p against F^s_d/F^s_m, all densities and tests, first 5 cycles" font ",13"
set xlabel "F^s_d/F^s_m (strong contacts, Eqs. 9–10)"; set ylabel "stress ratio q/p"; set key top left; set size ratio -1
set xrange [0:0.30]; set yrange [0:0.30]
plot 'fig13_strong_fabric_loose_test1.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "loose (Tests 1, 2, 3, 4, 5)", \
  'fig13_strong_fabric_loose_test2.dat' u 1:2 w l lw 1 lc rgb "#d62728" notitle, \
  'fig13_strong_fabric_loose_test3.dat' u 1:2 w l lw 1 lc rgb "#d62728" notitle, \
  'fig13_strong_fabric_loose_test4.dat' u 1:2 w l lw 1 lc rgb "#d62728" notitle, \
  'fig13_strong_fabric_loose_test5.dat' u 1:2 w l lw 1 lc rgb "#d62728" notitle, \
  'fig13_strong_fabric_medium_test1.dat' u 1:2 w l lw 1 lc rgb "#2ca02c" t "medium (Tests 1, 2, 3, 4, 5)", \
  'fig13_strong_fabric_medium_test2.dat' u 1:2 w l lw 1 lc rgb "#2ca02c" notitle, \
  'fig13_strong_fabric_medium_test3.dat' u 1:2 w l lw 1 lc rgb "#2ca02c" notitle, \
  'fig13_strong_fabric_medium_test4.dat' u 1:2 w l lw 1 lc rgb "#2ca02c" notitle, \
  'fig13_strong_fabric_medium_test5.dat' u 1:2 w l lw 1 lc rgb "#2ca02c" notitle, \
  'fig13_strong_fabric_dense_test1.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "dense (Tests 1, 2, 3, 4, 5)", \
  'fig13_strong_fabric_dense_test2.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" notitle, \
  'fig13_strong_fabric_dense_test3.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" notitle, \
  'fig13_strong_fabric_dense_test4.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" notitle, \
  'fig13_strong_fabric_dense_test5.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" notitle, \
  x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'
unset label 99
