# The critical-state section, figure (c): the peaks of the true-triaxial b series (b = 0 ... 1) and
# of the extension run at the same μ in the π-plane of the principal stresses normalised by p (σ1
# up), beside the Mohr–Coulomb hexagon and the Lade–Duncan (I1³/I3) and Matsuoka–Nakai (I1 I2/I3)
# surfaces through the compression (b = 0) peak, each over every Lode angle at the same p. Data:
# pi_plane.dat (compare-runs critical-state; columns: label, set 0 b series / 1 extension /
# 2 Mohr–Coulomb / 3 Lade–Duncan / 4 Matsuoka–Nakai, x, y, radius, Lode angle, b, held as named:
# a run that did not hold its p or b is drawn open) and values.gp.
# Runs in reports/critical_state/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 950,950 font ",11" enhanced
set output 'pi_plane.png'
set title "Peak stresses in the π-plane (normalised by p) and three criteria through the compression peak"
eval pi_axes
set key bottom right
unset xtics; unset ytics; unset grid
set style textbox opaque noborder
if (!has_compression_peak) { set label 98 "no compression peak yet: no surfaces" at graph 0.5, 0.6 center front font ',14' tc rgb '#888888' }
in_set(k, v) = column(2) == k ? v : 1/0
plot "pi_plane.dat" u (in_set(2, $3)):4 w l lw 2 lc rgb "#000000" t "Mohr–Coulomb", \
     "pi_plane.dat" u (in_set(3, $3)):4 w l lw 2 lc rgb "#ff7f0e" t "Lade–Duncan", \
     "pi_plane.dat" u (in_set(4, $3)):4 w l lw 2 dt 2 lc rgb "#2ca02c" t "Matsuoka–Nakai", \
     "pi_plane.dat" u (in_set(0, $3) + ($8 > 0.5 ? 0 : 1/0)):4 w p pt 7 ps 1.6 lc rgb "#1f77b4" t "peaks of the b series", \
     "pi_plane.dat" u (in_set(0, $3) + ($8 > 0.5 ? 1/0 : 0)):4 w p pt 6 ps 1.6 lw 2 lc rgb "#1f77b4" t "peaks of the b series, p or b not held (see the table)", \
     "pi_plane.dat" u (in_set(0, $3)):4:(sprintf("b = %.2f", $7)) w labels left offset char 1,0 font ",9" notitle, \
     "pi_plane.dat" u (in_set(1, $3)):4 w p pt 9 ps 1.8 lc rgb "#d62728" t "peak of the extension test", \
     NaN notitle
