#!/usr/bin/env bash
# A result read by a real client: h5py (Debian's python3-h5py, installed here if missing; the test
# is skipped with exit 77 if it cannot be) reads a short run's result and checks it against
# `dem table` and `dem state` (tests/clients/h5py_client.py); pandas reads `dem table --csv` and the
# docs/results.md one-liners run (tests/clients/pandas_client.py).
#   tests/clients/h5py_test.sh BIN_DIR WORKDIR
set -u
bin=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" || exit 1
# Debian's h5py is for Debian's python3 (another python3 may come first on the PATH).
py=/usr/bin/python3
[ -x "$py" ] || py=$(command -v python3) || { echo "h5py test: no python3: skipped"; exit 77; }
sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo -n"
if ! "$py" -c 'import h5py' 2> /dev/null; then
  { $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-h5py ||
    { $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq &&
      $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-h5py; }; } > "$work/apt.log" 2>&1
  "$py" -c 'import h5py' 2> /dev/null || { echo "h5py test: python3-h5py cannot be installed here (see $work/apt.log): skipped"; exit 77; }
fi
# 27 spheres: a fast compression to 100 kPa, then A -> TC1 -> A (rows, legs and particle frames).
"$bin/dem" run "$here/../../scenes/stability/base.yaml" --out "$work/result.h5" --quiet --no-resume \
  --set name=h5py_client --set 'particles.lattice.n=[3, 3, 3]' 2> "$work/run.log" ||
  { echo "h5py test: the run failed:"; cat "$work/run.log"; exit 1; }
"$py" "$here/h5py_client.py" "$bin/dem" "$work/result.h5" || exit 1
# dem table --csv through pandas (python3-pandas; this part is skipped alone if it cannot be had)
# and the one-liners of docs/results.md.
if ! "$py" -c 'import pandas' 2> /dev/null; then
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-pandas >> "$work/apt.log" 2>&1
fi
if "$py" -c 'import pandas' 2> /dev/null; then
  "$py" "$here/pandas_client.py" "$bin/dem" "$work/result.h5" "$here/../../docs/results.md" || exit 1
else
  echo "pandas client: python3-pandas cannot be installed here (see $work/apt.log): not run"
fi
# Frames for ParaView (output.frames, with the contact network) read back: tests/clients/frames_client.py.
"$bin/dem" run "$here/../../scenes/stability/base.yaml" --out "$work/frames.h5" --quiet --no-resume \
  --set name=frames_client --set 'particles.lattice.n=[3, 3, 3]' --set 'output.frames={interval: 400, contacts: true}' \
  2> "$work/frames_run.log" || { echo "h5py test: the frames run failed:"; cat "$work/frames_run.log"; exit 1; }
"$py" "$here/frames_client.py" "$work/frames.h5" 400 || exit 1
