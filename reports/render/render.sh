#!/usr/bin/env bash
# Renders a result's spheres with ParaView (pvbatch) from its XDMF file to a PNG: the check that the
# XDMF view of a result opens in ParaView. Installs Debian's paraview and xvfb if missing (apt-get,
# with sudo when not root); Debian's pvbatch draws through X, so without a DISPLAY it starts a
# virtual one (Xvfb) for the render and stops it after.
# Usage: reports/render/render.sh RESULT.xdmf OUT.png [TITLE]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 RESULT.xdmf OUT.png [TITLE]" >&2; exit 2; }
xdmf=$1; png=$2; title=${3:-$(basename "$xdmf" .xdmf)}
here=$(cd "$(dirname "$0")" && pwd)
[ -f "$xdmf" ] || { echo "error: $xdmf not found (every complete result has one beside it)" >&2; exit 2; }
sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo
missing=""
for p in paraview python3-paraview xvfb; do dpkg -s "$p" > /dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  echo "installing:$missing" >&2
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
fi
xvfb_pid=""
trap '[ -z "$xvfb_pid" ] || kill "$xvfb_pid" 2> /dev/null || true' EXIT
if [ -z "${DISPLAY:-}" ]; then
  for n in $(seq 90 120); do   # the first free display number
    [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ] && continue
    Xvfb ":$n" -screen 0 1280x1024x24 +extension GLX -nolisten tcp > /dev/null 2>&1 &
    xvfb_pid=$!
    for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$n" ] && break; sleep 0.1; done
    if kill -0 "$xvfb_pid" 2> /dev/null; then export DISPLAY=":$n"; break; fi
    xvfb_pid=""
  done
  [ -n "${DISPLAY:-}" ] || { echo "error: could not start Xvfb for pvbatch" >&2; exit 1; }
fi
mkdir -p "$(dirname "$png")"
# ParaView's log goes to a file; its own message or the error is what we show.
# Mesa's software OpenGL (Xvfb has no GPU). A fresh Xvfb often refuses pvbatch's first
# connections ("bad X server connection"; xvfb-run's display does too; on a loaded 2-core VM all of
# five tries 2 s apart once): try up to ten times, 3 s apart, each in a subshell that logs the
# abort of a refused try instead of showing it.
export LIBGL_ALWAYS_SOFTWARE=1
log=$(mktemp)
for attempt in $(seq 10); do
  (pvbatch "$here/render_spheres.py" "$xdmf" "$png" "$title"; exit $?) > "$log" 2>&1 && break
  grep -q 'bad X server connection' "$log" || break
  sleep 3
done
if ! grep -q '^rendered' "$log"; then
  grep -v '^ *[0-9]\+ \+0x' "$log" | tail -20 >&2; rm -f "$log"; exit 1
fi
grep '^rendered' "$log"; rm -f "$log"
