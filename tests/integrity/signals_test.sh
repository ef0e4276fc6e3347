#!/usr/bin/env bash
# How `dem run` ends when the system stops it, with every signal at its default disposition in the
# caller (as a user's shell has them; `env --default-signal` makes sure of it):
#  * a file size limit (ulimit -f) below the result's size: SIGXFSZ would kill dem silently (exit
#    153). dem must end as on a full disk: exit 1, "File too large" on stderr, RESULT.h5.partial
#    kept with status "failed: ..." (or, when the file is too full to take it, stderr saying so),
#    no RESULT.h5, no .lock left;
#  * SIGTERM and SIGINT in the middle of a run: dem ends by that signal (exit 128 + its number, as
#    without a handler), the .partial's status says "failed: interrupted by SIGTERM" (SIGINT), and
#    the .lock is gone;
#  * SIGTERM and SIGINT while the run waits for a particle CSV that is a FIFO without a writer: the
#    same, the .lock gone and no .partial;
#  * a run of 1e12 steps says, after 10 s, how many days it needs;
#  * a .partial read while its run goes on is said to be being written, not corrupt.
# A control first shows that the limit kills a program that does not handle SIGXFSZ (exit 153), so
# that the test cannot pass because the signal happened to be ignored.
#   tests/integrity/signals_test.sh build/bin/dem [WORK]
set -u
dem=$(readlink -f "$1")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=${2:-$(mktemp -d)}
rm -rf "$work"
mkdir -p "$work"
export OMP_NUM_THREADS=1
scene=$here/scenes/stability/base.yaml
small=(--set 'particles.lattice.n=[4,4,4]')
fail=0
check() {  # check WHAT CONDITION...: records a failure with WHAT when the condition fails
  local what=$1
  shift
  if ! "$@"; then echo "FAIL: $what"; fail=1; fi
}
status_of() { h5dump -a status "$1" 2> /dev/null | sed -n 's/.*(0): "\(.*\)".*/\1/p'; }
at_default=(env --default-signal=XFSZ,TERM,INT)  # exec'd: $! of a background run is dem's own PID

# The reference: the size of the whole result.
"$dem" run "$scene" "${small[@]}" --out "$work/reference.h5" --quiet 2> /dev/null || { echo "FAIL: the reference run failed"; exit 1; }
kib=$(( $(stat -c %s "$work/reference.h5") / 1024 ))
limit=$(( kib / 2 ))  # ulimit -f counts 1024-byte blocks in bash

# Control: SIGXFSZ at its default kills a writer past the limit.
(ulimit -f "$limit"; "${at_default[@]}" head -c $(( 2 * limit * 1024 )) /dev/zero > "$work/control.bin") 2> /dev/null
rc=$?
check "the control writer past ulimit -f $limit should die by SIGXFSZ (153), exit $rc" test "$rc" = 153

# dem under the same limit.
(ulimit -f "$limit"; "${at_default[@]}" "$dem" run "$scene" "${small[@]}" --out "$work/limited.h5" --quiet) 2> "$work/limited.err"
rc=$?
echo "ulimit -f $limit (result $kib KiB): exit $rc; $(head -1 "$work/limited.err")"
check "ulimit -f: exit 1 expected, got $rc" test "$rc" = 1
check "ulimit -f: no reason on stderr: $(cat "$work/limited.err")" grep -q "^error: .*File too large" "$work/limited.err"
check "ulimit -f: stderr does not name the kept partial" grep -q "partial result kept in $work/limited.h5.partial" "$work/limited.err"
check "ulimit -f: RESULT.h5 exists" test ! -e "$work/limited.h5"
check "ulimit -f: .lock left" test ! -e "$work/limited.h5.lock"
# The partial result says why, when HDF5 can still write into it; at the limit it often cannot (the
# file cannot grow by the attribute), and then dem says so instead.
st=$(status_of "$work/limited.h5.partial")
if [ "${st#failed: }" = "$st" ]; then
  check "ulimit -f: .partial status '$st', and stderr does not say it could not be set" \
    grep -q "limited.h5.partial; its status could not be set to the reason above" "$work/limited.err"
fi

# SIGTERM and SIGINT mid-run (a run of several seconds; the signal once the partial result exists).
for sig in TERM INT; do
  out=$work/$sig.h5
  "${at_default[@]}" "$dem" run "$scene" --set stages[1].path=[TC1,A,TC1,A,TC1,A,TC1,A] --out "$out" --quiet 2> "$work/$sig.err" &
  pid=$!
  for _ in $(seq 200); do [ -e "$out.partial" ] && break; sleep 0.05; done
  sleep 0.5
  # While it runs, its partial result is being written, not corrupt (its .lock is held).
  if [ "$sig" = TERM ]; then
    "$dem" table "$out.partial" step > /dev/null 2> "$work/live.err"
    check "a live .partial: $(cat "$work/live.err")" \
      grep -q "$out.partial: being written by a running dem run (it holds $out.lock); read it when the run has ended" "$work/live.err"
  fi
  kill -"$sig" "$pid"
  wait "$pid"
  rc=$?
  want=$(( 128 + $(kill -l "$sig") ))
  echo "SIG$sig: exit $rc; $(head -1 "$work/$sig.err")"
  check "SIG$sig: exit $want expected, got $rc" test "$rc" = "$want"
  check "SIG$sig: .lock left" test ! -e "$out.lock"
  st=$(status_of "$out.partial")
  check "SIG$sig: .partial status '$st'" test "${st#failed: interrupted by SIG$sig}" != "$st"
  check "SIG$sig: stderr: $(cat "$work/$sig.err")" grep -q "^error: .*interrupted by SIG$sig" "$work/$sig.err"
done
# A particle CSV that is a FIFO no writer ever opens: dem waits for its bytes without blocking in
# open() (where, restarted after each signal by the handlers' SA_RESTART, only SIGKILL ended it and
# the .lock stayed), so SIGTERM and SIGINT end the run by that signal, saying what it waited for,
# with no .lock and no .partial left. A run still there 5 s after the signal is killed and fails.
mkfifo "$work/no_writer.csv"
printf '%s\n' "name: fifo" "particles: {csv: no_writer.csv, cell: [0.02, 0.02, 0.02]}" \
  "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}" "numerics: {time_step: 1.0e-6}" \
  "stages: [{name: squeeze, type: strain_rate, strain_rate: [1.0, 1.0, 1.0], duration: 5.0e-4}]" > "$work/fifo.yaml"
for sig in TERM INT; do
  out=$work/fifo_$sig.h5
  "${at_default[@]}" "$dem" run "$work/fifo.yaml" --out "$out" --quiet 2> "$work/fifo_$sig.err" &
  pid=$!
  for _ in $(seq 200); do [ -e "$out.lock" ] && break; sleep 0.05; done  # taken before the CSV is opened
  sleep 1
  kill -"$sig" "$pid"
  for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  hung=0
  if kill -0 "$pid" 2> /dev/null; then hung=1; kill -KILL "$pid"; fi
  wait "$pid"
  rc=$?
  want=$(( 128 + $(kill -l "$sig") ))
  echo "FIFO without a writer, SIG$sig: exit $rc; $(head -1 "$work/fifo_$sig.err")"
  check "FIFO, SIG$sig: still running 5 s after the signal (killed)" test "$hung" = 0
  check "FIFO, SIG$sig: exit $want expected, got $rc" test "$rc" = "$want"
  check "FIFO, SIG$sig: .lock left" test ! -e "$out.lock"
  check "FIFO, SIG$sig: .partial left" test ! -e "$out.partial"
  check "FIFO, SIG$sig: stderr: $(cat "$work/fifo_$sig.err")" \
    grep -q "^error: .*interrupted by SIG$sig while waiting for the bytes of particles.csv $work/no_writer.csv" "$work/fifo_$sig.err"
done
# A run of 1e12 steps (a 1e6 s stage at dt = 1e-6 s, the most a run may take) is accepted, but says
# how long it will take:
# a warning once its stage has run 10 s (here the 8 spheres of tests/data/csv_scene, at rest).
out=$work/long.h5
"$dem" run "$here/tests/data/csv_scene/scene.yaml" --set stages[0].duration=1e6 --set 'stages[0].strain_rate=[0,0,0]' --set output.interval=1000000 \
  --out "$out" --quiet 2> "$work/long.err" &
pid=$!
for _ in $(seq 600); do grep -q "needs about" "$work/long.err" && break; kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
kill -TERM "$pid"
wait "$pid"
echo "1e12 steps: $(grep warning "$work/long.err")"
check "1e12 steps: no estimate: $(cat "$work/long.err")" \
  grep -q "^warning: stage 1/1 'squeeze': at its speed so far (.* % of it in 1[0-9] s) it needs about .* days more" "$work/long.err"
[ "$fail" = 0 ] && echo "signals_test: passed"
exit $fail
