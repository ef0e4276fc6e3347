# A calibration's figures, from the data calibrate writes to its report folder (run there):
#   posterior.png: each parameter's posterior density over its prior's (marginal_<j>.dat, over the
#     posterior's range), the truth as a dashed line when the references were made by the engine,
#     and, for two or more parameters, the plane of the first two near the posterior: points drawn
#     from it (posterior_points.dat), the sets run there (sets.dat) and the truth;
#   curves.png: each reference curve (with its specimens' sd) and the best set's samples.
# Values: values.gp (calibrate). The axes are linear: they span the posterior (-+ 6 sd), not the prior. gnuplot calibration.gp, in the report folder.
load 'values.gp'
load 'style.gp'
set terminal pngcairo size 1200,450 font ",11" enhanced
set output 'posterior.png'
n = int(parameters)
panels = n + (n >= 2 ? 1 : 0)
set multiplot layout 1, panels title "Posterior over the prior (bars, over the posterior's range; dashed: the truth when known)" font ",12"
unset logscale
unset key
set format x "%.3g"
set format y "%.3g"
set xtics rotate by -30
do for [j = 1:n] {
  set xlabel value(sprintf("parameter_%d", j)) noenhanced
  set ylabel "posterior density / prior density"
  t = value(sprintf("truth_%d", j))
  unset arrow
  if (t == t) { set arrow 1 from first t, graph 0 to first t, graph 1 nohead dt 2 lw 2 lc rgb "#d62728" }
  set yrange [0:*]
  set xrange [value(sprintf("low_%d", j)):value(sprintf("high_%d", j))]
  plot sprintf("marginal_%d.dat", j) u 2:(0):1:3:(0):4 w boxxyerror fs solid 0.5 lc rgb "#1f77b4" notitle
}
if (n >= 2) {
  unset arrow
  set key
  set xrange [value("low_1"):value("high_1")]
  set yrange [value("low_2"):value("high_2")]
  set xlabel value("parameter_1") noenhanced
  set ylabel value("parameter_2") noenhanced
  set title "near the posterior" font ",11"
  set key top right box opaque font ",9"
  t1 = value("truth_1"); t2 = value("truth_2")
  plot "posterior_points.dat" u 1:2 w p pt 7 ps 0.3 lc rgb "#801f77b4" t "posterior", \
       "sets.dat" u 2:3 w p pt 6 ps 1.2 lw 1.5 lc rgb "#333333" t "sets run", \
       (t1 == t1 ? "+" : "") u (t1):(t2) every ::0::0 w p pt 3 ps 3 lw 2 lc rgb "#d62728" t "truth"
  unset title
}
unset multiplot
set format x "% h"
set format y "% h"
set xtics norotate

set output 'curves.png'
m = int(curves)
set terminal pngcairo size (m > 1 ? 600 * m : 800), 450 font ",11" enhanced
set output 'curves.png'
unset logscale
set autoscale xy
set multiplot layout 1, m title "References (points: mean ± sd) and the best set's samples (lines)" font ",12"
do for [k = 1:m] {
  set xlabel value(sprintf("curve_x_%d", k)) noenhanced
  set ylabel value(sprintf("curve_y_%d", k)) noenhanced
  set title value(sprintf("curve_title_%d", k)) noenhanced
  set key bottom right
  plot sprintf("curve_%d.dat", k) index 0 u 1:2:3 w yerrorbars pt 7 ps 1 lc rgb "#000000" t "reference", \
       for [b = 1:int(samples)] sprintf("curve_%d.dat", k) index b u 1:2 w l lw 1.5 lc rgb "#1f77b4" t (b == 1 ? "best set" : "")
}
unset multiplot
