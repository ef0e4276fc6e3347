# Fig. 9: strain increment vectors on the π-plane, cycles 1 and 5, the caption's selection: rows
# Tests 1, 2, 4; (A)/(C)/(E) loose, (B)/(D)/(F) dense; suffix 1 = cycle 1, 2 = cycle 5.
# Data: fig09_<density>_test<t>_cycle{1,5}[_path].dat, fig03_test<t>_target.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,1480 font ",11" enhanced
set output 'fig09_strain_increments.png'
set multiplot layout 3,4 title "Fig. 9  Strain increment vectors on the normalised π-plane, cycles 1 and 5: one arrow per leg (numbered in order), drawn from the measured stress at the end of the leg\n(A) loose Test 1, (B) dense Test 1, (C) loose Test 2, (D) dense Test 2, (E) loose Test 4, (F) dense Test 4;  1 = 1st cycle, 2 = 5th cycle\nEach density and test has its own arrow scale (the same in both cycles), stated on the panel with a bar at its top left" font ",13"
set xlabel "π-plane x  (stress: /p;  Δε: × scale)" font ",10"; set ylabel "π-plane y" font ",10"; set key bottom right font ",8"
pi_r = 0.33; eval pi_axes
k = 0
do for [t in "1 2 4"] {
  do for [d in "loose dense"] {
    k = k + 1
    call 'panel_fig09.gp' d t 1 sprintf("(%s1) ", letter(k))
    call 'panel_fig09.gp' d t 5 sprintf("(%s2) ", letter(k))
  }
}
unset multiplot
