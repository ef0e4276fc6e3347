#!/usr/bin/env bash
# The shipped samples (scenes/samples/{loose,medium,dense}_1k.h5, made by `make example-samples`)
# are what this engine and the preparation scenes make: each preparation is run again at 1,000
# spheres (about 7 s each) and its final state (/state: positions, velocities, contacts, cell)
# must equal the shipped one bit for bit (h5diff). A change to the engine's results or to a
# preparation scene makes this fail until `make example-samples` is run and the samples committed.
#   tests/examples/samples_test.sh BIN_DIR SOURCE_DIR WORKDIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail=0
for d in loose medium dense; do
  shipped=$src/scenes/samples/${d}_1k.h5
  [ -f "$shipped" ] || { echo "FAIL: $shipped is missing (make example-samples)"; fail=1; continue; }
  # The same command as the make target.
  "$bin/dem" run "$src/scenes/prepare_$d.yaml" --set 'particles.lattice.n=[10, 10, 10]' --out "$work/${d}_1k.h5" \
    --threads 1 --no-resume --quiet 2> "$work/$d.log" || { echo "FAIL: the $d preparation failed:"; cat "$work/$d.log"; fail=1; continue; }
  if h5diff -r "$shipped" "$work/${d}_1k.h5" /state > "$work/$d.diff" 2>&1; then
    echo "$d: the shipped sample is current ($(du -k "$shipped" | cut -f1) KB)"
  else
    echo "FAIL: $shipped is stale: its /state differs from a fresh preparation (make example-samples; $work/$d.diff)"
    fail=1
  fi
done
exit $fail
