set terminal pngcairo size 1800,1050 font ",11" enhanced
set output "fig06_epsv.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 2,3 title "Fig. 6  Volumetric strain ε_v = 1 − V/V_0 (compression +), first 5 cycles: against σ_1/σ_3 for Tests 1, 4, 5 (top) and against q/p for Tests 2, 3 (bottom)" font ",13"
set ylabel "ε_v (%)"; set key top left; set offsets 0, 0, graph 0.25, 0
set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set xrange [0.75:1.3]; set yrange [*:*]
set title "(A) loose: Tests 1, 4, 5 against σ_1/σ_3" font ",12"
plot 'fig06_epsv_loose_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig06_epsv_loose_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig06_epsv_loose_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set xrange [0.75:1.3]; set yrange [*:*]
set title "(B) medium: Tests 1, 4, 5 against σ_1/σ_3" font ",12"
plot 'fig06_epsv_medium_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig06_epsv_medium_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig06_epsv_medium_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set xrange [0.75:1.3]; set yrange [*:*]
set title "(C) dense: Tests 1, 4, 5 against σ_1/σ_3" font ",12"
plot 'fig06_epsv_dense_test1.dat' u 1:2 w l lw 1.4 lc rgb "#000000" t "Test 1", \
  'fig06_epsv_dense_test4.dat' u 1:2 w l lw 1.4 lc rgb "#17a2b8" t "Test 4", \
  'fig06_epsv_dense_test5.dat' u 1:2 w l lw 1.4 lc rgb "#8c564b" t "Test 5"
unset label 99
set xlabel "stress ratio q/p"; set xrange [0:0.3]; set yrange [*:*]
set title "(A) loose: Tests 2, 3 against q/p" font ",12"
plot 'fig06_epsv_loose_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig06_epsv_loose_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3"
unset label 99
set xlabel "stress ratio q/p"; set xrange [0:0.3]; set yrange [*:*]
set title "(B) medium: Tests 2, 3 against q/p" font ",12"
plot 'fig06_epsv_medium_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig06_epsv_medium_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3"
unset label 99
set xlabel "stress ratio q/p"; set xrange [0:0.3]; set yrange [*:*]
set title "(C) dense: Tests 2, 3 against q/p" font ",12"
plot 'fig06_epsv_dense_test2.dat' u 1:2 w l lw 1.4 lc rgb "#ff7f0e" t "Test 2", \
  'fig06_epsv_dense_test3.dat' u 1:2 w l lw 1.4 lc rgb "#9467bd" t "Test 3"
unset label 99
unset multiplot
