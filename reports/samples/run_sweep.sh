#!/usr/bin/env bash
# Issue 3, item 4: how e0 and CN depend on the protocol's free choices, one at a time from the
# baseline (SPEC defaults), on 1,000-sphere samples (10^3 lattice, seed 1).
# Usage: reports/samples/run_sweep.sh [DEM] [OUTDIR]
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
dem=${1:-$here/build/bin/dem}
out=${2:-$here/results/sweep}
mkdir -p "$out"
variants=(
  "base|"
  "cap0.25|--set stages[0].max_strain_rate=0.25"
  "cap4|--set stages[0].max_strain_rate=4"
  "local|--set damping.form=local"
  "damping0.2|--set damping.translational=0.2 --set damping.rotational=0.2"
  "dt2e-6|--set numerics.time_step=2.0e-6"
  "number|--set particles.grading.basis=number"
)
for d in dense medium loose; do
  for v in "${variants[@]}"; do
    name=${v%%|*}; args=${v#*|}
    res="$out/${d}_${name}.h5"
    [ -f "$res" ] && { echo "skip ${d}_${name}"; continue; }
    # shellcheck disable=SC2086
    "$dem" run "$here/scenes/prepare_$d.yaml" --out "$res" --quiet --set "name=sweep_${d}_${name}" \
      --set "particles.lattice.n=[10, 10, 10]" $args > "$out/${d}_${name}.log" 2>&1 \
      && echo "done ${d}_${name}" || echo "FAILED ${d}_${name} (see $out/${d}_${name}.log)"
  done
done
