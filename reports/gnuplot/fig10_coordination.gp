# Fig. 10: coordination number 2N_c/N_p (rattlers included) at the end of every cycle, all tests;
# cycle 0 is the start of shearing. Dashed: the paper's value before shearing (paper_cn_<density>,
# reference_data/paper.yaml). Mean and band as Fig. 7. Data: fig10_coordination_<density>_test<t>.dat.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig10_coordination.png'
set multiplot layout 1,3 title "Fig. 10  Coordination number 2N_c/N_p (rattlers included) at the end of each cycle, all tests" . ensemble_note(samples_n) font ",13"
set xlabel "cycle number (0 = start of shearing)"; set ylabel "coordination number"; set key top right
set offsets 0, 0.3, graph 0.4, graph 0.05
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s", letter(i), d) font ",12"
  cn = value("paper_cn_" . d)
  if (!has_density(d)) {
    eval not_run; set xrange [0:1]; set yrange [0:1]
    plot NaN notitle
  } else {
    set xrange [0:*]; set yrange [*:*]
    plot for [t = 1:5] sprintf("fig10_coordination_%s_test%d.dat", d, t) u 1:($2 - $3):($2 + $3) w filledcurves fs transparent solid 0.12 noborder lc rgb test_colour(t) notitle, \
         for [t = 1:5] sprintf("fig10_coordination_%s_test%d.dat", d, t) u 1:2 w lp lw 1.4 pt 7 ps 0.7 lc rgb test_colour(t) t test_title(d, t), \
         cn w l dt 2 lw 1.5 lc rgb "#777777" t sprintf("paper, before shearing (%.2f)", cn)
  }
  eval not_run_off
}
unset multiplot
