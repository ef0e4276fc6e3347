#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then, from a folder outside the source and build
# trees: the installed dem answers --version (the same as the built one), the installed pipeline
# answers --help, the installed example (from its shipped sample, shortened) runs to a complete
# result written in the current folder, and dem render finds the installed render script.
#   tests/install/install_test.sh BUILD_DIR WORKDIR
set -u
build=$1 work=$2
rm -rf "$work" && mkdir -p "$work/elsewhere" || exit 1
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { echo "FAIL: cmake --install:"; cat "$work/install.log"; exit 1; }
cd "$work/elsewhere" || exit 1
fail=0
[ -x "$prefix/bin/dem" ] || { echo "FAIL: no $prefix/bin/dem"; exit 1; }
installed=$("$prefix/bin/dem" --version) || { echo "FAIL: installed dem --version"; fail=1; }
built=$("$build/bin/dem" --version)
[ "$installed" = "$built" ] || { echo "FAIL: installed '$installed', built '$built'"; fail=1; }
if [ -x "$prefix/bin/pipeline" ]; then
  "$prefix/bin/pipeline" --help > /dev/null || { echo "FAIL: installed pipeline --help"; fail=1; }
fi
scene=$prefix/share/cyclic-triax/scenes/examples/triaxial_compression.yaml
[ -f "$scene" ] || { echo "FAIL: $scene not installed"; exit 1; }
"$prefix/bin/dem" run "$scene" --out result.h5 --set 'stages[0].duration=0.002' --threads 1 --quiet 2> run.log ||
  { echo "FAIL: the installed example did not run:"; cat run.log; fail=1; }
status=$(h5dump -a /status result.h5 2> /dev/null | awk -F'"' '/\(0\)/ {print $2}')
[ "$status" = complete ] || { echo "FAIL: result.h5 in $(pwd) has status '$status'"; fail=1; }
[ -f "$prefix/share/doc/cyclic-triax/LICENSE" ] || { echo "FAIL: LICENSE not installed"; fail=1; }
# dem render finds the installed render script: a missing result is then the only complaint.
[ -x "$prefix/share/cyclic-triax/render/render.sh" ] && [ -f "$prefix/share/cyclic-triax/render/render_spheres.py" ] ||
  { echo "FAIL: the render script is not installed"; fail=1; }
"$prefix/bin/dem" render none.h5 --out none.png > render.log 2>&1
[ $? = 2 ] && grep -q "none.h5 is not a result file" render.log ||
  { echo "FAIL: installed dem render:"; cat render.log; fail=1; }
[ $fail = 0 ] && echo "install: $prefix/bin/dem ($installed) ran the installed example in $(pwd)"
exit $fail
