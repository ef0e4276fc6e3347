set terminal pngcairo size 1800,620 font ",11" enhanced
set output "fig08_test5_epsv.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0
set multiplot layout 1,3 title "Fig. 8  Test 5: volumetric strain ε_v (compression +) against σ_1/σ_3 over all cycles, coloured by block of cycles" font ",13"
set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set ylabel "ε_v (%)"; set key top left; set xrange [0.75:1.3]; set yrange [*:*]; set offsets 0, 0, graph 0.3, 0
set title "(A) loose, Test 5" font ",12"
plot 'fig08_test5_loose.dat' u 1:2 index 0 w l lw 1.4 lc rgb "#1f77b4" t "cycles 1–10: A↔TC1 (steps 1–2)", \
  'fig08_test5_loose.dat' u 1:2 index 1 w l lw 1.4 lc rgb "#d62728" t "cycles 11–20: A↔TC3 (steps 3–4)", \
  'fig08_test5_loose.dat' u 1:2 index 2 w l lw 1.4 lc rgb "#2ca02c" t "cycles 21–25: A↔TC1 (steps 5–6)", \
  'fig08_test5_loose.dat' u 1:2 index 3 w l lw 1.4 lc rgb "#ff7f0e" t "cycles 26–30: A↔TC3 (steps 7–8)"
unset label 99
set title "(B) medium, Test 5" font ",12"
plot 'fig08_test5_medium.dat' u 1:2 index 0 w l lw 1.4 lc rgb "#1f77b4" t "cycles 1–10: A↔TC1 (steps 1–2)", \
  'fig08_test5_medium.dat' u 1:2 index 1 w l lw 1.4 lc rgb "#d62728" t "cycles 11–20: A↔TC3 (steps 3–4)", \
  'fig08_test5_medium.dat' u 1:2 index 2 w l lw 1.4 lc rgb "#2ca02c" t "cycles 21–25: A↔TC1 (steps 5–6)", \
  'fig08_test5_medium.dat' u 1:2 index 3 w l lw 1.4 lc rgb "#ff7f0e" t "cycles 26–30: A↔TC3 (steps 7–8)"
unset label 99
set title "(C) dense, Test 5" font ",12"
plot 'fig08_test5_dense.dat' u 1:2 index 0 w l lw 1.4 lc rgb "#1f77b4" t "cycles 1–10: A↔TC1 (steps 1–2)", \
  'fig08_test5_dense.dat' u 1:2 index 1 w l lw 1.4 lc rgb "#d62728" t "cycles 11–20: A↔TC3 (steps 3–4)", \
  'fig08_test5_dense.dat' u 1:2 index 2 w l lw 1.4 lc rgb "#2ca02c" t "cycles 21–25: A↔TC1 (steps 5–6)", \
  'fig08_test5_dense.dat' u 1:2 index 3 w l lw 1.4 lc rgb "#ff7f0e" t "cycles 26–30: A↔TC3 (steps 7–8)"
unset label 99
unset multiplot
