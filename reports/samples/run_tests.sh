#!/usr/bin/env bash
# Issue 4: the five cyclic tests on each full-size sample, run one after the other.
# Waits for each density's sample (results/samples/<d>_n20_s1_viscous.h5), skips finished results.
# Usage: reports/samples/run_tests.sh DEM "dense medium loose"
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
densities=${2:-dense medium loose}
out=$here/results/tests
mkdir -p "$out"
for d in $densities; do
  sample=$here/results/samples/${d}_n20_s1_viscous.h5
  until [ -f "$sample" ]; do sleep 30; done
  for t in 1 2 3 4 5; do
    name=${d}_test$t
    [ -f "$out/$name.h5" ] && { echo "skip $name"; continue; }
    # Several workers may share the list: a lock folder marks a run taken (remove stale ones by hand).
    mkdir "$out/$name.lock" 2>/dev/null || { echo "skip $name (taken by another worker)"; continue; }
    "$dem" run "$here/scenes/tests/test$t.yaml" --out "$out/$name.h5" --quiet \
      --set "name=$name" --set "particles.state=$sample" > "$out/$name.log" 2>&1 \
      && echo "done $name" || echo "FAILED $name (see $out/$name.log)"
    rmdir "$out/$name.lock"
  done
done
