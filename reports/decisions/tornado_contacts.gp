# Tornado chart of the group 'contacts' (written by compare-runs decisions)
set terminal pngcairo size 1400,628 font 'Sans,10'
set output 'tornado_contacts.png'
set title "contacts: shift of the ensemble mean by each reading (baseline standard deviations)"
set xlabel 'shift of the mean / baseline standard deviation'
set grid xtics
set key outside right
set yrange [-0.6:5.6]
set ytics ("loose: coordination number decreases (cycles 1..5)" 0, "medium: coordination number slightly decreases (cycles 1..5)" 1, "loose: sliding fraction decreases (cycles 1..5, %%)" 2, "dense: sliding fraction unchanged (absolute change, cycles 1..5, %%)" 3, "dense: coordination number independent of cycles (absolute change, cycles 1..5)" 4, "medium: sliding fraction unchanged (absolute change, cycles 1..5, %%)" 5)
set style fill solid 0.8 noborder
set arrow from 0, graph 0 to 0, graph 1 nohead lc rgb 'black'
plot 'tornado_contacts.dat' using ($2 == 0 ? $3 / 2 : 1/0):($1 + -0.35):(abs($3) / 2):(0.05) with boxxyerror lc 1 title 'grading_by_mass', \
     'tornado_contacts.dat' using ($2 == 1 ? $3 / 2 : 1/0):($1 + -0.25):(abs($3) / 2):(0.05) with boxxyerror lc 2 title 'damping_local', \
     'tornado_contacts.dat' using ($2 == 2 ? $3 / 2 : 1/0):($1 + -0.15):(abs($3) / 2):(0.05) with boxxyerror lc 3 title 'shear_prep_friction', \
     'tornado_contacts.dat' using ($2 == 3 ? $3 / 2 : 1/0):($1 + -0.05):(abs($3) / 2):(0.05) with boxxyerror lc 4 title 'hold_ufr_1e-2', \
     'tornado_contacts.dat' using ($2 == 4 ? $3 / 2 : 1/0):($1 + 0.05):(abs($3) / 2):(0.05) with boxxyerror lc 5 title 'rate_cap_0_25', \
     'tornado_contacts.dat' using ($2 == 5 ? $3 / 2 : 1/0):($1 + 0.15):(abs($3) / 2):(0.05) with boxxyerror lc 6 title 'rate_cap_4', \
     'tornado_contacts.dat' using ($2 == 6 ? $3 / 2 : 1/0):($1 + 0.25):(abs($3) / 2):(0.05) with boxxyerror lc 7 title 'test3_directions', \
     'tornado_contacts.dat' using ($2 == 7 ? $3 / 2 : 1/0):($1 + 0.35):(abs($3) / 2):(0.05) with boxxyerror lc 8 title 'vertices_printed'
