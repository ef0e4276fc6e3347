#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then, from a folder outside the source and build
# trees: the installed dem answers --version (the same as the built one), the installed pipeline
# answers --help, and the installed example (from its shipped sample, shortened) runs to a complete
# result written in the current folder; every tool, the studies, the reference files, the report's
# templates and the installed layout's README are there, and `pipeline new` copies an installed
# study into the current folder, which then plans; dem render finds the installed render script;
# the Python module, installed, runs a scene.
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
# Everything a study needs: every tool, the studies, validate's reference files, the report's
# templates and figure scripts, the method, and a README for the installed layout.
share=$prefix/share/cyclic-triax
for tool in dem pipeline validate compare-runs ensemble-cycles figure-data report; do
  [ -x "$prefix/bin/$tool" ] || { echo "FAIL: $prefix/bin/$tool not installed"; fail=1; continue; }
  "$prefix/bin/$tool" --help > /dev/null 2>&1 || { echo "FAIL: installed $tool --help"; fail=1; }
done
for f in pipeline/studies/paper.yaml reference_data/paper.yaml reference_data/literature.yaml reports/templates/index.md \
         reports/templates/figure_notes.tsv reports/gnuplot/style.gp reports/make_figures.sh docs/method.md README.md \
         examples/own_references/references.yaml scenes/samples/dense_1k.h5 scenes/tests/test1.yaml; do
  [ -f "$share/$f" ] || { echo "FAIL: $share/$f not installed"; fail=1; }
done
readme=$prefix/share/doc/cyclic-triax/README.md
cmp -s "$readme" "$share/README.md" || { echo "FAIL: $readme is not the installed layout's README"; fail=1; }
# It speaks of the installed layout: no build tree, no make targets (both exist only in a clone).
if grep -n -E 'build/bin|\bmake ' "$readme"; then echo "FAIL: $readme speaks of the source tree"; fail=1; fi
# A study of your own from the installed studies, in this folder: the copy names the installed
# paper.yaml, resolves its scenes into the prefix and plans (no run: --plan).
"$prefix/bin/pipeline" new my_study.yaml --from paper > new.log 2>&1 || { echo "FAIL: pipeline new:"; cat new.log; fail=1; }
grep -q "$share/pipeline/studies/paper.yaml" new.log || { echo "FAIL: pipeline new did not copy the installed study:"; cat new.log; fail=1; }
grep -q "^preparation: $share/scenes/prepare_dense.yaml\|^preparation: .*share/cyclic-triax/scenes/prepare_dense.yaml" my_study.yaml ||
  { echo "FAIL: my_study.yaml's preparation does not lead to the installed scene:"; grep preparation my_study.yaml; fail=1; }
"$prefix/bin/pipeline" my_study.yaml --plan --profile quick > plan.log 2>&1 || { echo "FAIL: pipeline my_study.yaml --plan:"; cat plan.log; fail=1; }
grep -q "^seed1/loose_prepare " plan.log || { echo "FAIL: the plan lists no seed1/loose_prepare:"; head plan.log; fail=1; }
[ -d results/my_study/quick ] || { echo "FAIL: the copy's results folder is not results/my_study/quick beside it"; fail=1; }
# dem render finds the installed render script: a missing result is then the only complaint.
[ -x "$prefix/share/cyclic-triax/render/render.sh" ] && [ -f "$prefix/share/cyclic-triax/render/render_spheres.py" ] ||
  { echo "FAIL: the render script is not installed"; fail=1; }
"$prefix/bin/dem" render none.h5 --out none.png > render.log 2>&1
[ $? = 2 ] && grep -q "none.h5 is not a result file" render.log ||
  { echo "FAIL: installed dem render:"; cat render.log; fail=1; }
# The Python module, when the build made it: from the installed package alone (PYTHONPATH names only
# the prefix), Test 1 from the installed scenes, shortened, to a complete result in this folder; its
# studies and calibrations run the installed dem.
package=$(ls -d "$prefix"/lib/python3*/dist-packages/cyclic_triax 2> /dev/null | head -1)
if [ -f "$build/CMakeCache.txt" ] && grep -q '^DEM_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  if [ -z "$package" ]; then echo "FAIL: no cyclic_triax under $prefix/lib/python3*/dist-packages"; fail=1
  else
    (cd "$share" && PYTHONPATH=$(dirname "$package") /usr/bin/python3 -c "import sys, cyclic_triax as ct
r = ct.run('scenes/tests/test1.yaml', set={'stages[0].path': '[TC1]'}, out=sys.argv[1])
assert r.complete and ct.__file__.startswith(sys.argv[2]), (r, ct.__file__)
assert ct.dem_binary() == sys.argv[3], ('Study and calibrate would run', ct.dem_binary())" "$work/elsewhere/python.h5" "$package" \
      "$(cd "$prefix/bin" && pwd -P)/dem") > python.log 2>&1 ||
      { echo "FAIL: the installed Python module:"; cat python.log; fail=1; }
  fi
fi
[ $fail = 0 ] && echo "install: $prefix/bin/dem ($installed) ran the installed example in $(pwd)"
exit $fail
