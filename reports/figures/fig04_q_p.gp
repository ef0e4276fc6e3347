set terminal pngcairo size 1800,620 font ",11" enhanced
set output "fig04_q_p.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 4  Deviator stress q against mean stress p, all cycles of all tests (q from the principal values of the full stress tensor)" font ",13"
set xlabel "mean stress p (kPa)"; set ylabel "deviator stress q (kPa)"; set key bottom right

set xrange [90:110]; set yrange [0:30]
set title "(A) dense" font ",12"
plot 'fig04_q_p_dense_test1.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#000000" t "Test 1", \
  'fig04_q_p_dense_test2.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#ff7f0e" t "Test 2", \
  'fig04_q_p_dense_test3.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#9467bd" t "Test 3", \
  'fig04_q_p_dense_test4.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#17a2b8" t "Test 4", \
  'fig04_q_p_dense_test5.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#8c564b" t "Test 5", \
  22.222 w l dt 2 lw 1 lc rgb '#777777' t 'target q at TC (22.2 kPa)', \
  20.690 w l dt 3 lw 1 lc rgb '#777777' t 'target q at TE (20.7 kPa)'
unset label 99
set xrange [90:110]; set yrange [0:30]
set title "(B) medium" font ",12"
plot 'fig04_q_p_medium_test1.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#000000" t "Test 1", \
  'fig04_q_p_medium_test2.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#ff7f0e" t "Test 2", \
  'fig04_q_p_medium_test3.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#9467bd" t "Test 3", \
  'fig04_q_p_medium_test4.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#17a2b8" t "Test 4", \
  'fig04_q_p_medium_test5.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#8c564b" t "Test 5", \
  22.222 w l dt 2 lw 1 lc rgb '#777777' t 'target q at TC (22.2 kPa)', \
  20.690 w l dt 3 lw 1 lc rgb '#777777' t 'target q at TE (20.7 kPa)'
unset label 99
set xrange [90:110]; set yrange [0:30]
set title "(C) loose" font ",12"
plot 'fig04_q_p_loose_test1.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#000000" t "Test 1", \
  'fig04_q_p_loose_test2.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#ff7f0e" t "Test 2", \
  'fig04_q_p_loose_test3.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#9467bd" t "Test 3", \
  'fig04_q_p_loose_test4.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#17a2b8" t "Test 4", \
  'fig04_q_p_loose_test5.dat' u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb "#8c564b" t "Test 5", \
  22.222 w l dt 2 lw 1 lc rgb '#777777' t 'target q at TC (22.2 kPa)', \
  20.690 w l dt 3 lw 1 lc rgb '#777777' t 'target q at TE (20.7 kPa)'
unset label 99
unset multiplot
