set terminal pngcairo size 1800,660 font ",11" enhanced
set output "fig12_fabric.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 12  Stress ratio q/p against the fabric ratio F_d/F_m of all contacts, first 5 cycles of all tests" font ",13"
set xlabel "F_d/F_m (all contacts, Eq. 8)"; set ylabel "stress ratio q/p"; set key top left; set size ratio -1
set xrange [0:0.30]; set yrange [0:0.30]; set title "(A) loose" font ",12"
plot 'fig12_fabric_loose_test1.dat' u 1:2 w l lw 1.2 lc rgb "#000000" t "Test 1", \
  'fig12_fabric_loose_test2.dat' u 1:2 w l lw 1.2 lc rgb "#ff7f0e" t "Test 2", \
  'fig12_fabric_loose_test3.dat' u 1:2 w l lw 1.2 lc rgb "#9467bd" t "Test 3", \
  'fig12_fabric_loose_test4.dat' u 1:2 w l lw 1.2 lc rgb "#17a2b8" t "Test 4", \
  'fig12_fabric_loose_test5.dat' u 1:2 w l lw 1.2 lc rgb "#8c564b" t "Test 5", \
  x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'
unset label 99
set xrange [0:0.30]; set yrange [0:0.30]; set title "(B) medium" font ",12"
plot 'fig12_fabric_medium_test1.dat' u 1:2 w l lw 1.2 lc rgb "#000000" t "Test 1", \
  'fig12_fabric_medium_test2.dat' u 1:2 w l lw 1.2 lc rgb "#ff7f0e" t "Test 2", \
  'fig12_fabric_medium_test3.dat' u 1:2 w l lw 1.2 lc rgb "#9467bd" t "Test 3", \
  'fig12_fabric_medium_test4.dat' u 1:2 w l lw 1.2 lc rgb "#17a2b8" t "Test 4", \
  'fig12_fabric_medium_test5.dat' u 1:2 w l lw 1.2 lc rgb "#8c564b" t "Test 5", \
  x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'
unset label 99
set xrange [0:0.30]; set yrange [0:0.30]; set title "(C) dense" font ",12"
plot 'fig12_fabric_dense_test1.dat' u 1:2 w l lw 1.2 lc rgb "#000000" t "Test 1", \
  'fig12_fabric_dense_test2.dat' u 1:2 w l lw 1.2 lc rgb "#ff7f0e" t "Test 2", \
  'fig12_fabric_dense_test3.dat' u 1:2 w l lw 1.2 lc rgb "#9467bd" t "Test 3", \
  'fig12_fabric_dense_test4.dat' u 1:2 w l lw 1.2 lc rgb "#17a2b8" t "Test 4", \
  'fig12_fabric_dense_test5.dat' u 1:2 w l lw 1.2 lc rgb "#8c564b" t "Test 5", \
  x w l dt 2 lw 1.5 lc rgb '#777777' t '1:1'
unset label 99
unset multiplot
