#!/bin/bash
# A run killed under the pipeline: kill -9 one `dem run` of a small study (tests/kill/study.yaml)
# once it has written a checkpoint, the pipeline left running. SIGKILL gives dem no chance to say
# anything, so the pipeline must: its line says "FAILED <run> (killed by signal 9 (KILL)", the
# run's .partial no longer says "running" but how it ended, and the study started again resumes the
# run from its checkpoint and finishes.
#
#   tests/kill/run_killed_test.sh BUILD_BIN WORKDIR
set -u
bin=$1 work=$2
study=$(dirname "$0")/study.yaml
rm -rf "$work" && mkdir -p "$work" || exit 1
"$bin/pipeline" "$study" --profile quick --out "$work/study" -j 1 --dem "$bin/dem" > "$work/first.log" 2>&1 &
pipeline=$!
victim=""
for _ in $(seq 1200); do  # at most 60 s for the first checkpoint
  if [ -n "$(find "$work/study" -name '*.checkpoint' 2> /dev/null)" ]; then victim=$(pgrep -P "$pipeline" -f "dem run" | head -1); break; fi
  sleep 0.05
done
[ -n "$victim" ] || { echo "run killed test: no run wrote a checkpoint, or none was found running"; kill "$pipeline"; exit 1; }
out=$(tr '\0' '\n' < "/proc/$victim/cmdline" | sed -n '/^--out$/{n;p}')
kill -9 "$victim"
wait "$pipeline"
rc=$?
status=0
[ "$rc" != 0 ] || { echo "run killed test: the pipeline exited 0 with a run killed"; status=1; }
name=$(basename "$out" .h5)
grep -q "FAILED .*$name (killed by signal 9 (KILL); see" "$work/first.log" ||
  { echo "run killed test: no FAILED line naming the signal for $name:"; tail -5 "$work/first.log"; status=1; }
said=$(h5dump -a status "$out.partial" 2> /dev/null | sed -n 's/^ *(0): "\(.*\)"$/\1/p')
[ "$said" = 'failed: killed by signal 9 (KILL) (seen by the pipeline)' ] ||
  { echo "run killed test: the partial result's status is $said"; status=1; }
"$bin/pipeline" "$study" --profile quick --out "$work/study" -j 1 --dem "$bin/dem" > "$work/again.log" 2>&1 ||
  { echo "run killed test: the study started again failed:"; tail -5 "$work/again.log"; status=1; }
[ -f "$out" ] || { echo "run killed test: $out not finished after the second start"; status=1; }
grep -q resuming "$work/study/logs/$name.log" ||
  { echo "run killed test: the killed run did not resume from its checkpoint"; status=1; }
[ "$status" = 0 ] && echo "run killed test: $name killed; the pipeline said so ('$said') and the study finished on its second start"
exit $status
