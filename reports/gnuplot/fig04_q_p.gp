# Fig. 4: q against p, every row of every test; panels (A) dense (B) medium (C) loose, the caption's
# order. Dashed: the target q at the TC and TE states (fig04_targets.dat, from p and R of the
# scenes). Data: fig04_q_p_<density>_test<t>.dat (figure-data).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig04_q_p.png'
set multiplot layout 1,3 title "Fig. 4  Deviator stress q against mean stress p, all cycles of all tests (q from the principal values of the full stress tensor)" font ",13"
set xlabel "mean stress p (kPa)"; set ylabel "deviator stress q (kPa)"; set key bottom right
set xrange [mean_stress_kPa - 10:mean_stress_kPa + 10]; set yrange [0:30]
i = 0
do for [d in "dense medium loose"] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  if (!has_density(d)) { eval not_run }
  plot for [t = 1:5] sprintf("fig04_q_p_%s_test%d.dat", d, t) u 1:2 w lp lw 1 pt 7 ps 0.35 lc rgb test_colour(t) t test_title(d, t), \
       q_tc_kPa w l dt 2 lw 1 lc rgb "#777777" t sprintf("target q at TC (%.1f kPa)", q_tc_kPa), \
       q_te_kPa w l dt 3 lw 1 lc rgb "#777777" t sprintf("target q at TE (%.1f kPa)", q_te_kPa)
  eval not_run_off
}
unset multiplot
