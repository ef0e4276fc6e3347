# The critical-state section, figure (a): the peak and the critical-state friction angle of the
# dense sample against the shearing friction μ, triaxial compression and extension at constant p.
# Data: critical_state.dat (compare-runs critical-state; columns: label, μ, loading 1 compression /
# 2 extension / 3 b series, b target, peak φ, largest single-row φ, axial strain at the peak,
# critical φ and sd, e and sd, CN and sd, mechanical CN and sd, q/p and sd, b at the peak, largest
# axial strain, critical-state rows, ρ/p and Lode angle at the peak, p at the peak, p and b at the
# critical state, least and largest p, held as named 1/0) and values.gp. With --ensemble, the
# ensemble's mean critical and peak φ of each loading and μ with the samples' sd as error bars,
# drawn just left of their μ (ensemble.dat: label, μ, loading, samples, critical φ and sd, q/p and
# sd, e and sd, CN and sd, peak φ and sd); with --rates, the quasi-static critical φ (I -> 0) with
# its standard error, just right of its μ (rates_qs.dat: label, μ, q/p and se, φ and se, slope,
# points, monotonic). `for [k = 1:has_ensemble]` draws a set only when there is one (an empty
# iteration draws nothing). Runs in reports/critical_state/ (compare-runs critical-state --draw, make critical-state-report).
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
sd(x) = x == x ? x : 0   # one sample or two rates: no sd (NaN), drawn without a bar
plot "critical_state.dat" u 2:(compression($5)) w lp pt 7 ps 1.4 lw 2 lc rgb "#1f77b4" t "peak, compression", \
     "critical_state.dat" u 2:(extension($5)) w lp pt 9 ps 1.6 lw 2 lc rgb "#d62728" t "peak, extension", \
     "critical_state.dat" u 2:(compression($8)):9 w yerrorlines pt 6 ps 1.4 lw 1.5 dt 2 lc rgb "#1f77b4" t "critical state, compression", \
     "critical_state.dat" u 2:(extension($8)):9 w yerrorlines pt 8 ps 1.6 lw 1.5 dt 2 lc rgb "#d62728" t "critical state, extension", \
     "critical_state.dat" u 2:($3 < 3 && $28 < 0.5 ? $5 : 1/0) w p pt 2 ps 2.5 lw 2 lc rgb "#000000" t "p or b not held (see the table)", \
     for [k = 1:has_ensemble] "ensemble.dat" u ($2 - 0.02):(compression($5)):(sd($6)) w yerrorbars pt 4 ps 1.3 lw 2 lc rgb "#1f77b4" t sprintf("critical state, compression: mean ± sd over %d samples", ensemble_samples), \
     for [k = 1:has_ensemble] "ensemble.dat" u ($2 - 0.02):(extension($5)):(sd($6)) w yerrorbars pt 10 ps 1.5 lw 2 lc rgb "#d62728" t sprintf("critical state, extension: mean ± sd over %d samples", ensemble_samples), \
     for [k = 1:has_ensemble] "ensemble.dat" u ($2 - 0.02):(compression($13)):(sd($14)) w yerrorbars pt 5 ps 1.3 lw 2 lc rgb "#1f77b4" t "peak, compression: mean ± sd over the samples", \
     for [k = 1:has_ensemble] "ensemble.dat" u ($2 - 0.02):(extension($13)):(sd($14)) w yerrorbars pt 11 ps 1.5 lw 2 lc rgb "#d62728" t "peak, extension: mean ± sd over the samples", \
     for [k = 1:has_rates] "rates_qs.dat" u ($2 + 0.02):5:(sd($6)) w yerrorbars pt 13 ps 1.8 lw 2 lc rgb "#000000" t "critical state, compression, quasi-static (I → 0) ± se", \
     NaN notitle
eval not_run_off
