# The critical-state section, figure (a): the peak and the critical-state friction angle of the
# dense sample against the shearing friction μ, triaxial compression and extension at constant p.
# Data: critical_state.dat (compare-runs critical-state; columns: label, μ, loading 1 compression /
# 2 extension / 3 b series, b target, peak φ, largest single-row φ, axial strain at the peak,
# critical φ and sd, e and sd, CN and sd, mechanical CN and sd, q/p and sd, b at the peak, largest
# axial strain, critical-state rows, ρ/p and Lode angle at the peak, p at the peak, p and b at the
# critical state, least and largest p, held as named 1/0) and values.gp. Runs in reports/critical_state/ (reports/critical_state/make_section.sh).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1000,750 font ",11" enhanced
set output 'phi_mu.png'
set title sprintf("Dense sample, drained shear at constant p: peak and critical-state friction angle\n(critical state: mean ± sd over 0.3 ≤ |ε_3| ≤ 0.4; %d of %d runs finished)", runs_finished, runs_total)
set xlabel "shearing friction μ"
set ylabel "mobilised friction angle φ (°)"
set xrange [-0.05:1.05]
set yrange [0:*]
set key bottom right
if (runs_finished == 0) { set yrange [0:60]; eval not_run }
compression(x) = column(3) == 1 ? x : 1/0
extension(x) = column(3) == 2 ? x : 1/0
plot "critical_state.dat" u 2:(compression($5)) w lp pt 7 ps 1.4 lw 2 lc rgb "#1f77b4" t "peak, compression", \
     "critical_state.dat" u 2:(extension($5)) w lp pt 9 ps 1.6 lw 2 lc rgb "#d62728" t "peak, extension", \
     "critical_state.dat" u 2:(compression($8)):9 w yerrorlines pt 6 ps 1.4 lw 1.5 dt 2 lc rgb "#1f77b4" t "critical state, compression", \
     "critical_state.dat" u 2:(extension($8)):9 w yerrorlines pt 8 ps 1.6 lw 1.5 dt 2 lc rgb "#d62728" t "critical state, extension", \
     "critical_state.dat" u 2:($3 < 3 && $28 < 0.5 ? $5 : 1/0) w p pt 2 ps 2.5 lw 2 lc rgb "#000000" t "p or b not held (see the table)", \
     NaN notitle
eval not_run_off
