# The shared style of the report's figures: every script in reports/gnuplot/ starts with
#   load 'style.gp'
# and runs in the folder of its data. The figures of the study then load 'values.gp', which
# build/bin/figure-data wrote beside their data files (the numbers the scripts read: the paper's
# values from reference_data/paper.yaml, the settings of the resolved scenes, which results exist).
# reports/make_figures.sh and compare-runs --draw (validation/sections/draw.cpp) run them with GNUPLOT_LIB
# pointing here.

set grid lc rgb "#dddddd"
set key top left box opaque samplen 2 spacing 1.1 font ",10"
set tics font ",10"
set bars 0

# Colours: the tests (black, orange, purple, teal, brown); the densities as in Fig. 2.
test_colour(t) = t == 1 ? "#000000" : t == 2 ? "#ff7f0e" : t == 3 ? "#9467bd" : t == 4 ? "#17a2b8" : "#8c564b"
density_colour(d) = d eq "loose" ? "#d62728" : d eq "medium" ? "#2ca02c" : "#1f77b4"
block_colour(b) = word("#1f77b4 #d62728 #2ca02c #ff7f0e #9467bd #8c564b", (b - 1) % 6 + 1)
densities = "loose medium dense"
letter(i) = word("A B C D E F", i)

# What figure-data found: has(d, t) for one run, has_density(d) for any test of a density.
has(d, t) = value(sprintf("has_%s_test%d", d, t))
has_density(d) = value("has_" . d)
test_title(d, t) = has(d, t) ? sprintf("Test %d", t) : sprintf("Test %d: not run", t)
# The title note of the figures that show the ensemble's mean with a band of one standard deviation.
ensemble_note(n) = n > 1 ? sprintf(" — mean of %d samples, band ± 1 standard deviation", n) : ""

# A panel without data says so; `eval not_run` before its plot, `eval not_run_off` after.
not_run = "set label 99 'not run' at graph 0.5, 0.4 center front font ',18' tc rgb '#888888'"
not_run_off = "unset label 99"

# π-plane decorations: principal axes (1 up, 2 lower left, 3 lower right), square frame of
# half-width pi_r; `pi_r = 0.3; eval pi_axes`.
pi_axes = "set size ratio -1; set xrange [-pi_r:pi_r]; set yrange [-pi_r:pi_r]; \
  set arrow 1 from 0,0 to 0,0.83*pi_r head filled size graph 0.025,20 dt 2 lc rgb '#888888' back; \
  set arrow 2 from 0,0 to -0.83*pi_r*0.8660254,-0.83*pi_r*0.5 head filled size graph 0.025,20 dt 2 lc rgb '#888888' back; \
  set arrow 3 from 0,0 to 0.83*pi_r*0.8660254,-0.83*pi_r*0.5 head filled size graph 0.025,20 dt 2 lc rgb '#888888' back; \
  set label 1 'σ_1' at 0,0.9*pi_r center font ',12' tc rgb '#555555'; \
  set label 2 'σ_2' at -0.87*pi_r*0.8660254,-0.93*pi_r*0.5 right font ',12' tc rgb '#555555'; \
  set label 3 'σ_3' at 0.87*pi_r*0.8660254,-0.93*pi_r*0.5 left font ',12' tc rgb '#555555'"
# The named states (fig03_states.dat) as labels just outside their vertices; A beside the origin.
state_x(x, y) = (x == 0 && y == 0) ? 0.02 : 1.15 * x
state_y(x, y) = (x == 0 && y == 0) ? -0.02 : 1.15 * y
