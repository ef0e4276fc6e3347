#!/bin/bash
# Study kill test: kill -9 the pipeline KILLS times at random moments while it runs a
# small study (tests/kill/study.yaml: a quick 34,500-step preparation and two tests), start it again each time, and compare every result with
# those of an uninterrupted pipeline: /timeseries, /legs, /state and /particles identical bit for
# bit. A killed pipeline takes its `dem run`s with it; started again, it reuses the finished
# results and each unfinished run resumes from its checkpoint.
#
#   tests/kill/study_kill_test.sh BUILD_BIN KILLS WORKDIR [SEED]
set -u
bin=$1 kills=$2 work=$3 seed=${4:-1}
study=$(dirname "$0")/study.yaml
RANDOM=$seed
rm -rf "$work" && mkdir -p "$work" || exit 1
"$bin/pipeline" "$study" --profile quick --out "$work/reference" -j 2 --dem "$bin/dem" > "$work/reference.log" 2>&1 ||
  { echo "study kill test: the uninterrupted study failed:"; tail -20 "$work/reference.log"; exit 1; }

mkdir -p "$work/killed"
for k in $(seq "$kills"); do
  touch "$work/life-start"
  "$bin/pipeline" "$study" --profile quick --out "$work/killed" -j 2 --dem "$bin/dem" >> "$work/killed.log" 2>&1 &
  pid=$!
  # Killed a random 0 ... 5 s after one of its runs wrote a checkpoint in this life, so that every
  # life makes progress however loaded the machine is.
  while kill -0 "$pid" 2> /dev/null && [ -z "$(find "$work/killed" -name '*.checkpoint' -newer "$work/life-start")" ]; do
    sleep 0.05
  done
  sleep "$((RANDOM % 5)).$((RANDOM % 10))"
  kill -9 "$pid" 2> /dev/null
  wait "$pid" 2> /dev/null
  sleep 0.2  # the runs die with the pipeline (PR_SET_PDEATHSIG)
  echo "kill $k: $(ls "$work/killed" | grep -c '\.h5$') results complete, $(ls "$work/killed" | grep -c '\.checkpoint$') checkpoints"
done
"$bin/pipeline" "$study" --profile quick --out "$work/killed" -j 2 --dem "$bin/dem" >> "$work/killed.log" 2>&1 ||
  { echo "study kill test: the last start failed:"; tail -20 "$work/killed.log"; exit 1; }
echo "$(grep -l resuming "$work"/killed/logs/*.log | wc -l) of $(ls "$work"/killed/logs/*.log | wc -l) runs resumed from a checkpoint in their last life"

status=0 compared=0
for ref in "$work"/reference/*.h5; do
  name=$(basename "$ref")
  for group in /timeseries /legs /state /particles; do
    if ! h5diff -r "$ref" "$work/killed/$name" "$group" > "$work/diff.txt" 2>&1; then
      echo "study kill test: $name $group differs from the uninterrupted study:"; head -10 "$work/diff.txt"; status=1
    fi
  done
  compared=$((compared + 1))
done
[ "$compared" -ge 3 ] || { echo "study kill test: only $compared results to compare"; status=1; }
[ "$status" = 0 ] && echo "study kill test: $kills kills, $compared results identical bit for bit"
exit $status
