# Tornado chart of the group 'samples' (written by compare-runs decisions)
set terminal pngcairo size 1400,832 font 'Sans,10'
set output 'tornado_samples.png'
set title "samples: shift of the ensemble mean by each reading (baseline standard deviations)"
set xlabel 'shift of the mean / baseline standard deviation'
set grid xtics
set key outside right
set yrange [-0.6:8.6]
set ytics ("e0, medium" 0, "e0, loose" 1, "e0, dense" 2, "coordination number before shearing, loose" 3, "coordination number before shearing, medium" 4, "coordination number before shearing, dense" 5, "cell side (cm), medium" 6, "cell side (cm), dense" 7, "cell side (cm), loose" 8)
set style fill solid 0.8 noborder
set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
plot 'tornado_samples.dat' using ($2 == 0 ? $3 / 2 : 1/0):($1 + -0.35):(abs($3) / 2):(0.05) with boxxyerror lc 1 title 'grading_by_mass', \
     'tornado_samples.dat' using ($2 == 1 ? $3 / 2 : 1/0):($1 + -0.25):(abs($3) / 2):(0.05) with boxxyerror lc 2 title 'damping_local', \
     'tornado_samples.dat' using ($2 == 2 ? $3 / 2 : 1/0):($1 + -0.15):(abs($3) / 2):(0.05) with boxxyerror lc 3 title 'shear_prep_friction', \
     'tornado_samples.dat' using ($2 == 3 ? $3 / 2 : 1/0):($1 + -0.05):(abs($3) / 2):(0.05) with boxxyerror lc 4 title 'hold_ufr_1e-2', \
     'tornado_samples.dat' using ($2 == 4 ? $3 / 2 : 1/0):($1 + 0.05):(abs($3) / 2):(0.05) with boxxyerror lc 5 title 'rate_cap_0_25', \
     'tornado_samples.dat' using ($2 == 5 ? $3 / 2 : 1/0):($1 + 0.15):(abs($3) / 2):(0.05) with boxxyerror lc 6 title 'rate_cap_4', \
     'tornado_samples.dat' using ($2 == 6 ? $3 / 2 : 1/0):($1 + 0.25):(abs($3) / 2):(0.05) with boxxyerror lc 7 title 'test3_directions', \
     'tornado_samples.dat' using ($2 == 7 ? $3 / 2 : 1/0):($1 + 0.35):(abs($3) / 2):(0.05) with boxxyerror lc 8 title 'vertices_printed'
