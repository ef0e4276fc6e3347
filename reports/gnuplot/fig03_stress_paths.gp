# Fig. 3: stress paths on the normalised π-plane, target (from /legs) and measured (every row), one
# panel per test (A)-(E) and all five targets overlaid (E′). Data: fig03_test<t>_target.dat,
# fig03_<density>_test<t>.dat, fig03_states.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1650,1130 font ",11" enhanced
set output 'fig03_stress_paths.png'
set multiplot layout 2,3 title sprintf("Fig. 3  Stress paths on the normalised π-plane (p = %g kPa, σ_{max}/σ_{min} = %g): target (grey, arrows) and measured\nx = (σ_3 − σ_2)/(√2 p),  y = (2σ_1 − σ_2 − σ_3)/(√6 p); measured: from the axis stresses σ_{11}, σ_{22}, σ_{33}", mean_stress_kPa, stress_ratio) font ",13"
set xlabel "(σ_3 − σ_2)/(√2 p)"; set ylabel "(2σ_1 − σ_2 − σ_3)/(√6 p)"
set key top right font ",9" samplen 1.5
pi_r = 0.3; eval pi_axes
panel_title(t) = t == 1 ? "(A) Test 1: triangle, 5 cycles counter-clockwise then 5 clockwise" : \
                 t == 2 ? "(B) Test 2: loading–unloading on axes 1, 2, 3" : \
                 t == 3 ? "(C) Test 3: compression and extension on each axis" : \
                 t == 4 ? "(D) Test 4: Mohr–Coulomb hexagon" : "(E) Test 5: A↔TC1 ×10, A↔TC3 ×10, ×5, ×5 (caption: ‘Tests 1–5’)"
do for [t = 1:5] {
  set title panel_title(t) font ",11"
  plot sprintf("fig03_test%d_target.dat", t) u 1:2:3:4 w vectors head filled size graph 0.03,20 lw 4 lc rgb "#aaaaaa" t "target path", \
       for [d in densities] sprintf("fig03_%s_test%d.dat", d, t) u 1:2 w l lw 1.3 lc rgb density_colour(d) t (has(d, t) ? d : d . ": not run"), \
       "fig03_states.dat" u (state_x($2, $3)):(state_y($2, $3)):1 w labels font ",9" notitle
}
# (E′): Test 5's legs are a subset of Test 2's, which are a subset of Test 3's: drawn wide to narrow.
target_width(t) = t == 3 ? 7 : t == 2 ? 4 : t == 5 ? 1.5 : 2
set title "(E′) all five target paths overlaid" font ",11"
plot for [t in "3 2 5 1 4"] sprintf("fig03_test%s_target.dat", t) u 1:2:3:4 w vectors head filled size graph 0.03,20 lw target_width(t + 0) lc rgb test_colour(t + 0) notitle, \
     for [t = 1:5] NaN w l lw target_width(t) lc rgb test_colour(t) t sprintf("Test %d", t), \
     "fig03_states.dat" u (state_x($2, $3)):(state_y($2, $3)):1 w labels font ",9" notitle
unset multiplot
