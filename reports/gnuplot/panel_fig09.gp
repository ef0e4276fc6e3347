# One panel of Fig. 9 (called by fig09_strain_increments.gp and fig09_all_tests.gp):
#   call 'panel_fig09.gp' DENSITY TEST WHICH LABEL     WHICH: 1 = cycle 1, 5 = cycle 5 (or the last run)
# The arrows start at the measured stress at the end of each leg and are the leg's strain increment
# in the π-plane times the panel's scale (fig09_scale_<density>_test<t>: the same for both cycles and for every density of a test, so arrow lengths compare across a panel row).
d = ARG1; t = ARG2 + 0; which = ARG3 + 0; lbl = ARG4
if (!has(d, t)) {
  set title sprintf("%s%s, Test %d, cycle %d", lbl, d, t, which) font ",11"
  eval not_run
  plot NaN notitle
  eval not_run_off
} else {
  c = which == 1 ? 1 : value(sprintf("fig09_cycle5_%s_test%d", d, t))
  s = value(sprintf("fig09_scale_%s_test%d", d, t))
  set title sprintf("%s%s, Test %d, cycle %d%s\narrows: Δε × %g  (0.1 on the axes = %.3g %% strain)", lbl, d, t, c, \
                    (which == 5 && c != 5) ? sprintf(" (only %d cycles run)", c) : "", s, 10.0 / s) font ",11"
  base = sprintf("fig09_%s_test%d_cycle%d", d, t, which)
  plot sprintf("fig03_test%d_target.dat", t) u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
       base . "_path.dat" u 1:2 w l lw 1 lc rgb density_colour(d) t "measured stress", \
       base . ".dat" u 1:2:5:6 w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
       base . ".dat" u ($1 + $5):($2 + $6):(sprintf("%d", $8)) w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" notitle
}
