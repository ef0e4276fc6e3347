#!/usr/bin/env bash
# Issue 3: the sample table (mean and spread over seeds) from the preparation results.
# Usage: reports/samples/make_table.sh [DEM] [RESULTS_DIR] > reports/samples/table.md
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
dir=${2:-$here/results/samples}
shopt -s nullglob
files=("$dir"/*_n*_s*_*.h5)
[ ${#files[@]} -gt 0 ] || { echo "no results in $dir" >&2; exit 1; }
"$dem" summary "${files[@]}" | awk -F'\t' '
  NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  {
    n = split($1, parts, "/"); base = parts[n]; sub(/\.h5$/, "", base)
    split(base, f, "_")             # density, nN, sS, damping
    key = f[1] " " f[2] " " f[4]
    if (!(key in count)) order[++groups] = key
    count[key]++
    np = substr(f[2], 2) ^ 3        # scale the side to the 8,000-sphere sample the paper reports
    L = ($col["cell_length_1"] * $col["cell_length_2"] * $col["cell_length_3"] * 8000 / np) ^ (1 / 3) * 100
    v[key, "e0"] += $col["void_ratio"];              s[key, "e0"] += $col["void_ratio"] ^ 2
    v[key, "L"] += L;                                  s[key, "L"] += L ^ 2
    v[key, "cn"] += $col["coordination_number"];     s[key, "cn"] += $col["coordination_number"] ^ 2
    v[key, "cnm"] += $col["coordination_number_mechanical"]; s[key, "cnm"] += $col["coordination_number_mechanical"] ^ 2
    v[key, "sl"] += 100 * $col["sliding_fraction"];  s[key, "sl"] += (100 * $col["sliding_fraction"]) ^ 2
    v[key, "fn"] += $col["mean_normal_force"];       s[key, "fn"] += $col["mean_normal_force"] ^ 2
    v[key, "ub"] += $col["unbalanced_force_ratio"];  s[key, "ub"] += $col["unbalanced_force_ratio"] ^ 2
    v[key, "st"] += $col["step"];                    s[key, "st"] += $col["step"] ^ 2
    v[key, "wt"] += $2;                              s[key, "wt"] += $2 ^ 2
  }
  function cell(key, q, digits,   m, var) {
    m = v[key, q] / count[key]
    var = s[key, q] / count[key] - m * m; if (var < 0) var = 0
    if (count[key] == 1) return sprintf("%." digits "f", m)
    return sprintf("%." digits "f ± %." digits "f", m, sqrt(var * count[key] / (count[key] - 1)))
  }
  END {
    ref_e["loose"] = 0.73; ref_e["medium"] = 0.67; ref_e["dense"] = 0.57
    ref_z["loose"] = 4.09; ref_z["medium"] = 4.88; ref_z["dense"] = 5.94
    ref_L["loose"] = 7.3; ref_L["medium"] = 7.2; ref_L["dense"] = 7.1
    print "| sample | particles | damping | seeds | e0 (paper) | Δe0 | cell side cm, 8,000-sphere equivalent (paper) | CN (paper) | ΔCN | CN w/o rattlers | sliding % | mean f_n (N) | unbalanced | steps | wall time (s) |"
    print "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    for (g = 1; g <= groups; g++) {
      key = order[g]; split(key, k, " ")
      np = substr(k[2], 2) ^ 3
      de = v[key, "e0"] / count[key] - ref_e[k[1]]; dz = v[key, "cn"] / count[key] - ref_z[k[1]]
      printf "| %s | %d | %s | %d | %s (%.2f) | %+.3f | %s (%.1f) | %s (%.2f) | %+.2f | %s | %s | %s | %s | %s | %s |\n", \
        k[1], np, k[3], count[key], cell(key, "e0", 3), ref_e[k[1]], de, cell(key, "L", 2), ref_L[k[1]], \
        cell(key, "cn", 2), ref_z[k[1]], dz, cell(key, "cnm", 2), cell(key, "sl", 1), cell(key, "fn", 3), \
        cell(key, "ub", 5), cell(key, "st", 0), cell(key, "wt", 0)
    }
  }'
