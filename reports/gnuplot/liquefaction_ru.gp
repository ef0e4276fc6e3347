# The liquefaction section, figure (b): r_u = 1 - p/p0 against the number of cycles since the start
# of the cyclic stage of every run, one panel per density: the cyclic tests (solid, one colour per
# CSR, every sample's test in its CSR's colour) and the holds with nothing applied (dashed grey,
# their time divided by the period of their density's cyclic tests). Data: ru.dat (compare-runs
# liquefaction; one block per run: label, cycles, r_u, time) and values.gp (liq_run_<k>,
# liq_run_hold_<k>, liq_run_density_<k>, liq_run_csr_<k>, liq_run_csr_rank_<k>, liq_run_first_<k>).
# Runs in reports/liquefaction/.
load 'style.gp'
load 'values.gp'
set terminal pngcairo size 1100,1000 font ",11" noenhanced
set output 'ru.png'
run(k) = value(sprintf("liq_run_%d", k))
density_of(k) = int(value(sprintf("liq_run_density_%d", k)))
hold(k) = value(sprintf("liq_run_hold_%d", k)) eq "1"
csr(k) = value(sprintf("liq_run_csr_%d", k))
rank(k) = int(value(sprintf("liq_run_csr_rank_%d", k)))
first(k) = value(sprintf("liq_run_first_%d", k)) eq "1"
# The CSRs of a density from the lowest: blue, orange, purple, teal, brown, pink; holds grey.
colour(k) = hold(k) ? "#777777" : word("#1f77b4 #ff7f0e #9467bd #17a2b8 #8c564b #e377c2", (rank(k) - 1) % 6 + 1)
dashes(k) = hold(k) ? 2 : 1
key_title(k, i) = density_of(k) != i || !first(k) ? "" : hold(k) ? "holds: nothing applied" : "CSR " . csr(k)
panels = liq_run_n == 0 ? 1 : liq_density_n
set multiplot layout panels, 1 title "Excess pore pressure ratio r_u against cycles, every sample's run (log axis: the first row, at 0 cycles, is off it)"
set logscale x
set xrange [0.01:100]
set yrange [*:1]   # a dilating sample has r_u < 0
set xlabel "number of cycles (a hold: time / its density's cyclic period)"
set ylabel "r_u = 1 - p/p0"
set key top left
set arrow 1 from graph 0, first 0.95 to graph 1, first 0.95 nohead dt 3 lc rgb "#777777"
set label 1 "r_u = 0.95" at graph 0.99, first 0.95 right offset 0,-0.7 tc rgb "#555555"
if (liq_run_n == 0) {
  eval not_run
  plot NaN notitle
  eval not_run_off
} else {
  do for [i = 1:liq_density_n] {
    set title value(sprintf("liq_density_%d", i))
    plot for [k = 1:liq_run_n] "ru.dat" index (k - 1) u ($2 > 0 && density_of(k) == i ? $2 : 1/0):3 w l lw 2 dt dashes(k) lc rgb colour(k) t key_title(k, i), \
         NaN notitle
  }
}
unset multiplot
