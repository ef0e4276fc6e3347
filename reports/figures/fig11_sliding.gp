set terminal pngcairo size 1800,620 font ",11" enhanced
set output "fig11_sliding.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 11  Sliding contact fraction N_s/N_c × 100 % (|f_t| ≥ μ f_n) at the end of each cycle, all tests — mean of 5 samples, band ± 1 standard deviation" font ",13"
set xlabel "cycle number"; set ylabel "sliding contact fraction N_s/N_c (%)"; set key top right
set offsets 0, 0.3, graph 0.4, 0
set xrange [0:*]; set yrange [0:*]
set title "(A) loose" font ",12"
plot 'fig11_sliding_loose_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig11_sliding_loose_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig11_sliding_loose_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig11_sliding_loose_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig11_sliding_loose_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig11_sliding_loose_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig11_sliding_loose_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig11_sliding_loose_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig11_sliding_loose_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig11_sliding_loose_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5"
unset label 99
set xrange [0:*]; set yrange [0:*]
set title "(B) medium" font ",12"
plot 'fig11_sliding_medium_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig11_sliding_medium_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig11_sliding_medium_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig11_sliding_medium_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig11_sliding_medium_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig11_sliding_medium_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig11_sliding_medium_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig11_sliding_medium_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig11_sliding_medium_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig11_sliding_medium_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5"
unset label 99
set xrange [0:*]; set yrange [0:*]
set title "(C) dense" font ",12"
plot 'fig11_sliding_dense_test1.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#000000" notitle, \
  'fig11_sliding_dense_test1.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#000000" t "Test 1", \
  'fig11_sliding_dense_test2.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#ff7f0e" notitle, \
  'fig11_sliding_dense_test2.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#ff7f0e" t "Test 2", \
  'fig11_sliding_dense_test3.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#9467bd" notitle, \
  'fig11_sliding_dense_test3.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#9467bd" t "Test 3", \
  'fig11_sliding_dense_test4.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#17a2b8" notitle, \
  'fig11_sliding_dense_test4.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#17a2b8" t "Test 4", \
  'fig11_sliding_dense_test5.dat' u 1:($2-$3):($2+$3) w filledcurves fs transparent solid 0.12 noborder lc rgb "#8c564b" notitle, \
  'fig11_sliding_dense_test5.dat' u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb "#8c564b" t "Test 5"
unset label 99
unset multiplot
