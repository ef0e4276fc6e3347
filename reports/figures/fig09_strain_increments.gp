set terminal pngcairo size 1800,1480 font ",11" enhanced
set output "fig09_strain_increments.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 3,4 title "Fig. 9  Strain increment vectors on the normalised π-plane, cycles 1 and 5: one arrow per leg (numbered in order), drawn from the measured stress at the end of the leg\n(A) loose Test 1, (B) dense Test 1, (C) loose Test 2, (D) dense Test 2, (E) loose Test 4, (F) dense Test 4;  1 = 1st cycle, 2 = 5th cycle" font ",13"
set xlabel "π-plane x  (stress: /p;  Δε: × scale)" font ",10"; set ylabel "π-plane y" font ",10"; set key bottom right font ",8"
set size ratio -1
set xrange [-0.33:0.33]; set yrange [-0.33:0.33]
set arrow 1 from 0,0 to 0,0.83*0.33 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 2 from 0,0 to -0.83*0.33*0.8660254,-0.83*0.33*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 3 from 0,0 to 0.83*0.33*0.8660254,-0.83*0.33*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set label 1 "σ_1" at 0,0.9*0.33 center font ",12" tc rgb "#555555"
set label 2 "σ_2" at -0.87*0.33*0.8660254,-0.93*0.33*0.5 right font ",12" tc rgb "#555555"
set label 3 "σ_3" at 0.87*0.33*0.8660254,-0.93*0.33*0.5 left font ",12" tc rgb "#555555"
set title "(A1) loose, Test 1, cycle 1\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test1_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test1_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test1_cycle1.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test1_cycle1.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(A2) loose, Test 1, cycle 5\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test1_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test1_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test1_cycle5.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test1_cycle5.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(B1) dense, Test 1, cycle 1\narrows: Δε × 500  (0.1 on the axes = 0.02 % strain)" font ",11"
plot 'fig03_test1_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test1_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test1_cycle1.dat' u 1:2:($3*500):($4*500) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test1_cycle1.dat' u ($1+$3*500):($2+$4*500):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(B2) dense, Test 1, cycle 5\narrows: Δε × 500  (0.1 on the axes = 0.02 % strain)" font ",11"
plot 'fig03_test1_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test1_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test1_cycle5.dat' u 1:2:($3*500):($4*500) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test1_cycle5.dat' u ($1+$3*500):($2+$4*500):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(C1) loose, Test 2, cycle 1\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test2_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test2_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test2_cycle1.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test2_cycle1.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(C2) loose, Test 2, cycle 5\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test2_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test2_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test2_cycle5.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test2_cycle5.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(D1) dense, Test 2, cycle 1\narrows: Δε × 1000  (0.1 on the axes = 0.01 % strain)" font ",11"
plot 'fig03_test2_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test2_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test2_cycle1.dat' u 1:2:($3*1000):($4*1000) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test2_cycle1.dat' u ($1+$3*1000):($2+$4*1000):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(D2) dense, Test 2, cycle 5\narrows: Δε × 1000  (0.1 on the axes = 0.01 % strain)" font ",11"
plot 'fig03_test2_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test2_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test2_cycle5.dat' u 1:2:($3*1000):($4*1000) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test2_cycle5.dat' u ($1+$3*1000):($2+$4*1000):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(E1) loose, Test 4, cycle 1\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test4_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test4_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test4_cycle1.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test4_cycle1.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(E2) loose, Test 4, cycle 5\narrows: Δε × 100  (0.1 on the axes = 0.1 % strain)" font ",11"
plot 'fig03_test4_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_loose_test4_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#d62728" t "measured stress", \
  'fig09_loose_test4_cycle5.dat' u 1:2:($3*100):($4*100) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_loose_test4_cycle5.dat' u ($1+$3*100):($2+$4*100):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(F1) dense, Test 4, cycle 1\narrows: Δε × 1000  (0.1 on the axes = 0.01 % strain)" font ",11"
plot 'fig03_test4_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test4_cycle1_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test4_cycle1.dat' u 1:2:($3*1000):($4*1000) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test4_cycle1.dat' u ($1+$3*1000):($2+$4*1000):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
set title "(F2) dense, Test 4, cycle 5\narrows: Δε × 1000  (0.1 on the axes = 0.01 % strain)" font ",11"
plot 'fig03_test4_target.dat' u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
  'fig09_dense_test4_cycle5_path.dat' u 1:2 w l lw 1 lc rgb "#1f77b4" t "measured stress", \
  'fig09_dense_test4_cycle5.dat' u 1:2:($3*1000):($4*1000) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
  'fig09_dense_test4_cycle5.dat' u ($1+$3*1000):($2+$4*1000):6 w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" t ""
unset label 99
unset multiplot
