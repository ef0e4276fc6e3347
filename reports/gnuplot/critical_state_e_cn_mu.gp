# The critical-state section, figure (b): the critical-state void ratio and coordination number of
# the dense sample against the shearing friction μ (mean ± sd over 0.3 ≤ |ε_3| ≤ 0.4), compression
# and extension; the coordination number both with rattlers (2Nc/Np) and without them (mechanical,
# Thornton 2000). Data: critical_state.dat and values.gp (see critical_state_phi_mu.gp). Runs in
# reports/critical_state/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1400,650 font ",11" enhanced
set output 'e_cn_mu.png'
set multiplot layout 1,2 title sprintf("Dense sample at the critical state (mean ± sd over 0.3 ≤ |ε_3| ≤ 0.4; %d of %d runs finished)", runs_finished, runs_total)
set xlabel "shearing friction μ"
set xrange [-0.05:1.05]
compression(x) = column(3) == 1 ? x : 1/0
extension(x) = column(3) == 2 ? x : 1/0
set key top right
set title "(a) void ratio"
set ylabel "e_{cs}"
if (runs_finished == 0) { set yrange [0.5:1]; eval not_run }
plot "critical_state.dat" u 2:(compression($10)):11 w yerrorlines pt 7 ps 1.4 lw 2 lc rgb "#1f77b4" t "compression", \
     "critical_state.dat" u 2:(extension($10)):11 w yerrorlines pt 9 ps 1.6 lw 2 lc rgb "#d62728" t "extension", \
     NaN notitle
eval not_run_off
set title "(b) coordination number"
set ylabel "CN_{cs}"
if (runs_finished == 0) { set yrange [2:6]; eval not_run }
plot "critical_state.dat" u 2:(compression($14)):15 w yerrorlines pt 7 ps 1.4 lw 2 lc rgb "#1f77b4" t "mechanical, compression", \
     "critical_state.dat" u 2:(extension($14)):15 w yerrorlines pt 9 ps 1.6 lw 2 lc rgb "#d62728" t "mechanical, extension", \
     "critical_state.dat" u 2:(compression($12)):13 w yerrorlines pt 6 ps 1.4 lw 1.5 dt 2 lc rgb "#1f77b4" t "2Nc/Np, compression", \
     "critical_state.dat" u 2:(extension($12)):13 w yerrorlines pt 8 ps 1.6 lw 1.5 dt 2 lc rgb "#d62728" t "2Nc/Np, extension", \
     NaN notitle
eval not_run_off
unset multiplot
