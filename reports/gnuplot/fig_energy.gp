# The energy balance of Test 1 of each density: the work by the cell against what was dissipated
# and the change of stored energy, every curve from the same row (the first whose energies are the
# sample's true state: t = 0). Data: fig_energy_<density>_test1.dat (figure-data; columns time,
# work_by_cell, dissipated_by_damping, dissipated_by_friction, stored_change,
# dissipated_plus_stored_change, gap, energy_closure_error; validation/figures.hpp, energy_curves).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1500,450 font ",11" enhanced
set output 'fig_energy.png'
set key top left box opaque samplen 2 font ",9"
set multiplot layout 1,3 title "Energy balance of Test 1: the work by the cell against what was dissipated and stored, all from the same row (a closed balance: the dashed curve covers the black one)"
set xlabel "time (s)"; set xtics font ",9"; set ylabel "energy (J)"
do for [d in densities] {
  set title d
  if (!has(d, 1)) {
    eval not_run; set xrange [0:1]; set yrange [0:1]
    plot NaN notitle
    eval not_run_off
  } else {
    set autoscale
    f = sprintf("fig_energy_%s_test1.dat", d)
    plot f u 1:2 w l lw 2 lc rgb "#000000" t "work by the cell", \
         f u 1:3 w l lw 2 lc rgb "#1f77b4" t "dissipated by damping", \
         f u 1:4 w l lw 2 lc rgb "#d62728" t "dissipated by sliding", \
         f u 1:5 w l lw 2 lc rgb "#2ca02c" t "change of stored energy", \
         f u 1:6 w l lw 2 dt 2 lc rgb "#ff7f0e" t "dissipated + change of stored"
  }
}
unset multiplot
