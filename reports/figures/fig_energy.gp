set terminal pngcairo size 1500,450 font ",11" enhanced
set output "fig_energy.png"
set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 font ",9"
set multiplot layout 1,3 title "Energy balance of Test 1: the work by the cell against what was dissipated and stored (from the first row after the start; the dashed curve must cover the black one)"
set xlabel "time (s)"
set xtics font ",9"
set ylabel "energy (J)"
set title 'loose'
stored0 = NaN
first(x) = (stored0 != stored0 ? stored0 = x : 0, stored0)
plot 'fig_energy_loose_test1.dat' every ::2 u 1:2 w l lw 2 lc rgb "#000000" t "work by the cell", \
     '' every ::2 u 1:3 w l lw 2 lc rgb "#1f77b4" t "dissipated by damping", \
     '' every ::2 u 1:4 w l lw 2 lc rgb "#d62728" t "dissipated by sliding", \
     '' every ::2 u 1:($5+$6+$7-first($5+$6+$7)) w l lw 2 lc rgb "#2ca02c" t "change of stored energy", \
     '' every ::2 u 1:($3+$4+$5+$6+$7-stored0) w l lw 2 dt 2 lc rgb "#ff7f0e" t "dissipated + change of stored"
set title 'medium'
stored0 = NaN
first(x) = (stored0 != stored0 ? stored0 = x : 0, stored0)
plot 'fig_energy_medium_test1.dat' every ::2 u 1:2 w l lw 2 lc rgb "#000000" t "work by the cell", \
     '' every ::2 u 1:3 w l lw 2 lc rgb "#1f77b4" t "dissipated by damping", \
     '' every ::2 u 1:4 w l lw 2 lc rgb "#d62728" t "dissipated by sliding", \
     '' every ::2 u 1:($5+$6+$7-first($5+$6+$7)) w l lw 2 lc rgb "#2ca02c" t "change of stored energy", \
     '' every ::2 u 1:($3+$4+$5+$6+$7-stored0) w l lw 2 dt 2 lc rgb "#ff7f0e" t "dissipated + change of stored"
set title 'dense'
stored0 = NaN
first(x) = (stored0 != stored0 ? stored0 = x : 0, stored0)
plot 'fig_energy_dense_test1.dat' every ::2 u 1:2 w l lw 2 lc rgb "#000000" t "work by the cell", \
     '' every ::2 u 1:3 w l lw 2 lc rgb "#1f77b4" t "dissipated by damping", \
     '' every ::2 u 1:4 w l lw 2 lc rgb "#d62728" t "dissipated by sliding", \
     '' every ::2 u 1:($5+$6+$7-first($5+$6+$7)) w l lw 2 lc rgb "#2ca02c" t "change of stored energy", \
     '' every ::2 u 1:($3+$4+$5+$6+$7-stored0) w l lw 2 dt 2 lc rgb "#ff7f0e" t "dissipated + change of stored"
unset multiplot
