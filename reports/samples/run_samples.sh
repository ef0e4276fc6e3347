#!/usr/bin/env bash
# Issue 3: the three preparation scenes over seeds, sample sizes and the two damping forms.
# Runs JOBS at a time (default 2), skips results that already exist (complete files only),
# and logs each run beside its result. Usage: reports/samples/run_samples.sh [DEM] [OUTDIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
out=${2:-$here/results/samples}
jobs=${JOBS:-2}
mkdir -p "$out"

list() {  # density n seed damping; full-size seeds 2 and 3, and local damping beyond 1,000 spheres, only with FULL=1
  for n in 10 15 20; do
    for seed in 1 2 3; do
      [ "$n" = 20 ] && [ "$seed" != 1 ] && [ "${FULL:-0}" != 1 ] && continue
      for d in dense medium loose; do echo "$d $n $seed viscous"; done
    done
    [ "$n" = 10 ] || [ "${FULL:-0}" = 1 ] && for d in dense medium loose; do echo "$d $n 1 local"; done
  done
}

run_one() {
  local d=$1 n=$2 seed=$3 damping=$4
  local name="${d}_n${n}_s${seed}_${damping}"
  [ -f "$out/$name.h5" ] && { echo "skip $name (done)"; return 0; }
  "$dem" run "$here/scenes/prepare_$d.yaml" --out "$out/$name.h5" --quiet \
    --set "name=prepare_$name" --set "particles.lattice.n=[$n, $n, $n]" \
    --set "particles.lattice.seed=$seed" --set "damping.form=$damping" > "$out/$name.log" 2>&1 \
    && echo "done $name" || echo "FAILED $name (see $out/$name.log)"
}
export -f run_one
export dem out here
list | xargs -P "$jobs" -L 1 bash -c 'run_one "$@"' _
