# One panel of Fig. 9 (called by fig09_strain_increments.gp and fig09_all_tests.gp):
#   call 'panel_fig09.gp' DENSITY TEST WHICH LABEL     WHICH: 1 = cycle 1, 5 = cycle 5 (or the last run)
# The arrows start at the measured stress at the end of each leg and are the leg's strain increment
# in the π-plane (columns 3-4 of fig09_<density>_test<t>_cycle{1,5}.dat) times the scale of this
# density and test: the same for both cycles, so that the panels of cycles 1 and 5 compare, but its
# own for each density (a dense sample's increments are about a tenth of a loose one's, and at a
# shared scale its arrows were shorter than their heads). The scale keeps the longest increment of
# the two cycles at 0.08-0.12 on the axes (0.12 / longest, rounded down to 1, 2 or 5 × 10^k); a bar
# at the top left of every panel is 0.1 on the axes and says how much strain that is.
d = ARG1; t = ARG2 + 0; which = ARG3 + 0; lbl = ARG4
unset arrow 10; unset label 10
if (!has(d, t)) {
  set title sprintf("%s%s, Test %d, cycle %d", lbl, d, t, which) font ",11"
  eval not_run
  plot NaN notitle
  eval not_run_off
} else {
  c = which == 1 ? 1 : value(sprintf("fig09_cycle5_%s_test%d", d, t))
  base = sprintf("fig09_%s_test%d_cycle%d", d, t, which)
  longest = 0
  do for [w in "1 5"] {
    undefine F9_*   # a file without data rows: stats warns and defines nothing, and the file counts as 0
    stats sprintf("fig09_%s_test%d_cycle%s.dat", d, t, w) using (sqrt($3**2 + $4**2)) nooutput name "F9"
    longest = !exists("F9_max") ? longest : F9_max > longest ? F9_max : longest
  }
  raw = longest > 0 ? 0.12 / longest : 1
  decade = 10**floor(log10(raw))
  s = (raw / decade >= 5 ? 5 : raw / decade >= 2 ? 2 : 1) * decade
  set title sprintf("%s%s, Test %d, cycle %d%s\narrows: Δε × %g (own scale; bar: %.3g %% strain)", \
                    lbl, d, t, c, (which == 5 && c != 5) ? sprintf(" (only %d cycles run)", c) : "", s, 10.0 / s) font ",11"
  set arrow 10 from graph 0.04, graph 0.94 rto first 0.1, first 0 heads size graph 0.012,90 lw 2.5 lc rgb "#000000" front
  set label 10 sprintf("%.3g %% strain", 10.0 / s) at graph 0.04, graph 0.89 left font ",9" front
  plot sprintf("fig03_test%d_target.dat", t) u 1:2:3:4 w vectors nohead lw 3 lc rgb "#dddddd" t "target path", \
       base . "_path.dat" u 1:2 w l lw 1 lc rgb density_colour(d) t "measured stress", \
       base . ".dat" u 1:2:($3 * s):($4 * s) w vectors head filled size graph 0.03,20 lw 2.2 lc rgb "#000000" t "strain increment of a leg", \
       base . ".dat" u ($1 + $3 * s):($2 + $4 * s):(sprintf("%d", $8)) w labels offset char 0.6,0.6 font ",9" tc rgb "#000000" notitle
  unset arrow 10; unset label 10
}
