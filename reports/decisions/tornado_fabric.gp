# Tornado chart of the group 'fabric' (written by compare-runs decisions)
set terminal pngcairo size 1400,424 font 'Sans,10'
set output 'tornado_fabric.png'
set title "fabric: shift of the ensemble mean by each reading (baseline standard deviations)"
set termoption noenhanced
set xlabel 'shift of the mean / baseline standard deviation (bars beyond ±10 are cut and labelled with their value)'
set grid xtics
set key outside right
set xrange [-11:11]
clip(x) = x > 10 ? 10 : x < -10 ? -10 : x
set yrange [-0.6:2.6]
set label 1 "slope of q/p against F^s_d/F^s_m, medium" at graph -0.01, first 0 right
set label 2 "slope of q/p against F^s_d/F^s_m, loose" at graph -0.01, first 1 right
set label 3 "slope of q/p against F^s_d/F^s_m, dense" at graph -0.01, first 2 right
set lmargin 38
set ytics ("" 0, "" 1, "" 2)
set style fill solid 0.8 noborder
set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
plot 'tornado_fabric.dat' using ($2 == 0 ? clip($3) / 2 : 1/0):($1 + -0.35):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 1 title 'grading_by_mass', \
     'tornado_fabric.dat' using ($2 == 1 ? clip($3) / 2 : 1/0):($1 + -0.25):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 2 title 'damping_local', \
     'tornado_fabric.dat' using ($2 == 2 ? clip($3) / 2 : 1/0):($1 + -0.15):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 3 title 'shear_prep_friction', \
     'tornado_fabric.dat' using ($2 == 3 ? clip($3) / 2 : 1/0):($1 + -0.05):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 4 title 'hold_ufr_1e-2', \
     'tornado_fabric.dat' using ($2 == 4 ? clip($3) / 2 : 1/0):($1 + 0.05):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 5 title 'rate_cap_0_25', \
     'tornado_fabric.dat' using ($2 == 5 ? clip($3) / 2 : 1/0):($1 + 0.15):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 6 title 'rate_cap_4', \
     'tornado_fabric.dat' using ($2 == 6 ? clip($3) / 2 : 1/0):($1 + 0.25):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 7 title 'test3_directions', \
     'tornado_fabric.dat' using ($2 == 7 ? clip($3) / 2 : 1/0):($1 + 0.35):(abs(clip($3)) / 2):(0.05) with boxxyerror lc 8 title 'vertices_printed', \
     'tornado_fabric.dat' using (abs($3) > 10 ? clip($3) * 0.93 : 1/0):($1 + ($2 - 3.5) * 0.1):(sprintf('%+.0f', $3)) with labels font ',8' notitle
