#!/usr/bin/env bash
# `dem render` on a shipped sample (scenes/samples/dense_1k.h5, read where the clone has it): a PNG
# of the last frame is made and shows coloured spheres, not only greys (ParaView's opaque cell was a
# grey box). Skipped (exit 77) where pvbatch or xvfb-run is missing: Debian's paraview,
# python3-paraview and xvfb (`dem render` would install them; this test does not).
#   tests/render/render_test.sh BIN_DIR SOURCE_DIR WORKDIR
set -u
bin=$1 src=$2 work=$3
command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null && command -v pvpython > /dev/null ||
  { echo "render test: pvbatch, pvpython or xvfb-run missing (Debian paraview, python3-paraview, xvfb): skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work" || exit 1
png=$work/dense.png
"$bin/dem" render "$src/scenes/samples/dense_1k.h5" --out "$png" > "$work/render.log" 2>&1 ||
  { echo "render test: dem render failed:"; cat "$work/render.log"; exit 1; }
cat "$work/render.log"
[ -s "$png" ] || { echo "render test: no $png"; exit 1; }
[ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { echo "render test: $png is not a PNG"; exit 1; }
# The colours of the picture, counted by VTK's own PNG reader (ParaView's Python).
colours=$(pvpython - "$png" 2> "$work/count.log" <<'PY'
import sys
from vtkmodules.vtkIOImage import vtkPNGReader
r = vtkPNGReader()
r.SetFileName(sys.argv[1])
r.Update()
img = r.GetOutput()
a = img.GetPointData().GetScalars()
n = a.GetNumberOfComponents()
seen = set()
for i in range(0, a.GetNumberOfTuples(), 7):
    rgb = tuple(int(a.GetComponent(i, c)) for c in range(min(n, 3)))
    if len(set(rgb)) > 1:  # not a grey: the white ground, black lines and text, a grey box are greys
        seen.add(rgb)
print(len(seen))
PY
) || { echo "render test: cannot read $png:"; cat "$work/count.log"; exit 1; }
echo "render test: $png has $colours colours that are not greys (every 7th pixel)"
# Spheres coloured by radius (Viridis, shaded) give many; a grey box, the ground, the outline and the
# text none.
[ "$colours" -gt 16 ] || { echo "render test: $png shows no coloured spheres"; exit 1; }
