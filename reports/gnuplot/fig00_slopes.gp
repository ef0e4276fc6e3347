# The headline check after shearing: the slope of q/p against F^s_d/F^s_m (least squares through
# the origin over every shearing row of all five tests, the validation row's quantity) of every
# sample of the ensemble, per density, against the paper's "approximately 1" for all (Figs. 13-14).
# Data: fig00_slopes.dat (a label per sample, then density 1 loose, 2 medium, 3 dense; the slope;
# no row: the figure says "not run"); the paper's value and the row's tolerance from values.gp
# (paper_slope, paper_slope_tolerance): a black bar and a grey band.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 700,520 font ",12" enhanced
set output 'fig00_slopes.png'
set title sprintf("After shearing: the slope of q/p against F^s_d/F^s_m of each of the %d samples\nper density (dots), against the paper's ≈ %g for all (bar; band: ± %g)", samples_n, paper_slope, paper_slope_tolerance)
set xrange [0.5:3.5]
set xtics ("loose" 1, "medium" 2, "dense" 3)
set ylabel "slope of q/p against F^s_d/F^s_m"
unset key  # the densities are the x axis's labels
set offsets 0, 0, graph 0.08, graph 0.08
if (paper_slope_tolerance == paper_slope_tolerance && paper_slope == paper_slope) {  # no row of the paper: neither (NaN)
  # the whole band in view, whatever the samples' spread: autoscaled, but never inside it
  set yrange [* < (paper_slope - paper_slope_tolerance - 0.05) : (paper_slope + paper_slope_tolerance + 0.05) < *]
  set object 1 rectangle from graph 0, first paper_slope - paper_slope_tolerance to graph 1, first paper_slope + paper_slope_tolerance \
      fc rgb "#dddddd" fs solid 0.6 noborder behind
  set arrow 1 from graph 0, first paper_slope to graph 1, first paper_slope nohead lw 3 lc rgb "#000000" front
}
spread_x(k, row) = k + 0.08 * ((int(row) % samples_n) - (samples_n - 1) / 2.0)
if (fig00_slopes_rows == 0) {
  set yrange [0:2]; eval not_run
  plot NaN notitle
  eval not_run_off
} else {
  plot for [k=1:3] "fig00_slopes.dat" u ($2 == k ? spread_x(k, $0) : NaN):3 w p pt 7 ps 1.4 lc rgb density_colour(word(densities, k)) title word(densities, k)
}
