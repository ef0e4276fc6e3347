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
set -euo pipefail
build=${1:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
out=${2:?usage: run_bench.sh BUILD_DIR OUT_DIR [STEPS] [REPS]}
steps=${3:-5000}
reps=${4:-7}
# Both codes use the Verlet skin of the study's cyclic tests. Measured on the mu = 0.5 like-for-like
# case: LAMMPS 1.00e7, 9.8e6 and 9.5e6 particle-steps/s with 2.5e-5, 5e-5 and 2e-4 m (so this is
# also its fastest of the three); our engine 14 % faster with 2.5e-5 than with 2e-4.
export SKIN=${SKIN:-2.5e-5}
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

echo "== LAMMPS, same packings =="
cases="mu05:0.5 mu0:0 mu0:0.5"   # packing:friction, the engine's order
for c in $cases; do
  name=${c%%:*} mu=${c##*:}
  "$build/bin/dem" state "$work/packing_$name.h5" >"$work/packing_$name.txt"
  read -r lx ly lz < <("$build/bin/dem" table "$work/packing_$name.h5" cell_length_1 cell_length_2 cell_length_3 | tail -n 1)
  echo "$lx $ly $lz" >"$work/packing_$name.box"
  FRICTIONS=$mu "$here/lammps_bench.sh" "$work/packing_$name.txt" "$lx" "$ly" "$lz" "$steps" "$reps" "$work/lammps_${name}_$mu.json"
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

# One line per run in both JSON files (our own formats): pick the median of a (packing, friction,
# threads) run.
engine_row() { grep "\"packing\": \"$1\", \"friction\": $2, \"$3\": " "$work/bench.json"; }
engine_rate() { engine_row "$1" "$2" threads | grep "\"threads\": $3," | sed 's/.*"particle_steps_per_s_median": \([^,]*\),.*/\1/'; }
engine_z() { engine_row "$1" "$2" threads | grep '"threads": 1,' | sed 's/.*"coordination_number": \([^,]*\),.*/\1/'; }
two_runs_rate() { engine_row "$1" "$2" runs | sed 's/.*"total_particle_steps_per_s_median": \([^,]*\),.*/\1/'; }
lammps_value() { grep "\"$3\"" "$work/lammps_$1_$2.json" | sed "s/.*\"$3\": \([^,]*\),.*/\1/"; }

{
  echo "{"
  echo "  \"engine\": $(sed 's/^/  /' "$work/bench.json" | sed '1s/^  //'),"
  echo "  \"sheared_cell\": $(sed 's/^/  /' "$work/shear.json" | sed '1s/^  //'),"
  echo "  \"lammps\": ["
  sep=""
  for c in $cases; do
    [ -n "$sep" ] && echo "    ,"
    sed 's/^/    /' "$work/lammps_${c%%:*}_${c##*:}.json"
    sep=1
  done
  echo "  ],"
  echo "  \"cost_against_size\": {"
  echo "    \"engine\": ["
  sep=""
  for n in $size_files; do
    [ -n "$sep" ] && echo "      ,"
    sed 's/^/      /' "$work/size_${n}_tiled.json"
    sep=1
  done
  echo "    ],"
  echo "    \"lammps\": ["
  sep=""
  for n in $size_files; do
    [ -n "$sep" ] && echo "      ,"
    sed 's/^/      /' "$work/lammps_size_$n.json"
    sep=1
  done
  echo "    ]"
  echo "  }"
  echo "}"
} >"$out/bench.json"

{
  echo "| packing jammed with | friction | 2Nc/N (ours / LAMMPS at start → end) | ours, 1 thread | ours, 2 threads | 2 / 1 thread | ours, 2 runs at once (1 thread each), total | 2 runs / 1 thread | LAMMPS, 1 core | ours (1 thread) / LAMMPS |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for c in $cases; do
    name=${c%%:*} mu=${c##*:}
    e1=$(engine_rate "$name" "$mu" 1) e2=$(engine_rate "$name" "$mu" 2) r2=$(two_runs_rate "$name" "$mu")
    l=$(lammps_value "$name" "$mu" particle_steps_per_s_median)
    awk -v pk="$([ "$name" = mu0 ] && echo "μ = 0" || echo "μ = 0.5")" -v mu="$mu" -v e1="$e1" -v e2="$e2" -v r2="$r2" -v l="$l" \
      -v ze="$(engine_z "$name" "$mu")" -v zl="$(lammps_value "$name" "$mu" coordination_number_start)" \
      -v zle="$(lammps_value "$name" "$mu" coordination_number_end)" 'BEGIN {
      printf "| %s | %s | %.2f / %.2f → %.2f | %.3g | %.3g | %.2f | %.3g | %.2f | %.3g | %.2f |\n", pk, mu, ze, zl, zle, e1, e2, e2 / e1, r2, r2 / e1, l, e1 / l }'
  done
  echo
  echo "Particle-steps per second, medians of $reps repetitions of $steps steps (dt = 1 µs, 8,000 spheres,"
  echo "Verlet skin $SKIN m in both codes),"
  echo "measured by \`make bench\` on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')),"
  echo "force loop $(grep vector_lanes "$work/bench.json" | sed 's/.*: \([0-9]*\).*/\1/') pairs per vector operation (8: AVX-512, 4: AVX2, 0: scalar)."
  echo "Peak memory of dem-bench: $(grep peak_rss_MB "$work/bench.json" | sed 's/.*: \([0-9.]*\).*/\1/') MB."
  echo "LAMMPS runs in a fixed cell without our stress servo and starts without tangential springs. On the"
  echo "packing jammed with μ = 0.5 it loses them and, where its 2Nc/N falls during the run (→ end), it times a"
  echo "loosening packing; μ = 0.5 on the packing jammed with μ = 0 needs no tangential force to stand, so"
  echo "both codes time the same jammed packing with friction: that row is the like-for-like comparison."
  echo "Load average of the machine (1, 5, 15 min; the benchmark's own runs add 1 to 2): $load_start at the"
  echo "start, $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown) at the end; above 2 other work shared the two cores."
} >"$out/bench.md"
[ -n "$size_files" ] && {
  # A value of one run line: size_value FILE FRICTION THREADS KEY (THREADS "" for LAMMPS's lines).
  size_value() {
    grep "\"friction\": $2, ${3:+\"threads\": $3, }" "$1" | sed "s/.*\"$4\": \([^,}]*\).*/\1/"
  }
  top() { grep "\"$2\":" "$1" | head -n 1 | sed "s/.*\"$2\": \([^,]*\),*/\1/"; }
  first=${size_files%% *}
  first=${first:-8000}
  lmp_peak() { awk '/"peak_rss_MB"/ { sub(/.*"peak_rss_MB": /, ""); sub(/[,}].*/, ""); if ($0 + 0 > m) m = $0 + 0 } END { print m + 0 }' "$1"; }
  echo
  echo "### Cost against size"
  echo
  echo "| spheres | friction | ours, 1 thread (min – max) | vs 8,000 | ours, 2 threads (min – max) | vs 8,000 | 2 / 1 thread | LAMMPS, 1 core (min – max) | vs 8,000 | ours (1 thread) / LAMMPS |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  for mu in 0.5 0; do
    for n in $size_files; do
      e="$work/size_${n}_tiled.json" l="$work/lammps_size_$n.json" e8="$work/size_${first}_tiled.json" l8="$work/lammps_size_$first.json"
      awk -v n="$n" -v mu="$mu" \
        -v e1="$(size_value "$e" "$mu" 1 particle_steps_per_s_median)" -v e1a="$(size_value "$e" "$mu" 1 min)" -v e1b="$(size_value "$e" "$mu" 1 max)" \
        -v e2="$(size_value "$e" "$mu" 2 particle_steps_per_s_median)" -v e2a="$(size_value "$e" "$mu" 2 min)" -v e2b="$(size_value "$e" "$mu" 2 max)" \
        -v l="$(size_value "$l" "$mu" "" particle_steps_per_s_median)" -v la="$(size_value "$l" "$mu" "" min)" -v lb="$(size_value "$l" "$mu" "" max)" \
        -v r1="$(size_value "$e8" "$mu" 1 particle_steps_per_s_median)" -v r2="$(size_value "$e8" "$mu" 2 particle_steps_per_s_median)" \
        -v rl="$(size_value "$l8" "$mu" "" particle_steps_per_s_median)" 'function commas(x,  s) { x = sprintf("%d", x); s = ""; while (length(x) > 3) { s = "," substr(x, length(x) - 2) s; x = substr(x, 1, length(x) - 3) } return x s }
      BEGIN {
        printf "| %s | %s | %.3g (%.3g – %.3g) | %.2f | %.3g (%.3g – %.3g) | %.2f | %.2f | %.3g (%.3g – %.3g) | %.2f | %.2f |\n",
          commas(n), mu, e1, e1a, e1b, e1 / r1, e2, e2a, e2b, e2 / r2, e2 / e1, l, la, lb, l / rl, e1 / l }'
    done
  done
  echo
  echo "The same on one thread per CPU-second of the timed steps (ours: the thread's CPU time; LAMMPS: its \"% CPU"
  echo "use\"), which a busy machine's time-slicing does not inflate (its sharing of caches and memory still counts):"
  echo
  echo "| spheres | friction | ours, 1 thread | vs 8,000 | LAMMPS, 1 core | vs 8,000 | ours / LAMMPS |"
  echo "|---|---|---|---|---|---|---|"
  for mu in 0.5 0; do
    for n in $size_files; do
      e="$work/size_${n}_tiled.json" l="$work/lammps_size_$n.json" e8="$work/size_${first}_tiled.json" l8="$work/lammps_size_$first.json"
      awk -v n="$n" -v mu="$mu" -v e="$(size_value "$e" "$mu" 1 cpu_rate_median)" -v e8="$(size_value "$e8" "$mu" 1 cpu_rate_median)" \
        -v l="$(size_value "$l" "$mu" "" cpu_rate_median)" -v l8="$(size_value "$l8" "$mu" "" cpu_rate_median)" \
        'function commas(x,  s) { x = sprintf("%d", x); s = ""; while (length(x) > 3) { s = "," substr(x, length(x) - 2) s; x = substr(x, 1, length(x) - 3) } return x s }
      BEGIN { printf "| %s | %s | %.3g | %.2f | %.3g | %.2f | %.2f |\n", commas(n), mu, e, e / e8, l, l / l8, e / l }'
    done
  done
  echo
  echo "| spheres | ours: peak memory (MB) | ours: bytes per sphere beyond 8,000 | LAMMPS: peak memory (MB) | LAMMPS: bytes per sphere beyond 8,000 |"
  echo "|---|---|---|---|---|"
  for n in $size_files; do
    awk -v n="$n" -v n8="$first" -v e="$(top "$work/size_${n}_tiled.json" peak_rss_MB)" -v e8="$(top "$work/size_${first}_tiled.json" peak_rss_MB)" \
      -v l="$(lmp_peak "$work/lammps_size_$n.json")" -v l8="$(lmp_peak "$work/lammps_size_$first.json")" 'function commas(x,  s) { x = sprintf("%d", x); s = ""; while (length(x) > 3) { s = "," substr(x, length(x) - 2) s; x = substr(x, 1, length(x) - 3) } return x s }
      BEGIN {
      if (n == n8) printf "| %s | %.0f | – | %.0f | – |\n", commas(n), e, l
      else printf "| %s | %.0f | %.0f | %.0f | %.0f |\n", commas(n), e, (e - e8) * 1048576 / (n - n8), l, (l - l8) * 1048576 / (n - n8) }'
  done
  echo
  echo "Particle-steps per second, median (min – max) of REPS repetitions of STEPS steps after 200 warm-up steps,"
  echo "the same for both codes (TILES:STEPS:REPS: $size_plan), on the μ = 0 packing above tiled n × n × n"
  echo "(\`dem-bench size\`, LAMMPS \`replicate\`): identical contacts and stress at every size; Verlet skin $SKIN m."
  echo "\"vs 8,000\": the median over the same code's 8,000-sphere median of this table. Each size of our engine"
  echo "runs in its own process (peak memory: VmHWM; LAMMPS: GNU time's maximum resident set, μ = 0.5 and μ = 0 runs"
  echo "each in its own process, the larger shown). Our particles are in tiled order (copy after copy); LAMMPS sorts"
  echo "its atoms spatially when a run starts."
} >>"$out/bench.md"

# The sheared cell (a scene whose cell never shears runs the orthorhombic kernels, chosen per step).
shear_rate() { grep "\"cell\": \"$1\"" "$work/shear.json" | sed "s/.*\"$2\": \([^,}]*\).*/\1/"; }
{
  echo
  echo "### The sheared cell"
  echo
  echo "| cell | particle-steps per CPU-s (median) | min – max | vs orthorhombic |"
  echo "|---|---|---|---|"
  for c in orthorhombic sheared; do
    awk -v c="$c" -v m="$(shear_rate "$c" cpu_rate_median)" -v a="$(shear_rate "$c" min)" -v b="$(shear_rate "$c" max)" \
      -v o="$(shear_rate orthorhombic cpu_rate_median)" 'BEGIN { printf "| %s | %.3g | %.3g – %.3g | %.3f |\n", c, m, a, b, m / o }'
  done
  echo
  echo "\`dem-bench shear\`: μ = 0.5 on the μ = 0 packing, one thread, the axes held at 100 kPa; \"sheared\" also shears"
  echo "xy at 1/s, so its cell tilts from the first step and every step runs the sheared kernels (nearest image"
  echo "through the tilts, fractional positions in the update). Medians of $reps repetitions of $steps steps,"
  echo "the two ways interleaved, per CPU second of the one thread."
} >>"$out/bench.md"
cat "$out/bench.md"
