#!/usr/bin/env bash
# One line per cyclic test result of one sample: steps, wall time, worst tracking error, largest
# inertial number, and volumetric strain and coordination number at the end of cycles 1 and 5
# (cycles 1 and 30 for Test 5). Usage: reports/samples/tests_table.sh [DEM] [DIR] > table.md
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
dir=${2:-$here/results/study/paper/seed1}
echo "| sample | test | steps | wall time (s) | worst leg RMS tracking error (% of p) | largest inertial number | εv cycle 1 (%) | εv cycle 5/30 (%) | CN cycle 0 | CN cycle 1 | CN cycle 5/30 |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for d in loose medium dense; do
  for t in 1 2 3 4 5; do
    f=$dir/${d}_test$t.h5
    [ -f "$f" ] || { echo "| $d | $t | not run | | | | | | | | |"; continue; }
    last=5; [ "$t" = 5 ] && last=30
    wall=$("$dem" summary "$f" | awk -F'\t' 'NR == 2 { print $2 }')
    legs=$("$dem" table "$f" --legs rms_error_1 rms_error_2 rms_error_3 max_inertial_number | awk '
      NR > 1 { for (k = 1; k <= 3; k++) if ($k > e) e = $k; if ($4 > I) I = $4 }
      END { printf "%.3f\t%.2e", 100 * e, I }')
    "$dem" table "$f" step cycle cycle_end volumetric_strain coordination_number | awk -v d="$d" -v t="$t" \
      -v last="$last" -v wall="$wall" -v legs="$legs" '
      NR == 2 { cn0 = $5 }
      NR > 1 { steps = $1 }
      NR > 1 && $3 == 1 && $2 == 1 { ev1 = 100 * $4; cn1 = $5 }
      NR > 1 && $3 == 1 && $2 == last { evl = 100 * $4; cnl = $5 }
      END { split(legs, l, "\t")
            printf "| %s | %s | %d | %.0f | %s | %s | %.4f | %.4f | %.3f | %.3f | %.3f |\n", d, t, steps, wall, l[1], l[2], ev1, evl, cn0, cn1, cnl }'
  done
done
