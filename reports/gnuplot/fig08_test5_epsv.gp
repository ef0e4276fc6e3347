# Fig. 8: Test 5, ε_v against σ_1/σ_3 over all its cycles, coloured by block of cycles (a block
# ends when the loaded axis changes, from the /legs targets). Data: fig08_test5_<density>.dat, one
# gnuplot index per block; the block captions fig08_titles_<density>_<b> in values.gp.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1800,620 font ",11" enhanced
set output 'fig08_test5_epsv.png'
set multiplot layout 1,3 title "Fig. 8  Test 5: volumetric strain ε_v (compression +) against σ_1/σ_3 over all cycles, coloured by block of cycles" font ",13"
set xlabel "σ_1/σ_3 = σ_{11}/σ_{33} (axes 1, 3 of the cell)"; set ylabel "ε_v (%)"; set key top left
set xrange [0.75:1.3]; set offsets 0, 0, graph 0.3, 0
i = 0
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s, Test 5", letter(i), d) font ",12"
  if (!has(d, 5)) {
    eval not_run; set yrange [0:1]
    plot NaN t "Test 5: not run"
  } else {
    set yrange [*:*]
    blocks = value(sprintf("fig08_titles_%s_n", d))
    plot for [b = 1:blocks] sprintf("fig08_test5_%s.dat", d) index (b - 1) u 1:2 w l lw 1.4 lc rgb block_colour(b) t value(sprintf("fig08_titles_%s_%d", d, b))
  }
  eval not_run_off
}
unset multiplot
