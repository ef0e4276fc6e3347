# The critical-state section, figure (d): the critical q/p of compression at constant p against the
# square root of the inertial number I = rate d sqrt(rho / p), one series per μ (the rates study's
# slower runs and the main study's own), with the least-squares line of each taken to I = 0 and the
# quasi-static value there with its standard error. Data: rates.dat (compare-runs critical-state
# --rates; columns: label, series, μ, strain rate, d, ρ, p at cs, I, sqrt I, q/p at cs and its
# row-to-row sd, used 1/0), rates_qs.dat (label, μ, q/p and se at I = 0, φ and se, slope, points,
# monotonic) and values.gp (rate_series_n, rate_mu_<k>, rate_intercept_<k>, rate_slope_<k>).
# Runs in reports/critical_state/ (compare-runs critical-state --draw, make critical-state-report).
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1000,750 font ",11" enhanced
set output 'rates.png'
set title "Dense sample, compression at constant p: critical q/p against the inertial number\n(points: mean ± row-to-row sd over the critical-state window; lines: least squares in √I, taken to I → 0)"
set xlabel "√I"
set ylabel "critical-state q/p"
set xrange [0:*]
set key center right box opaque   # between the frictional series (top) and the frictionless one (bottom)
colour(k) = k == 1 ? "#1f77b4" : k == 2 ? "#d62728" : k == 3 ? "#2ca02c" : "#9467bd"
mu(k) = value(sprintf("rate_mu_%d", k))
a(k) = value(sprintf("rate_intercept_%d", k))
b(k) = value(sprintf("rate_slope_%d", k))
sd(x) = x == x ? x : 0
if (rate_series_n == 0) { eval not_run }
plot for [k = 1:rate_series_n] "rates.dat" u (column(2) == k && column(12) == 1 ? $9 : 1/0):10:(sd($11)) w yerrorbars pt 7 ps 1.5 lw 1.5 lc rgb colour(k) t sprintf("μ = %g", mu(k)), \
     for [k = 1:rate_series_n] "rates.dat" u (column(2) == k && column(12) == 0 ? $9 : 1/0):10 w p pt 2 ps 2 lw 2 lc rgb colour(k) t sprintf("μ = %g: left out of the fit", mu(k)), \
     for [k = 1:rate_series_n] (value(sprintf("rate_fitted_%d", k)) ? a(k) + b(k) * x : 1/0) w l lw 1.5 dt 2 lc rgb colour(k) notitle, \
     for [k = 1:rate_series_n] "rates_qs.dat" u (abs($2 - mu(k)) < 1e-12 ? 0 : 1/0):3:(sd($4)) w yerrorbars pt 13 ps 2 lw 2 lc rgb colour(k) t sprintf("μ = %g: quasi-static (I → 0) ± se", mu(k)), \
     NaN notitle
eval not_run_off
