set terminal pngcairo size 1800,620 font ",11" enhanced
set output "fig05_qp_epsd.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 5  Stress ratio q/p against deviatoric strain ε_d, first 5 cycles of all tests (strains from the start of shearing)\nε_d of paper Eq. 4: √(2/3 [(ε_1−ε_2)^2 + (ε_2−ε_3)^2 + (ε_1−ε_3)^2]) = √3 × the usual equivalent strain" font ",13"
set xlabel "ε_d (%)  (paper Eq. 4)"; set ylabel "stress ratio q/p"; set key bottom right

set xrange [0:*]; set yrange [0:0.3]
set title "(A) loose" font ",12"
plot 'fig05_qp_epsd_loose_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig05_qp_epsd_loose_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig05_qp_epsd_loose_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3", \
  'fig05_qp_epsd_loose_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig05_qp_epsd_loose_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
set xrange [0:*]; set yrange [0:0.3]
set title "(B) medium" font ",12"
plot 'fig05_qp_epsd_medium_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig05_qp_epsd_medium_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig05_qp_epsd_medium_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3", \
  'fig05_qp_epsd_medium_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig05_qp_epsd_medium_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
set xrange [0:*]; set yrange [0:0.3]
set title "(C) dense" font ",12"
plot 'fig05_qp_epsd_dense_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig05_qp_epsd_dense_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig05_qp_epsd_dense_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3", \
  'fig05_qp_epsd_dense_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig05_qp_epsd_dense_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
unset multiplot
