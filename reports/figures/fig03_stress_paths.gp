set terminal pngcairo size 1650,1130 font ",11" enhanced
set output "fig03_stress_paths.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 2,3 title "Fig. 3  Stress paths on the normalised π-plane (p = 100 kPa, σ_{max}/σ_{min} = 1.24): target (grey, arrows) and measured\nx = (σ_3 − σ_2)/(√2 p),  y = (2σ_1 − σ_2 − σ_3)/(√6 p); measured: from the axis stresses σ_{11}, σ_{22}, σ_{33}" font ",13"
set xlabel "(σ_3 − σ_2)/(√2 p)"; set ylabel "(2σ_1 − σ_2 − σ_3)/(√6 p)"
set key top right font ",9" samplen 1.5
set label 11 "TC1" at 0,0.1815 offset 1.2,0.5 font ",9" front
set label 12 "TC2" at -0.1572,-0.0908 offset -1.5,-1 right font ",9" front
set label 13 "TC3" at 0.1572,-0.0908 offset 1.5,-1 left font ",9" front
set label 14 "TE1" at 0,-0.1690 offset 1,-0.8 font ",9" front
set label 15 "TE2" at 0.1464,0.0845 offset 1,0.5 left font ",9" front
set label 16 "TE3" at -0.1464,0.0845 offset -1,0.5 right font ",9" front
set label 17 "A" at 0,0 offset 0.8,-0.8 font ",9" front
set size ratio -1
set xrange [-0.3:0.3]; set yrange [-0.3:0.3]
set arrow 1 from 0,0 to 0,0.83*0.3 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 2 from 0,0 to -0.83*0.3*0.8660254,-0.83*0.3*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set arrow 3 from 0,0 to 0.83*0.3*0.8660254,-0.83*0.3*0.5 head filled size graph 0.025,20 dt 2 lc rgb "#888888" back
set label 1 "σ_1" at 0,0.9*0.3 center font ",12" tc rgb "#555555"
set label 2 "σ_2" at -0.87*0.3*0.8660254,-0.93*0.3*0.5 right font ",12" tc rgb "#555555"
set label 3 "σ_3" at 0.87*0.3*0.8660254,-0.93*0.3*0.5 left font ",12" tc rgb "#555555"
set title "(A) Test 1: triangle, 5 cycles counter-clockwise then 5 clockwise" font ",11"
plot 'fig03_test1_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
  'fig03_loose_test1.dat' u 1:2 w l lw 1.3 lc rgb "#d62728" t "loose", \
  'fig03_medium_test1.dat' u 1:2 w l lw 1.3 lc rgb "#2ca02c" t "medium", \
  'fig03_dense_test1.dat' u 1:2 w l lw 1.3 lc rgb "#1f77b4" t "dense"
unset label 99
set title "(B) Test 2: loading–unloading on axes 1, 2, 3" font ",11"
plot 'fig03_test2_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
  'fig03_loose_test2.dat' u 1:2 w l lw 1.3 lc rgb "#d62728" t "loose", \
  'fig03_medium_test2.dat' u 1:2 w l lw 1.3 lc rgb "#2ca02c" t "medium", \
  'fig03_dense_test2.dat' u 1:2 w l lw 1.3 lc rgb "#1f77b4" t "dense"
unset label 99
set title "(C) Test 3: compression and extension on each axis" font ",11"
plot 'fig03_test3_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
  'fig03_loose_test3.dat' u 1:2 w l lw 1.3 lc rgb "#d62728" t "loose", \
  'fig03_medium_test3.dat' u 1:2 w l lw 1.3 lc rgb "#2ca02c" t "medium", \
  'fig03_dense_test3.dat' u 1:2 w l lw 1.3 lc rgb "#1f77b4" t "dense"
unset label 99
set title "(D) Test 4: Mohr–Coulomb hexagon" font ",11"
plot 'fig03_test4_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
  'fig03_loose_test4.dat' u 1:2 w l lw 1.3 lc rgb "#d62728" t "loose", \
  'fig03_medium_test4.dat' u 1:2 w l lw 1.3 lc rgb "#2ca02c" t "medium", \
  'fig03_dense_test4.dat' u 1:2 w l lw 1.3 lc rgb "#1f77b4" t "dense"
unset label 99
set title "(E) Test 5: A↔TC1 ×10, A↔TC3 ×10, ×5, ×5 (caption: ‘Tests 1–5’)" font ",11"
plot 'fig03_test5_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
  'fig03_loose_test5.dat' u 1:2 w l lw 1.3 lc rgb "#d62728" t "loose", \
  'fig03_medium_test5.dat' u 1:2 w l lw 1.3 lc rgb "#2ca02c" t "medium", \
  'fig03_dense_test5.dat' u 1:2 w l lw 1.3 lc rgb "#1f77b4" t "dense"
unset label 99
set title "(E′) all five target paths overlaid" font ",11"
plot 'fig03_test3_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 7 lc rgb "#9467bd" notitle, \
  'fig03_test2_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#ff7f0e" notitle, \
  'fig03_test5_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 1.5 lc rgb "#8c564b" notitle, \
  'fig03_test1_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 2 lc rgb "#000000" notitle, \
  'fig03_test4_target.dat' u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 2 lc rgb "#17a2b8" notitle, \
  NaN w l lw 2 lc rgb "#000000" t "Test 1", \
  NaN w l lw 4 lc rgb "#ff7f0e" t "Test 2", \
  NaN w l lw 7 lc rgb "#9467bd" t "Test 3", \
  NaN w l lw 2 lc rgb "#17a2b8" t "Test 4", \
  NaN w l lw 1.5 lc rgb "#8c564b" t "Test 5"
unset label 99
unset multiplot
