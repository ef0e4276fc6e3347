# Tornado chart of the group 'volumetric strain' (written by compare-runs decisions)
set terminal pngcairo size 1400,628 font 'Sans,10'
set output 'tornado_volumetric_strain.png'
set title "volumetric strain: shift of the ensemble mean by each reading (baseline standard deviations)"
set termoption noenhanced
set xlabel 'shift of the mean / baseline standard deviation (bars beyond ±10 are cut and labelled with their value)'
set grid xtics
set key outside right
set xrange [-11:11]
clip(x) = x > 10 ? 10 : x < -10 ? -10 : x
set yrange [-0.6:5.6]
set label 1 "loose: Test 3 compacts most after 5 cycles (its εv lead over the next test, %)" at graph -0.01, first 0 right
set label 2 "loose: Test 5 compacts least after 5 cycles (its εv lag behind the next test, %)" at graph -0.01, first 1 right
set label 3 "loose: εv grows with cycles (cycles 1..5, %)" at graph -0.01, first 2 right
set label 4 "loose: εv after 5 cycles (%), mean of the tests" at graph -0.01, first 3 right
set label 5 "medium: εv grows with cycles (cycles 1..5, %)" at graph -0.01, first 4 right
set label 6 "dense: hardly any εv growth (cycles 1..5, %)" at graph -0.01, first 5 right
set lmargin 74
set ytics ("" 0, "" 1, "" 2, "" 3, "" 4, "" 5)
set style fill solid 0.8 noborder
set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
plot 'tornado_volumetric_strain.dat' using ($2 == 0 ? clip($3) / 2 : 1/0):($1 + -0.35):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 1 title 'grading_by_mass', \
     'tornado_volumetric_strain.dat' using ($2 == 1 ? clip($3) / 2 : 1/0):($1 + -0.25):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 2 title 'damping_local', \
     'tornado_volumetric_strain.dat' using ($2 == 2 ? clip($3) / 2 : 1/0):($1 + -0.15):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 3 title 'shear_prep_friction', \
     'tornado_volumetric_strain.dat' using ($2 == 3 ? clip($3) / 2 : 1/0):($1 + -0.05):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 4 title 'hold_ufr_1e-2', \
     'tornado_volumetric_strain.dat' using ($2 == 4 ? clip($3) / 2 : 1/0):($1 + 0.05):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 5 title 'rate_cap_0_25', \
     'tornado_volumetric_strain.dat' using ($2 == 5 ? clip($3) / 2 : 1/0):($1 + 0.15):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 6 title 'rate_cap_4', \
     'tornado_volumetric_strain.dat' using ($2 == 6 ? clip($3) / 2 : 1/0):($1 + 0.25):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 7 title 'test3_directions', \
     'tornado_volumetric_strain.dat' using ($2 == 7 ? clip($3) / 2 : 1/0):($1 + 0.35):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 8 title 'vertices_printed', \
     'tornado_volumetric_strain.dat' using (abs($3) > 10 ? clip($3) * 0.93 : 1/0):($1 + ($2 - 3.5) * 0.1):(sprintf('%+.0f', $3)) with labels font ',8' notitle
