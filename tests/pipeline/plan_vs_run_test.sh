#!/usr/bin/env bash
# The plan against the run: the quick profile's dense preparation of seed 2 (1,000 spheres; the
# plan's model was fitted on seed 1's, the shipped sample) is planned, run, and its particle-steps
# compared: within 25 %. Then, its scene changed (another output interval: other inputs, the same
# run), the plan takes the finished result's recorded particle-steps as they are and its recorded
# wall time for the throughput: the one-core time is that wall time. About 90 s of one core.
#   tests/pipeline/plan_vs_run_test.sh BIN_DIR SOURCE_DIR WORKDIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
study() {  # $1: extra preparation settings of the variant
  cat > "$work/study.yaml" <<YAML
name: plan_check
output: out
preparation: $src/scenes/prepare_dense.yaml
densities: [{name: dense, friction: 0.0}]
variants: [{name: dense_prepare$1}]
profiles: {quick: {lattice: 10, seeds: [2]}}
YAML
}
planned() {  # the particle-steps and basis the plan gives the run: "6.8e+08 model"
  "$bin/pipeline" "$work/study.yaml" --profile quick --plan > "$work/plan.txt" 2>&1 || { cat "$work/plan.txt"; exit 1; }
  awk '$1 == "seed2/dense_prepare" { print $3, $5 }' "$work/plan.txt" | tr -d '()'
}
study ""
read -r plan basis < <(planned)
[ "$basis" = model ] || { echo "plan: basis '$basis', expected model"; cat "$work/plan.txt"; exit 1; }
# A plan runs nothing and lists nothing: no runs.tsv for the other tools to take as a study that ran.
[ -d "$work/out/quick/scenes" ] || { echo "plan: no resolved scenes in $work/out/quick"; exit 1; }
[ ! -e "$work/out/quick/runs.tsv" ] || { echo "plan: wrote $work/out/quick/runs.tsv"; exit 1; }
"$bin/pipeline" "$work/study.yaml" --profile quick -j 1 --threads 1 > "$work/run.txt" 2>&1 || { cat "$work/run.txt"; exit 1; }
result=$work/out/quick/seed2/dense_prepare.h5
steps=$(h5dump -a /state/step "$result" | awk '/\(0\)/ { print $2 }')
wall=$(h5dump -a /wall_time_s "$result" | awk '/\(0\)/ { print $2 }')
awk -v p="$plan" -v s="$steps" 'BEGIN {
  m = s * 1000; e = p / m - 1
  printf "dense seed 2, 1,000 spheres: planned %.4g particle-steps, ran %.4g (%d steps): %+.1f %%\n", p, m, s, 100 * e
  exit (e > 0.25 || e < -0.25) }' || { echo "plan and run differ by more than 25 %"; exit 1; }
# The same run with other inputs: planned at what it recorded, its wall time on one core.
study ", prepare: {output.interval: 1000}"
read -r plan basis < <(planned)
echo "re-planned: $plan particle-steps ($basis), recorded $steps steps in $wall s"
[ "$basis" = recorded ] || { echo "plan: basis '$basis', expected recorded"; cat "$work/plan.txt"; exit 1; }
awk -v p="$plan" -v s="$steps" 'BEGIN { exit (p != sprintf("%.3g", s * 1000)) }' ||
  { echo "plan: $plan particle-steps, recorded $((steps * 1000))"; exit 1; }
one_core=$(grep -o 'estimated wall time[^;]*1 core [0-9.]* [a-z]*' "$work/plan.txt" | awk '{ print $(NF-1), $NF }')
awk -v t="$one_core" -v w="$wall" 'BEGIN { split(t, a, " "); s = a[2] == "min" ? 60 * a[1] : a[1]
  exit (s - w > 0.05 * w + 0.5 || w - s > 0.05 * w + 0.5) }' || { echo "one core: $one_core, recorded wall $wall s"; exit 1; }
grep -q "throughput: the finished runs' recorded" "$work/plan.txt" || { echo "plan: throughput not from the record"; exit 1; }
echo "plan vs run: ok"
