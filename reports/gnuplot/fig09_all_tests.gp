# Fig. 9 for every test of each density (beyond the paper's selection): fig09_all_tests_<density>.png,
# cycle 1 on top, cycle 5 below; the panels of panel_fig09.gp.
load 'style.gp'
load 'values.gp'
do for [dd in densities] {
  set terminal pngcairo size 2250,1000 font ",11" enhanced
  set output sprintf("fig09_all_tests_%s.png", dd)
  set multiplot layout 2,5 title sprintf("Fig. 9 (all tests, %s)  Strain increment vectors on the normalised π-plane, one arrow per leg, from the measured stress at the end of the leg: cycle 1 (top), cycle 5 (bottom);\neach test has its own arrow scale, stated on the panel (the bar at its top left)", dd) font ",13"
  set xlabel "x" font ",10"; set ylabel "y" font ",10"; set key bottom right font ",8"
  pi_r = 0.33; eval pi_axes
  do for [which in "1 5"] {
    do for [t = 1:5] {
      call 'panel_fig09.gp' dd t which ""
    }
  }
  unset multiplot
}
