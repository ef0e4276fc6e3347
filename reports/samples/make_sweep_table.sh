#!/usr/bin/env bash
# Issue 3, item 4: the protocol sweep table (1,000 spheres, seed 1), one row per variant.
# Usage: reports/samples/make_sweep_table.sh [DEM] [SWEEP_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
dir=${2:-$here/results/sweep}
echo "| sample | variant | e0 | Δe0 vs base | CN | ΔCN vs base | CN w/o rattlers | cell side ×2 (cm, 8,000-sphere equivalent) | steps |"
echo "|---|---|---|---|---|---|---|---|---|"
"$dem" summary "$dir"/*.h5 | awk -F'\t' '
  NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { n = split($1, a, "/"); b = a[n]; sub(/\.h5$/, "", b); split(b, f, "_")
    key = f[1] SUBSEP f[2]; d[key] = f[1]; v[key] = f[2]
    e[key] = $c["void_ratio"]; z[key] = $c["coordination_number"]; zm[key] = $c["coordination_number_mechanical"]
    side[key] = 200 * ($c["cell_length_1"] * $c["cell_length_2"] * $c["cell_length_3"]) ^ (1 / 3); st[key] = $c["step"] }
  END {
    split("loose medium dense", ds, " ")
    split("base cap0.25 cap4 local damping0.2 dt2e-6 number", vs, " ")
    label["base"] = "baseline (SPEC: viscous 0.05, cap 1/s, dt 1 µs, grading by mass)"
    label["cap0.25"] = "strain-rate cap 0.25 /s"; label["cap4"] = "strain-rate cap 4 /s"
    label["local"] = "Cundall local damping α = 0.05"; label["damping0.2"] = "viscous damping 0.2 of critical"
    label["dt2e-6"] = "Δt = 2 µs"; label["number"] = "grading read by count"
    for (i = 1; i <= 3; i++) for (j = 1; j <= 7; j++) {
      k = ds[i] SUBSEP vs[j]; b = ds[i] SUBSEP "base"
      if (!(k in e)) continue
      printf "| %s | %s | %.4f | %+.4f | %.3f | %+.3f | %.3f | %.2f | %d |\n", ds[i], label[vs[j]], e[k], e[k] - e[b], z[k], z[k] - z[b], zm[k], side[k], st[k]
    }
  }'
