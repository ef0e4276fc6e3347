set terminal pngcairo size 1800,620 font ",11" enhanced
set output "fig10_coordination.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 10  Coordination number 2N_c/N_p (rattlers included) at the end of each cycle, all tests — mean of 5 samples, band ± 1 standard deviation" font ",13"
set xlabel "cycle number (0 = start of shearing)"; set ylabel "coordination number"; set key top right
set offsets 0, 0.3, graph 0.4, graph 0.05
set xrange [0:*]; set yrange [*:*]
set title "(A) loose" font ",12"
plot 'fig10_coordination_loose_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig10_coordination_loose_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig10_coordination_loose_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig10_coordination_loose_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig10_coordination_loose_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig10_coordination_loose_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig10_coordination_loose_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig10_coordination_loose_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig10_coordination_loose_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig10_coordination_loose_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5", \
  4.09 w l dt 2 lw 1.5 lc rgb '#777777' t 'paper, before shearing (4.09)'
unset label 99
set xrange [0:*]; set yrange [*:*]
set title "(B) medium" font ",12"
plot 'fig10_coordination_medium_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig10_coordination_medium_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig10_coordination_medium_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig10_coordination_medium_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig10_coordination_medium_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig10_coordination_medium_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig10_coordination_medium_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig10_coordination_medium_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig10_coordination_medium_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig10_coordination_medium_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5", \
  4.88 w l dt 2 lw 1.5 lc rgb '#777777' t 'paper, before shearing (4.88)'
unset label 99
set xrange [0:*]; set yrange [*:*]
set title "(C) dense" font ",12"
plot 'fig10_coordination_dense_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig10_coordination_dense_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig10_coordination_dense_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig10_coordination_dense_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig10_coordination_dense_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig10_coordination_dense_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig10_coordination_dense_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig10_coordination_dense_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig10_coordination_dense_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig10_coordination_dense_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5", \
  5.94 w l dt 2 lw 1.5 lc rgb '#777777' t 'paper, before shearing (5.94)'
unset label 99
unset multiplot
