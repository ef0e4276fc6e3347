# Tornado chart of the group 'volumetric strain' (written by compare-runs decisions)
set terminal pngcairo size 1400,628 font 'Sans,10'
set output 'tornado_volumetric_strain.png'
set title "volumetric strain: shift of the ensemble mean by each reading (baseline standard deviations)"
set xlabel 'shift of the mean / baseline standard deviation'
set grid xtics
set key outside right
set yrange [-0.6:5.6]
set ytics ("loose: Test 3 compacts most after 5 cycles (its εv lead over the next test, %%)" 0, "loose: Test 5 compacts least after 5 cycles (its εv lag behind the next test, %%)" 1, "loose: εv grows with cycles (cycles 1..5, %%)" 2, "loose: εv after 5 cycles (%%), mean of the tests" 3, "medium: εv grows with cycles (cycles 1..5, %%)" 4, "dense: hardly any εv growth (cycles 1..5, %%)" 5)
set style fill solid 0.8 noborder
set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
plot 'tornado_volumetric_strain.dat' using ($2 == 0 ? $3 / 2 : 1/0):($1 + -0.35):(abs($3) / 2):(0.05) with boxxyerror lc 1 title 'grading_by_mass', \
     'tornado_volumetric_strain.dat' using ($2 == 1 ? $3 / 2 : 1/0):($1 + -0.25):(abs($3) / 2):(0.05) with boxxyerror lc 2 title 'damping_local', \
     'tornado_volumetric_strain.dat' using ($2 == 2 ? $3 / 2 : 1/0):($1 + -0.15):(abs($3) / 2):(0.05) with boxxyerror lc 3 title 'shear_prep_friction', \
     'tornado_volumetric_strain.dat' using ($2 == 3 ? $3 / 2 : 1/0):($1 + -0.05):(abs($3) / 2):(0.05) with boxxyerror lc 4 title 'hold_ufr_1e-2', \
     'tornado_volumetric_strain.dat' using ($2 == 4 ? $3 / 2 : 1/0):($1 + 0.05):(abs($3) / 2):(0.05) with boxxyerror lc 5 title 'rate_cap_0_25', \
     'tornado_volumetric_strain.dat' using ($2 == 5 ? $3 / 2 : 1/0):($1 + 0.15):(abs($3) / 2):(0.05) with boxxyerror lc 6 title 'rate_cap_4', \
     'tornado_volumetric_strain.dat' using ($2 == 6 ? $3 / 2 : 1/0):($1 + 0.25):(abs($3) / 2):(0.05) with boxxyerror lc 7 title 'test3_directions', \
     'tornado_volumetric_strain.dat' using ($2 == 7 ? $3 / 2 : 1/0):($1 + 0.35):(abs($3) / 2):(0.05) with boxxyerror lc 8 title 'vertices_printed'
