# The headline check before shearing: e0 and the coordination number of every sample of the
# ensemble, per density, against the paper's values (Table 1, §3.3). Data: fig00_samples.dat
# (a label per sample, then density 1 loose, 2 medium, 3 dense; e0; coordination number; no row:
# the panels say "not run"); the
# paper's values from values.gp (paper_e0_<density>, paper_cn_<density>), drawn as black bars.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1200,520 font ",12" enhanced
set output 'fig00_samples.png'
set multiplot layout 1,2 title sprintf("Before shearing: each of the %d samples per density (dots) against the paper's one sample (bars)", samples_n)
set xrange [0.5:3.5]
set xtics ("loose" 1, "medium" 2, "dense" 3)
unset key  # the densities are the x axis's labels
set offsets 0, 0, graph 0.08, graph 0.08
paper_value(k, name) = value(sprintf("paper_%s_%s", name, word(densities, k)))
# the samples of a density side by side around its x
spread_x(k, row) = k + 0.08 * ((int(row) % samples_n) - (samples_n - 1) / 2.0)
do for [panel=1:2] {
  name = panel == 1 ? "e0" : "cn"
  unset arrow
  do for [k=1:3] {
    set arrow k from k - 0.3, paper_value(k, name) to k + 0.3, paper_value(k, name) nohead lw 3 lc rgb "#000000" front
  }
  set title panel == 1 ? "(A) void ratio e0" : "(B) coordination number 2N_c/N_p"
  set ylabel panel == 1 ? "e0" : "coordination number"
  if (fig00_samples_rows == 0) {
    set yrange [0:1]; eval not_run
    plot NaN notitle
    eval not_run_off; set autoscale y
  } else {
    plot for [k=1:3] "fig00_samples.dat" u ($2 == k ? spread_x(k, $0) : NaN):(column(panel + 2)) w p pt 7 ps 1.4 \
         lc rgb density_colour(word(densities, k)) title word(densities, k)
  }
}
unset multiplot
