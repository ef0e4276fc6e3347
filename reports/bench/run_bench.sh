#!/usr/bin/env bash
# run_bench.sh: `make bench`. Times our engine (dem-bench: 1 and 2 threads) and LAMMPS (one core) on
# the same 8,000-sphere packings, and writes OUT_DIR/bench.json and OUT_DIR/bench.md.
#
#   reports/bench/run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]
#
# Each friction is timed on a packing jammed at 100 kPa with that friction (built once by dem-bench,
# cached in BUILD_DIR/bench). LAMMPS gets the same positions, radii, box, contact law, dt and skin
# (reports/bench/lammps_bench.sh says what it cannot match: it has no stress servo and no spin damping).
set -euo pipefail
build=${1:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
out=${2:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
steps=${3:-3000}
reps=${4:-5}
here=$(cd "$(dirname "$0")" && pwd)
work=$build/bench
mkdir -p "$work" "$out"

# The mu = 0 packing takes dem-bench 10-20 min to build; the study's dense sample is one (8,000
# spheres, mu = 0, 100 kPa, same material and dt), so it is used when it exists.
sample=${BENCH_MU0_PACKING:-results/study/paper/dense_prepare.h5}
if [ ! -f "$work/packing_mu0.h5" ] && [ -f "$sample" ]; then
  echo "run_bench: mu = 0 packing: the study's dense sample $sample"
  cp "$sample" "$work/packing_mu0.h5"
fi

echo "== our engine (dem-bench) =="
"$build/bin/dem-bench" "$work" 0   # builds missing packings; the timing runs in a fresh process
"$build/bin/dem-bench" "$work" "$steps" "$reps"

echo "== LAMMPS, same packings =="
for tag in mu05:0.5 mu0:0; do
  name=${tag%%:*} mu=${tag##*:}
  "$build/bin/dem" state "$work/packing_$name.h5" >"$work/packing_$name.txt"
  read -r lx ly lz < <("$build/bin/dem" table "$work/packing_$name.h5" cell_length_1 cell_length_2 cell_length_3 | tail -n 1)
  FRICTIONS=$mu "$here/lammps_bench.sh" "$work/packing_$name.txt" "$lx" "$ly" "$lz" "$steps" "$reps" "$work/lammps_$name.json"
done

# One line per run in both JSON files (our own formats): pick the median of a (friction, threads) run.
engine_rate() { grep "\"friction\": $1, \"threads\": $2," "$work/bench.json" | sed 's/.*"particle_steps_per_s_median": \([^,]*\),.*/\1/'; }
engine_z() { grep "\"friction\": $1, \"threads\": 1," "$work/bench.json" | sed 's/.*"coordination_number": \([^,]*\),.*/\1/'; }
two_runs_rate() { grep "\"friction\": $1, \"runs\": 2," "$work/bench.json" | sed 's/.*"total_particle_steps_per_s_median": \([^,]*\),.*/\1/'; }
lammps_rate() { grep '"particle_steps_per_s_median"' "$work/lammps_$1.json" | sed 's/.*"particle_steps_per_s_median": \([^,]*\),.*/\1/'; }
lammps_z() { grep '"coordination_number_start"' "$work/lammps_$1.json" | sed 's/.*"coordination_number_start": \([^,]*\),.*/\1/'; }
lammps_z_end() { grep '"coordination_number_end"' "$work/lammps_$1.json" | sed 's/.*"coordination_number_end": \([^,]*\),.*/\1/'; }

{
  echo "{"
  echo "  \"engine\": $(sed 's/^/  /' "$work/bench.json" | sed '1s/^  //'),"
  echo "  \"lammps\": ["
  sed 's/^/    /' "$work/lammps_mu05.json"
  echo "    ,"
  sed 's/^/    /' "$work/lammps_mu0.json"
  echo "  ]"
  echo "}"
} >"$out/bench.json"

{
  echo "| friction | packing 2Nc/N (ours / LAMMPS at start → end) | ours, 1 thread | ours, 2 threads | 2 / 1 thread | ours, 2 runs at once (1 thread each), total | 2 runs / 1 thread | LAMMPS, 1 core | ours (1 thread) / LAMMPS |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for tag in mu05:0.5 mu0:0; do
    name=${tag%%:*} mu=${tag##*:}
    e1=$(engine_rate "$mu" 1) e2=$(engine_rate "$mu" 2) r2=$(two_runs_rate "$mu") l=$(lammps_rate "$name")
    awk -v mu="$mu" -v e1="$e1" -v e2="$e2" -v r2="$r2" -v l="$l" -v ze="$(engine_z "$mu")" -v zl="$(lammps_z "$name")" \
      -v zle="$(lammps_z_end "$name")" 'BEGIN {
      printf "| %s | %.2f / %.2f → %.2f | %.3g | %.3g | %.2f | %.3g | %.2f | %.3g | %.2f |\n", mu, ze, zl, zle, e1, e2, e2 / e1, r2, r2 / e1, l, e1 / l }'
  done
  echo
  echo "Particle-steps per second, medians of $reps repetitions of $steps steps (dt = 1 µs, 8,000 spheres),"
  echo "measured by \`make bench\` on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')),"
  echo "force loop $(grep vector_lanes "$work/bench.json" | sed 's/.*: \([0-9]*\).*/\1/') pairs per vector operation (8: AVX-512, 4: AVX2, 0: scalar)."
  echo "Peak memory of dem-bench: $(grep peak_rss_MB "$work/bench.json" | sed 's/.*: \([0-9.]*\).*/\1/') MB."
  echo "LAMMPS runs in a fixed cell without our stress servo and starts without tangential springs; where"
  echo "its 2Nc/N falls during the run (→ end), it times a loosening packing, not a like-for-like one."
} >"$out/bench.md"
cat "$out/bench.md"
