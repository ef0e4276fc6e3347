# A calibration's figures, from the data calibrate writes to its report folder (run there):
#   posterior.png: each parameter's posterior density over its prior's (marginal_<j>.dat, over the
#     posterior's range; a parameter of values: a bar per value), the truth as a dashed line when
#     the references were made by the engine, and, with two or more continuous parameters, the
#     plane of the two most correlated (pair_a, pair_b) near the posterior: points drawn from it
#     (posterior_points.dat), the sets run there (sets.dat) and the truth;
#   curves.png: each reference curve (with its specimens' sd) and the best set's samples (none
#     when the references have no curves).
# Values: values.gp (calibrate). The axes span the posterior (-+ 6 sd), not the prior; a
# log-uniform parameter's axis is logarithmic where it spans a factor of 4 or more. gnuplot calibration.gp, in the report folder.
load 'values.gp'
load 'style.gp'
n = int(parameters)
if (!exists("pair_a")) { pair_a = (n >= 2 ? 1 : 0); pair_b = (n >= 2 ? 2 : 0) }
pa = int(pair_a); pb = int(pair_b)
panels = n + (pa > 0 ? 1 : 0)
# One row up to 4 panels, else rows of 4 (7 readings: 2 rows).
columns = panels <= 4 ? panels : 4
rows = (panels + columns - 1) / columns
set terminal pngcairo size (columns < 3 ? 900 : 300 * columns), 60 + 360 * rows font ",11" enhanced  # 900: the title's width
set output 'posterior.png'
set multiplot layout rows, columns title "Posterior over the prior (bars, over the posterior's range; dashed: the truth when known)" font ",12"
unset key
set format y "%.3g"
set xtics rotate by -30 font ",9"
do for [j = 1:n] {
  set xlabel value(sprintf("parameter_%d", j)) noenhanced
  set ylabel (j - 1) % columns == 0 ? "posterior density / prior density" : ""
  t = value(sprintf("truth_%d", j))
  unset arrow
  unset logscale
  if (t == t) { set arrow 1 from first t, graph 0 to first t, graph 1 nohead dt 2 lw 2 lc rgb "#d62728" }
  set yrange [0:*]
  if (value(sprintf("discrete_%d", j)) > 0) {
    # A bar per value, labelled with it; the prior is flat at 1.
    set xrange [-0.6:value(sprintf("values_%d", j)) - 0.4]
    set xtics norotate font ",10" noenhanced
    set arrow 2 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb "#555555"
    plot sprintf("marginal_%d.dat", j) u 2:(0):1:3:(0):4:xtic(5) w boxxyerror fs solid 0.5 lc rgb "#1f77b4" notitle
    set xtics rotate by -30 font ",9" enhanced
  } else {
    set xtics autofreq
    set format x "%.3g"
    # A log-uniform parameter over a factor of 4 or more: a log axis, a tic per factor 2 (over
    # less, a linear axis reads better: a log one would have no tic in it).
    if (value(sprintf("log_%d", j)) > 0 && value(sprintf("high_%d", j)) >= 4 * value(sprintf("low_%d", j))) { set logscale x; set xtics 2 }
    set xrange [value(sprintf("low_%d", j)):value(sprintf("high_%d", j))]
    plot sprintf("marginal_%d.dat", j) u 2:(0):1:3:(0):4 w boxxyerror fs solid 0.5 lc rgb "#1f77b4" notitle
  }
}
if (pa > 0) {
  unset arrow
  unset logscale
  set xtics autofreq
  set ytics autofreq
  set format x "%.3g"
  set format y "%.3g"
  if (value(sprintf("log_%d", pa)) > 0 && value(sprintf("high_%d", pa)) >= 4 * value(sprintf("low_%d", pa))) { set logscale x; set xtics 2 }
  if (value(sprintf("log_%d", pb)) > 0 && value(sprintf("high_%d", pb)) >= 4 * value(sprintf("low_%d", pb))) { set logscale y; set ytics 2 }
  set key
  set xrange [value(sprintf("low_%d", pa)):value(sprintf("high_%d", pa))]
  set yrange [value(sprintf("low_%d", pb)):value(sprintf("high_%d", pb))]
  set xlabel value(sprintf("parameter_%d", pa)) noenhanced
  set ylabel value(sprintf("parameter_%d", pb)) noenhanced
  set title (n > 2 ? "the most correlated pair" : "near the posterior") font ",11"
  set key top right box opaque font ",9"
  t1 = value(sprintf("truth_%d", pa)); t2 = value(sprintf("truth_%d", pb))
  # The truth's marker only when the truth is known (NaN otherwise).
  truth_plot = (t1 == t1) ? sprintf(', "+" u (%.17g):(%.17g) every ::0::0 w p pt 3 ps 3 lw 2 lc rgb "#d62728" t "truth"', t1, t2) : ""
  eval('plot "posterior_points.dat" u pa:pb w p pt 7 ps 0.3 lc rgb "#801f77b4" t "posterior", ' . \
       '"sets.dat" u (column(pa + 1)):(column(pb + 1)) w p pt 6 ps 1.2 lw 1.5 lc rgb "#333333" t "sets run"' . truth_plot)
  unset title
  unset logscale
  set format y "%.3g"
}
unset multiplot
set format x "% h"
set format y "% h"
set xtics norotate

m = int(curves)
if (m > 0) {
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
}
