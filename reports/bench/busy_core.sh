#!/usr/bin/env bash
# busy_core.sh: threads beside other work, `make bench`'s last table (run_bench.sh appends it to
# bench.md), or on its own. Times whole `dem run`s of Test 1 (scenes/tests/test1.yaml, the shipped
# 1,000-sphere sample) on 1 and 2 threads, on the machine as it is and beside a busy core (a shell
# loop at the same priority, started and ended by this script), the four ways interleaved
# repetition by repetition; prints a Markdown table of the median wall times.
#
#   reports/bench/busy_core.sh BUILD_DIR [REPS] [PATH]
#
# PATH cuts Test 1's stress path (a `--set 'stages[0].path=PATH'`, e.g. '[TC1, TC2, TC3, TC1]': its
# first cycle); default the whole test. A run on 2 threads tries 1 thread now and then and keeps
# whichever steps faster (engine/run/thread_choice.hpp); the table gives the share of its steps
# it made on 1 thread (the last line `dem run` prints).
set -euo pipefail
build=${1:?usage: busy_core.sh BUILD_DIR [REPS] [PATH]}
reps=${2:-3}
path=${3:-}
work=$(mktemp -d)
busy=""
cleanup() {
  [ -z "$busy" ] || kill "$busy" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT  # the loop is never left behind, however the script ends
sets=()
[ -z "$path" ] || sets=(--set "stages[0].path=$path")

one_run() {  # one_run THREADS WAY: appends "WAY SECONDS SHARE_ON_1" to $work/times
  rm -f "$work"/run.h5*
  local start end line share
  start=$(date +%s.%N)
  "$build/bin/dem" run scenes/tests/test1.yaml --out "$work/run.h5" --threads "$1" --no-resume --quiet "${sets[@]}" \
    2>"$work/log" || { cat "$work/log" >&2; echo "busy_core: dem run --threads $1 failed" >&2; exit 1; }
  end=$(date +%s.%N)
  line=$(tail -n 1 "$work/log")
  share=$(sed -n 's/.* \([0-9]*\) % of the steps on 1 thread.*/\1/p' <<<"$line")
  [ "$1" = 1 ] && share=100
  echo "$2 $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }') ${share:--}" >>"$work/times"
}

load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
for ((r = 0; r < reps; r++)); do
  one_run 1 idle1
  one_run 2 idle2
  sh -c 'while :; do :; done' &
  busy=$!
  one_run 1 busy1
  one_run 2 busy2
  kill "$busy"
  wait "$busy" 2>/dev/null || true
  busy=""
done

median() { awk -v w="$1" '$1 == w { print $2 }' "$work/times" | sort -g | awk '{ v[NR] = $1 } END { printf "%.2f", v[int((NR + 1) / 2)] }'; }
spread() { awk -v w="$1" '$1 == w { print $2 }' "$work/times" | sort -g | awk '{ v[NR] = $1 } END { printf "%.2f-%.2f", v[1], v[NR] }'; }
shares() { awk -v w="$1" '$1 == w { printf "%s%s", (n++ ? ", " : ""), $3 }' "$work/times"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b / a }'; }
i1=$(median idle1) i2=$(median idle2) b1=$(median busy1) b2=$(median busy2)
echo
echo "### Threads beside other work"
echo
echo "| machine | 1 thread (s) | 2 threads (s) | 2 threads / 1 thread (time) | 2-thread runs: % of steps on 1 thread |"
echo "|---|---|---|---|---|"
echo "| as it is | $i1 ($(spread idle1)) | $i2 ($(spread idle2)) | $(ratio "$i1" "$i2") | $(shares idle2) |"
echo "| beside a busy core | $b1 ($(spread busy1)) | $b2 ($(spread busy2)) | $(ratio "$b1" "$b2") | $(shares busy2) |"
echo
echo "Wall time of \`dem run scenes/tests/test1.yaml\`${path:+ cut to the path $path} (1,000 spheres), median (min-max) of"
echo "$reps repetition$([ "$reps" = 1 ] || echo s), the four ways interleaved; \"beside a busy core\": with a shell loop at the same priority."
echo "Load average (1, 5, 15 min) at the start: $load_start; at the end: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)."
