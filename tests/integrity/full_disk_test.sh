#!/usr/bin/env bash
# A real full disk: `dem run` of 64 spheres into a 200 KiB tmpfs, and with checkpoints
# into tmpfs of several sizes, so that the disk fills up in rows, in frames, in a checkpoint and
# at the final flush and close. Every run must end with exit 0 and a complete result, or with
# exit 1, the reason ("No space left on device") on stderr, no RESULT.h5, its
# .partial kept, a checkpoint that is whole or absent and no .checkpoint.tmp; never a crash (it
# was a segfault, exit 139, after RESULT.h5 had been renamed into place with status "running").
#
# Needs root (mount); exits 77 (skipped: ctest SKIP_RETURN_CODE) when it cannot mount a tmpfs.
# The same checks without root, with a file size limit, are in tests/engine/run/cli_test.cpp.
#   tests/integrity/full_disk_test.sh build/bin/dem [WORK]
set -u
dem=$(readlink -f "$1")
here=$(cd "$(dirname "$0")/../.." && pwd)
work=${2:-$(mktemp -d)}
mkdir -p "$work"
mnt=$work/tmpfs
mkdir -p "$mnt"
[ "$(id -u)" = 0 ] || { echo "full_disk_test: not root, skipped"; exit 77; }
mount -t tmpfs -o size=200k tmpfs "$mnt" 2>/dev/null || { echo "full_disk_test: cannot mount a tmpfs, skipped"; exit 77; }
umount "$mnt"
trap 'umount "$mnt" 2>/dev/null' EXIT
export OMP_NUM_THREADS=1

scene=$here/scenes/stability/base.yaml
fail=0
ok=0
failed=0
# The reference, on a disk with room: every complete run must match its time series. (Made anew:
# one left by an earlier engine or scene is not this run's, and dem would refuse to replace it.)
rm -f "$work"/reference.*
"$dem" run "$scene" --set 'particles.lattice.n=[4,4,4]' --out "$work/reference.h5" --quiet 2>/dev/null ||
  { echo "FAIL: the reference run failed"; exit 1; }
"$dem" table "$work/reference.h5" step p > "$work/reference.txt"

for case in "200 -" "120 -" "400 -" "540 -" "600 -" "400 5000" "900 5000" "1100 5000" "1500 5000" "3000 5000"; do
  set -- $case
  size=$1 interval=$2
  mount -t tmpfs -o size=${size}k tmpfs "$mnt" || { echo "FAIL: mount"; exit 1; }
  args=(run "$scene" --set 'particles.lattice.n=[4,4,4]' --out "$mnt/r.h5" --quiet)
  [ "$interval" = - ] || args+=(--set "output.checkpoint_interval=$interval")
  "$dem" "${args[@]}" 2> "$work/err.txt"
  rc=$?
  what="tmpfs ${size}k, checkpoint_interval $interval: exit $rc"
  case $rc in
    0)
      ok=$((ok + 1))
      [ -f "$mnt/r.h5" ] && [ ! -e "$mnt/r.h5.partial" ] || { echo "FAIL: $what, but no complete result"; fail=1; }
      "$dem" table "$mnt/r.h5" step p | cmp -s - "$work/reference.txt" || { echo "FAIL: $what, time series differ"; fail=1; }
      ;;
    1)
      failed=$((failed + 1))
      [ ! -e "$mnt/r.h5" ] || { echo "FAIL: $what, yet r.h5 exists"; fail=1; }
      [ -f "$mnt/r.h5.partial" ] || { echo "FAIL: $what, no r.h5.partial kept"; fail=1; }
      [ ! -e "$mnt/r.h5.checkpoint.tmp" ] || { echo "FAIL: $what, r.h5.checkpoint.tmp left"; fail=1; }
      grep -q "^error: " "$work/err.txt" && grep -q "partial result kept in $mnt/r.h5.partial" "$work/err.txt" ||
        { echo "FAIL: $what, stderr: $(cat "$work/err.txt")"; fail=1; }
      grep -q "No space left on device" "$work/err.txt" ||
        { echo "FAIL: $what, no reason on stderr: $(cat "$work/err.txt")"; fail=1; }
      if [ -e "$mnt/r.h5.checkpoint" ]; then
        h5dump -a checkpoint/identity "$mnt/r.h5.checkpoint" > /dev/null 2>&1 ||
          { echo "FAIL: $what, a damaged checkpoint"; fail=1; }
      fi
      ;;
    *)
      echo "FAIL: $what (a crash?): $(cat "$work/err.txt")"; fail=1 ;;
  esac
  echo "$what; $(head -1 "$work/err.txt")"
  umount "$mnt"
done
[ "$failed" -ge 5 ] || { echo "FAIL: only $failed runs hit the full disk"; fail=1; }
[ "$ok" -ge 1 ] || { echo "FAIL: no run had room enough"; fail=1; }
[ "$fail" = 0 ] && echo "full_disk_test: passed ($failed full, $ok complete)"
exit $fail
