# Fig. 1: the grading curve of the scene (target, as the preparation reads it) and the one realised
# in the dense sample, by count and by mass. Data: fig01_grading_target.dat, fig01_grading_sample.dat.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 900,650 font ",12" enhanced
set output 'fig01_grading.png'
set title sprintf("Fig. 1  Grain size distribution (d_{min} = %g mm, d_{50} = %g mm, d_{max} = %g mm)", grading_d_min_mm, grading_d50_mm, grading_d_max_mm)
set xlabel "diameter d (mm)"; set ylabel "percent finer (%)"
set xrange [grading_d_min_mm - 0.1:grading_d_max_mm + 0.1]; set yrange [0:105]
set key left top Left reverse box opaque font ",10"
if (!has_prepare_dense) { eval not_run; set xrange [0:1]; set yrange [0:1]; plot NaN notitle; exit }
plot "fig01_grading_target.dat" w lp lw 3 pt 7 ps 1.5 lc rgb "black" t sprintf("target curve (read by %s)", grading_basis), \
     "fig01_grading_sample.dat" u 1:3 w l lw 2 lc rgb "#d62728" t sprintf("dense sample %s, percent finer by count", sample), \
     "fig01_grading_sample.dat" u 1:2 w l lw 2 dt 2 lc rgb "#1f77b4" t "the same sample, percent finer by mass"
