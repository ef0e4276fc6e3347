# Fig. 6: ε_v against σ_1/σ_3 (Tests 1, 4, 5; top row) and against q/p (Tests 2, 3; bottom row),
# first 5 cycles. Data: fig06_epsv_<density>_test<t>.dat (figure-data; column 1 is σ11/σ33 or q/p).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,1050 font ",11" enhanced
set output 'fig06_epsv.png'
set multiplot layout 2,3 title "Fig. 6  Volumetric strain ε_v = 1 − V/V_0 (compression +), first 5 cycles: against σ_1/σ_3 for Tests 1, 4, 5 (top) and against q/p for Tests 2, 3 (bottom)" font ",13"
set ylabel "ε_v (%)"; set key top left; set offsets 0, 0, graph 0.25, 0
do for [row = 1:2] {
  i = 0
  do for [d in densities] {
    i = i + 1
    if (row == 1) {
      set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set xrange [0.75:1.3]
      set title sprintf("(%s) %s: Tests 1, 4, 5 against σ_1/σ_3", letter(i), d) font ",12"
      tests = "1 4 5"
    } else {
      set xlabel "stress ratio q/p"; set xrange [0:0.3]
      set title sprintf("(%s) %s: Tests 2, 3 against q/p", letter(i), d) font ",12"
      tests = "2 3"
    }
    any = 0
    do for [t in tests] { any = any + has(d, t + 0) }
    if (!any) { eval not_run; set yrange [0:1] } else { set yrange [*:*] }
    plot for [t in tests] sprintf("fig06_epsv_%s_test%s.dat", d, t) u 1:2 w l lw 1.4 lc rgb test_colour(t + 0) t test_title(d, t + 0)
    eval not_run_off
  }
}
unset multiplot
