# Fig. 2: (A) the lattice before compression, (B-D) the loose, medium and dense samples in 3-D,
# point size proportional to the diameter, axis 1 vertical. Data: fig02_lattice.dat,
# fig02_<density>.dat (x1, x2, x3, diameter in mm); the friction of each preparation from its scene.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1400,1200 font ",12" enhanced
set output 'fig02_samples.png'
set multiplot layout 2,2 title sprintf("Fig. 2  Samples before (A) and after isotropic compression to %g kPa: (B) loose, (C) medium, (D) dense\n%d spheres, point size proportional to diameter, axis 1 vertical", target_pressure_kPa, particles)
set view 65, 35, 1, 1; set ticslevel 0; unset key; unset grid
set xlabel "x_2 (mm)"; set ylabel "x_3 (mm)"; set zlabel "x_1 (mm)" rotate
set xrange [0:lattice_side_mm]; set yrange [0:lattice_side_mm]; set zrange [0:lattice_side_mm]
set title sprintf("(A) lattice, %g mm cube", lattice_side_mm)
if (!has_lattice) { eval not_run }
splot "fig02_lattice.dat" u 2:3:1:($4 * 0.175) w p pt 7 ps variable lc rgb "#7f7f7f"
eval not_run_off
set xrange [0:sample_side_mm]; set yrange [0:sample_side_mm]; set zrange [0:sample_side_mm]
i = 1
do for [d in densities] {
  i = i + 1
  set title sprintf("(%s) %s (μ = %g during compression)", letter(i), d, value("friction_prepare_" . d))
  if (!value("has_prepare_" . d)) { eval not_run }
  splot sprintf("fig02_%s.dat", d) u 2:3:1:($4 * 0.225) w p pt 7 ps variable lc rgb density_colour(d)
  eval not_run_off
}
unset multiplot
