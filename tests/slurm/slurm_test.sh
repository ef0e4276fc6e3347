#!/bin/bash
# SLURM test: the tiny study tests/slurm/study.yaml through a real one-node SLURM
# (tests/slurm/start_cluster.sh; stopped again at the end), checked against the local executor:
#  1. the local executor's results, the reference;
#  2. the SLURM executor with loose_prepare's job cancelled (scancel) after its first checkpoint:
#     the pipeline reports it FAILED and blocks (and cancels) only loose_test1; the dense runs finish;
#  3. a second SLURM pipeline submits the two again; loose_prepare resumes from its checkpoint;
#  4. a SLURM pipeline killed with -9 right after submitting: the next one adopts its jobs, submits
#     nothing twice and finishes;
#  5. a SLURM pipeline sent SIGINT (Ctrl-C) mid-run: it cancels its jobs and exits 130;
#  6. a job requeued mid-run (scontrol requeue): the pipeline follows it and it resumes;
#  then every result of 3, 4 and 6 equals the reference bit for bit (h5diff of /timeseries /legs
#  /state /particles).
#
#   tests/slurm/slurm_test.sh BUILD_BIN WORKDIR
set -u
bin=$(cd "$1" && pwd) work=$2
here=$(cd "$(dirname "$0")" && pwd)
study=$here/study.yaml
state=${DEM_SLURM_STATE:-/tmp/dem-slurm-test.$$}
export OMP_NUM_THREADS=1
rm -rf "$work" && mkdir -p "$work" || exit 1
start=$(date +%s.%N)
status=0
fail() { echo "slurm test: $*"; status=1; }
run=("$bin/pipeline" "$study" --profile quick --dem "$bin/dem")  # "${run[@]} ... &": $! is the pipeline itself
elapsed() { awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f s", b - a}'; }

"$here/start_cluster.sh" "$state"
rc=$?
[ "$rc" = 77 ] && { echo "slurm test: skipped, SLURM cannot be installed here"; exit 77; }
[ "$rc" = 0 ] || { echo "slurm test: the cluster did not start"; "$here/stop_cluster.sh" "$state"; exit 1; }
trap '"$here/stop_cluster.sh" "$state" > /dev/null' EXIT
. "$state/env"
echo "cluster up after $(elapsed)"

# 1. the reference
"${run[@]}" --executor local -j 2 --out "$work/local" > "$work/local.log" 2>&1 ||
  { echo "slurm test: the local study failed:"; tail -20 "$work/local.log"; exit 1; }
echo "1. local executor: $(grep -c '^\[pipeline.*finished' "$work/local.log") runs, after $(elapsed)"

# 2. a job cancelled mid-run
out=$work/slurm
"${run[@]}" --out "$out" > "$work/slurm-1.log" 2>&1 &
pid=$!
while kill -0 "$pid" 2> /dev/null && [ ! -f "$out/loose_prepare.h5.checkpoint" ]; do sleep 0.05; done
job=$(awk -F'"' '/job_id/ {print $2}' "$out/loose_prepare.h5.job" 2> /dev/null)
[ -n "$job" ] && scancel "$job"
wait "$pid"
rc=$?
[ "$rc" = 1 ] || fail "the pipeline whose job was cancelled exited $rc, not 1"
grep -q "FAILED loose_prepare (job $job CANCELLED" "$work/slurm-1.log" || fail "no 'FAILED loose_prepare (job $job CANCELLED' in $work/slurm-1.log"
grep -q "loose_test1 blocked" "$work/slurm-1.log" || fail "loose_test1 was not blocked"
[ -f "$out/dense_test1.h5" ] || fail "dense_test1 did not finish beside the failure"
[ -f "$out/loose_prepare.h5.checkpoint" ] || fail "the cancelled run left no checkpoint"
echo "2. job $job (loose_prepare) cancelled at its checkpoint step" \
  "$(h5dump -a /checkpoint/step "$out/loose_prepare.h5.checkpoint" 2> /dev/null | awk '/\(0\)/ {print $2}'):" \
  "pipeline exited $rc, loose_test1 blocked, after $(elapsed)"

# 3. started again: the cancelled run resumes from its checkpoint
"${run[@]}" --out "$out" > "$work/slurm-2.log" 2>&1 || fail "the second SLURM pipeline failed: $(tail -5 "$work/slurm-2.log")"
grep -q "2 to run" "$work/slurm-2.log" || fail "the second pipeline did not reuse the two dense results"
grep -q resuming "$out/logs/loose_prepare.log" || fail "loose_prepare did not resume from its checkpoint"
echo "3. started again: $(grep -c 'submitted .* as job' "$work/slurm-2.log") jobs submitted, loose_prepare" \
  "$(grep -o 'resuming.*' "$out/logs/loose_prepare.log" | head -1), after $(elapsed)"

# 4. a pipeline killed -9 with its jobs in the queue: the next one adopts them
adopt=$work/adopt
"${run[@]}" --out "$adopt" > "$work/adopt-1.log" 2>&1 &
pid=$!
while kill -0 "$pid" 2> /dev/null && [ "$(ls "$adopt"/*.h5.job 2> /dev/null | wc -l)" -lt 4 ]; do sleep 0.02; done
kill -9 "$pid" 2> /dev/null
wait "$pid" 2> /dev/null
queued=$(squeue --noheader --format=%i | wc -l)
"${run[@]}" --out "$adopt" > "$work/adopt-2.log" 2>&1 || fail "the adopting pipeline failed: $(tail -5 "$work/adopt-2.log")"
adopted=$(grep -c 'adopted job' "$work/adopt-2.log")
submitted=$(grep -c 'submitted .* as job' "$work/adopt-2.log")
[ "$queued" -ge 1 ] && [ "$adopted" -ge 1 ] || fail "nothing adopted ($queued jobs were in the queue)"
[ $((adopted + submitted)) -le 4 ] || fail "$adopted adopted and $submitted submitted: some run twice"
echo "4. pipeline killed -9 with $queued jobs in the queue: the next adopted $adopted, submitted $submitted, after $(elapsed)"

# 5. Ctrl-C: the pipeline cancels its jobs
stop=$work/interrupted
"${run[@]}" --out "$stop" > "$work/interrupted.log" 2>&1 &
pid=$!
while kill -0 "$pid" 2> /dev/null && [ ! -f "$stop/loose_prepare.h5.checkpoint" ]; do sleep 0.05; done
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" = 130 ] || fail "the interrupted pipeline exited $rc, not 130"
left=$(squeue --noheader --format=%T | grep -cvE 'COMPLETED|CANCELLED|FAILED')
[ "$left" = 0 ] || fail "$left jobs still in the queue after Ctrl-C"
grep -q "cancelling" "$work/interrupted.log" || fail "no cancelling message"
ls "$stop"/*.job > /dev/null 2>&1 && fail "job records left behind after Ctrl-C"
echo "5. Ctrl-C: pipeline exited $rc, $(grep -o 'cancelling [0-9]* jobs\?' "$work/interrupted.log"), $left left in the queue, after $(elapsed)"

# 6. a job requeued mid-run (as after a node failure or preemption): it starts again and resumes
requeue=$work/requeued
"${run[@]}" --out "$requeue" > "$work/requeued.log" 2>&1 &
pid=$!
# Requeued once the pipeline has seen it running and it has written a checkpoint.
while kill -0 "$pid" 2> /dev/null &&
  ! { grep -q "running loose_prepare" "$work/requeued.log" && [ -f "$requeue/loose_prepare.h5.checkpoint" ]; }; do
  sleep 0.05
done
job=$(awk -F'"' '/job_id/ {print $2}' "$requeue/loose_prepare.h5.job" 2> /dev/null)
[ -n "$job" ] && scontrol requeue "$job"
# SLURM holds a requeued job 2 min before it may start again; the test lets it start at once, which
# it can once the job is back to PENDING (reason BeginTime).
for _ in $(seq 200); do
  [ "$(squeue --noheader --jobs="$job" --format='%T %r' 2> /dev/null)" = "PENDING BeginTime" ] &&
    { scontrol update JobId="$job" StartTime=now; break; }
  sleep 0.05
done
wait "$pid" || fail "the pipeline whose job was requeued failed: $(tail -5 "$work/requeued.log")"
grep -q "requeued loose_prepare (job $job" "$work/requeued.log" || fail "the requeue of job $job was not reported"
grep -q resuming "$requeue/logs/loose_prepare.log" || fail "the requeued loose_prepare did not resume from its checkpoint"
echo "6. job $job (loose_prepare) requeued: $(grep -o 'resuming.*step [0-9]*' "$requeue/logs/loose_prepare.log" | sed 's/from .* at/at/'), after $(elapsed)"

# bit for bit
compared=0
for ref in "$work"/local/*.h5; do
  name=$(basename "$ref")
  for dir in "$out" "$adopt" "$requeue"; do
    for group in /timeseries /legs /state /particles; do
      h5diff -r "$ref" "$dir/$name" "$group" > "$work/diff.txt" 2>&1 ||
        { fail "$dir/$name $group differs from the local executor's:"; head -5 "$work/diff.txt"; }
    done
    compared=$((compared + 1))
  done
done
[ "$compared" = 12 ] || fail "compared $compared results, not 12"
[ "$status" = 0 ] && echo "slurm test: passed in $(elapsed): $compared results identical bit for bit to the local executor's"
exit $status
