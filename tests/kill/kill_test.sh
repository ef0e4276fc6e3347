#!/bin/bash
# Kill test: kill -9 a run KILLS times at random moments, resume it each time, and
# compare the result with an uninterrupted run of the same scene: the time series, the legs, the
# final state and the particle frames must be identical bit for bit (h5diff without tolerance).
#
#   tests/kill/kill_test.sh DEM KILLS WORKDIR [SEED]
#
# The scene (tests/kill/scene.yaml) checkpoints every 5,000 steps; each life is killed at a random
# moment after its first checkpoint, so kills land in both kinds of stage loop. `make test` runs
# 3 kills, `make kill-test` 20.
set -u
dem=$1 kills=$2 work=$3 seed=${4:-1}
scene=$(dirname "$0")/scene.yaml
RANDOM=$seed
rm -rf "$work" && mkdir -p "$work" || exit 1
"$dem" run "$scene" --out "$work/reference.h5" --no-resume --quiet 2> "$work/reference.log" ||
  { echo "kill test: the uninterrupted run failed:"; cat "$work/reference.log"; exit 1; }

checkpoint_step() { h5dump -a /checkpoint/step "$work/killed.h5.checkpoint" 2> /dev/null | awk '/\(0\)/ {print $2}'; }
done_kills=0 lives=0 last=0
while [ "$done_kills" -lt "$kills" ]; do
  "$dem" run "$scene" --out "$work/killed.h5" --quiet 2>> "$work/killed.log" &
  pid=$!
  lives=$((lives + 1))
  # Each life is killed a random 0 ... 0.3 s after it has written a checkpoint of its own, so
  # that every life makes progress however loaded the machine is, and the kill lands anywhere:
  # in a step, a row, the next checkpoint's write or the final rename.
  # (No checkpoint file yet reads as no step: a life starved of CPU beside other work waits too.)
  new_checkpoint() { local step; step=$(checkpoint_step); [ -n "$step" ] && [ "$step" != "$last" ]; }
  while kill -0 "$pid" 2> /dev/null && ! new_checkpoint; do sleep 0.02; done
  sleep "0.$((RANDOM % 4))$((RANDOM % 10))"
  if kill -9 "$pid" 2> /dev/null; then
    wait "$pid" 2> /dev/null
    done_kills=$((done_kills + 1))
    last=$(checkpoint_step)
    echo "kill $done_kills: checkpoint at step ${last:-none}"
  else  # it finished before the kill: start again from nothing for the kills still to do
    wait "$pid"
    echo "life $lives finished before its kill; starting over"
    rm -f "$work"/killed.*
    last=0
  fi
done
"$dem" run "$scene" --out "$work/killed.h5" --quiet 2>> "$work/killed.log" ||
  { echo "kill test: the last life failed:"; cat "$work/killed.log"; exit 1; }
resumes=$(grep -c resuming "$work/killed.log")
echo "$resumes resumes from a checkpoint in $lives lives plus the last"

status=0
[ "$resumes" -ge "$kills" ] || { echo "kill test: only $resumes resumes for $kills kills"; status=1; }
for group in /timeseries /legs /state /particles; do
  if ! h5diff -r "$work/reference.h5" "$work/killed.h5" "$group" > "$work/diff${group//\//_}.txt" 2>&1; then
    echo "kill test: $group differs from the uninterrupted run:"; head -20 "$work/diff${group//\//_}.txt"; status=1
  fi
done
[ "$status" = 0 ] && echo "kill test: $kills kills, /timeseries /legs /state /particles identical bit for bit"
exit $status
