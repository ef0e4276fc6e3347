# The decisions study's tornado charts, one per group of validation rows (tornado_<group>.png): the
# shift of the ensemble mean that each reading of the paper's open choices causes, in units of
# max(baseline standard deviation, the row's resolution) as compare-runs computes it (a row without
# a resolution in the references: the baseline sd alone), one bar per reading and row. Data: tornado_<group>.dat (row index, reading
# index, shift) and tornado_values.gp (groups, readings, row names, sizes), both written by
# build/bin/compare-runs decisions. Runs in reports/decisions/ (make decisions-report).
load 'style.gp'
load 'tornado_values.gp'
unset grid; set grid xtics
set key outside right noopaque nobox
set xlabel "shift of the mean / max(baseline standard deviation, the row's resolution)   (bars beyond ±10 are cut and labelled with their value)"
set xrange [-11:11]
clip(x) = x > 10 ? 10 : x < -10 ? -10 : x
set style fill solid 0.8 noborder
set arrow 1 from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
n = tornado_reading_n
h = 0.8 / (n > 0 ? n : 1)          # bar height: the readings of a row share 0.8 of its slot
offset(k) = (k - (n - 1) / 2.0) * h
do for [g in tornado_groups] {
  rows = value(sprintf("tornado_%s_row_n", g))
  set terminal pngcairo size 1400, value(sprintf("tornado_%s_height", g)) font 'Sans,10' noenhanced
  set output sprintf("tornado_%s.png", g)
  set title sprintf("%s: shift of the ensemble mean by each reading, in max(baseline sd, resolution)", value(sprintf("tornado_%s_title", g)))
  set yrange [-0.6:rows - 0.4]
  set ytics 0, 1 format ""
  unset label
  do for [i = 1:rows] { set label i value(sprintf("tornado_%s_row_%d", g, i)) at graph -0.01, first i - 1 right }
  set lmargin value(sprintf("tornado_%s_lmargin", g))
  file = sprintf("tornado_%s.dat", g)
  plot for [k = 0:n - 1] file using ($2 == k ? clip($3) / 2 : 1/0):($1 + offset(k)):(abs(clip($3)) / 2):(h / 2) \
         with boxxyerror lc k + 1 title value(sprintf("tornado_reading_%d", k + 1)), \
       file using (abs($3) > 10 ? clip($3) * 0.93 : 1/0):($1 + offset($2)):(sprintf('%+.0f', $3)) with labels font ',8' notitle
}
