#!/usr/bin/env bash
# run_bench.sh: `make bench`. Times our engine (dem-bench: 1 and 2 threads) and LAMMPS (one core) on
# the same 8,000-sphere packings, then the cost against size on the same packing tiled up to a
# million spheres, and writes OUT_DIR/bench.json and OUT_DIR/bench.md.
#
#   reports/bench/run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]
#
# Three cases, each on a packing jammed at 100 kPa (built once by dem-bench, cached in BUILD_DIR/bench):
# mu = 0.5 and mu = 0 each on the packing jammed with that friction, and mu = 0.5 on the mu = 0
# packing, the like-for-like case: that packing needs no tangential force to stand, so LAMMPS, which
# starts without tangential springs, keeps its contacts as our engine does. LAMMPS gets the same
# positions, radii, box, contact law, dt and skin (reports/bench/lammps_bench.sh says what it cannot
# match: it has no stress servo and no spin damping).
#
# Cost against size: the mu = 0 packing tiled n x n x n (8,000 n^3 spheres: `dem-bench size`, LAMMPS's
# `replicate`), mu = 0.5 and mu = 0, our engine on 1 and 2 threads (each size in its own process, for
# its peak memory), LAMMPS on one core. SIZE_PLAN lists TILES:STEPS:REPS per size, the same for both
# codes (each repetition: the packing again, 200 warm-up steps, then STEPS timed); the steps shrink
# with the size so that the whole benchmark stays near a quarter of an hour. SIZE_PLAN="" skips it.
#
# The contact laws' price: `dem-bench laws` runs Test 1's first 2 cycles on the shipped 1,000-sphere
# loose sample with each law (linear, contact dashpots, Hertz-Mindlin, rolling resistance), one
# thread, LAWS_REPS repetitions (default 5) interleaved, per CPU second per step.
#
# Every program writes JSON with nlohmann-json (dem-bench; lammps_bench.sh through `bench-report lammps-json`);
# build/bin/bench-report reads them all and writes bench.json and bench.md.
set -euo pipefail
build=${1:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
out=${2:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
steps=${3:-5000}
reps=${4:-7}
# Both codes use the Verlet skin of the study's cyclic tests. Measured on the mu = 0.5 like-for-like
# case: LAMMPS 1.00e7, 9.8e6 and 9.5e6 particle-steps/s with 2.5e-5, 5e-5 and 2e-4 m (so this is
# also its fastest of the three); our engine 14 % faster with 2.5e-5 than with 2e-4.
export SKIN=${SKIN:-2.5e-5}
export BENCH_REPORT=$build/bin/bench-report   # lammps_bench.sh writes its JSON with it
size_plan=${SIZE_PLAN-"1:4000:5 2:600:5 4:100:3 5:60:3"}
here=$(cd "$(dirname "$0")" && pwd)
# The machine is shared: its load before and after says how far the figures are the code's.
load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
work=$build/bench
mkdir -p "$work" "$out"

# The mu = 0 packing takes dem-bench 10-20 min to build; the study's dense sample is one (8,000
# spheres, mu = 0, 100 kPa, same material and dt), so it is used when it exists.
sample=${BENCH_MU0_PACKING:-results/study/paper/seed1/dense_prepare.h5}
[ -f "$sample" ] || sample=results/study/paper/dense_prepare.h5   # a study from before the ensembles
if [ ! -f "$work/packing_mu0.h5" ] && [ -f "$sample" ]; then
  echo "run_bench: mu = 0 packing: the study's dense sample $sample"
  cp "$sample" "$work/packing_mu0.h5"
fi

echo "== our engine (dem-bench) =="
"$build/bin/dem-bench" "$work" 0   # builds missing packings; the timing runs in a fresh process
"$build/bin/dem-bench" "$work" "$steps" "$reps" "$SKIN"

echo "== our engine: the sheared cell's price (dem-bench shear) =="
"$build/bin/dem-bench" shear "$work" "$steps" "$reps" "$SKIN"

echo "== our engine: the contact laws' price (dem-bench laws) =="
"$build/bin/dem-bench" laws "$work" "${LAWS_REPS:-5}"

echo "== LAMMPS, same packings =="
cases="mu05:0.5 mu0:0 mu0:0.5"   # packing:friction, the engine's order
for c in $cases; do
  name=${c%%:*} mu=${c##*:}
  "$build/bin/dem" state "$work/packing_$name.h5" >"$work/packing_$name.txt"
  # The cell's lengths and tilts (a preparation that holds its shear stresses at zero tilts its cell).
  "$build/bin/dem" table "$work/packing_$name.h5" cell_length_1 cell_length_2 cell_length_3 cell_tilt_12 cell_tilt_13 \
    cell_tilt_23 | tail -n 1 >"$work/packing_$name.box"
  FRICTIONS=$mu "$here/lammps_bench.sh" "$work/packing_$name.txt" $(cat "$work/packing_$name.box") "$steps" "$reps" \
    "$work/lammps_${name}_$mu.json"
done

# Cost against size: one dem-bench process per size, then LAMMPS on the same tiled packing.
size_files=""
for plan in $size_plan; do
  IFS=: read -r tiles size_steps size_reps <<<"$plan"
  n=$((8000 * tiles * tiles * tiles))
  echo "== cost against size: $n spheres, our engine =="
  "$build/bin/dem-bench" size "$work" "$tiles" "$size_steps" "$size_reps" "$SKIN" tiled
  echo "== cost against size: $n spheres, LAMMPS =="
  TILES=$tiles FRICTIONS="0.5 0" "$here/lammps_bench.sh" "$work/packing_mu0.txt" $(cat "$work/packing_mu0.box") \
    "$size_steps" "$size_reps" "$work/lammps_size_$n.json"
  size_files="$size_files $n"
done

# bench.json (every run's JSON file in one) and bench.md (the tables and what they were measured
# on): build/bin/bench-report reads the files with nlohmann-json (validation/bench_report.cpp).
"$build/bin/bench-report" "$work" "$out" --steps "$steps" --reps "$reps" --skin "$SKIN" --cases "$cases" \
  --sizes "$size_files" --size-plan "$size_plan" --cores "$(nproc)" \
  --cpu "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')" \
  --load-start "$load_start" --load-end "$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)"
# Threads beside other work: the 1,000-sphere Test 1 (scenes/tests/test1.yaml, whole `dem run`s) on 1
# and 2 threads, on the machine as it is and beside a busy core (a shell loop at the same priority),
# 3 interleaved repetitions (busy_core.sh; about 5 min). OpenMP threads that spin while they wait
# made 2 threads 28 times slower than 1 beside a busy core (Test 1's first leg: 90.9 s against
# 3.3 s) and, on a machine at load average 8, the whole Test 1 344.7 s against 32.0 s (38.7 s
# waiting passively); dem's threads wait passively (engine/cli/dem_main.cpp), and a run on several
# threads keeps 1 thread while that steps faster (engine/run/thread_choice.hpp).
echo "== threads beside a busy core (dem run scenes/tests/test1.yaml) =="
"$here/busy_core.sh" "$build" "${BUSY_REPS:-3}" >>"$out/bench.md"
cat "$out/bench.md"
