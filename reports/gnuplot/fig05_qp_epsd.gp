# Fig. 5: q/p against ε_d (paper Eq. 4), first 5 cycles (cycle 0, the A→TC1 leg of Tests 1 and 4,
# included). Data: fig05_qp_epsd_<density>_test<t>.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig05_qp_epsd.png'
set multiplot layout 1,3 title "Fig. 5  Stress ratio q/p against deviatoric strain ε_d, first 5 cycles of all tests (strains from the start of shearing)\nε_d of paper Eq. 4: √(2/3 [(ε_1−ε_2)^2 + (ε_2−ε_3)^2 + (ε_1−ε_3)^2]) = √3 × the usual equivalent strain" font ",13"
set xlabel "ε_d (%)  (paper Eq. 4)"; set ylabel "stress ratio q/p"; set key bottom right
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  set yrange [0:0.3]
  if (!has_density(d)) { eval not_run; set xrange [0:1] } else { set xrange [0:*] }
  plot for [t = 1:5] sprintf("fig05_qp_epsd_%s_test%d.dat", d, t) u 1:2 w l lw 1.4 lc rgb test_colour(t) t test_title(d, t)
  eval not_run_off
}
unset multiplot
