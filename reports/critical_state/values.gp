# Written by compare-runs critical-state from results/critical_state/paper
has_compression_peak = 1
pi_r = 1.1
runs_finished = 17
runs_total = 17
