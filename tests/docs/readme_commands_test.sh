#!/usr/bin/env bash
# The README's commands, as written: every command line of its ```sh blocks is listed below, and
# each is run as it stands from a folder laid out as a fresh clone (the source tree's folders and
# the build, by symbolic links), except where the list says why not (a build, a whole study) or
# what cheaper command stands in for it (a smaller sample). A README line missing from the list,
# or a listed line gone from the README, fails the test: the two are kept in step.
# Also the README's frames line (`--set 'output.frames={interval: 1000, contacts: true}'`) on every
# example of scenes/examples/, each shortened as the scene tests shorten it.
#   tests/docs/readme_commands_test.sh SOURCE_DIR BUILD_DIR WORKDIR
set -u
src=$1 build=$2 work=$3
rm -rf "$work" && mkdir -p "$work/clone" || exit 1
clone=$work/clone
for entry in "$src"/*; do
  name=$(basename "$entry")
  [ "$name" = build ] || ln -s "$entry" "$clone/$name"
done
ln -s "$build" "$clone/build"

# What each README command line does here, fields joined by " @@ ". `run @@ LINE`: as written.
# `instead @@ LINE @@ COMMAND @@ WHY`: COMMAND in its place. `skip @@ LINE @@ WHY`.
list=$(cat <<'EOF'
skip @@ make tools @@ installs packages and builds: what this test is built by
skip @@ make examples @@ each example whole (minutes); the frames check below runs every example shortened
skip @@ make all @@ the whole study (hours)
skip @@ make test @@ runs this test
instead @@ build/bin/dem run scenes/prepare_dense.yaml --out RESULT.h5 --threads 2 @@ build/bin/dem run scenes/prepare_dense.yaml --out RESULT.h5 --threads 1 --set 'particles.lattice.n=[4, 4, 4]' @@ 8,000 spheres take minutes: the same scene with 64
run @@ build/bin/dem table RESULT.h5 time p void_ratio coordination_number
run @@ build/bin/dem summary RESULT.h5
run @@ build/bin/dem plot RESULT.h5 time p --out p.png
run @@ build/bin/dem keys; build/bin/dem columns
run @@ build/bin/dem run --help
run @@ PYTHONPATH=build/python /usr/bin/python3 -c "import cyclic_triax as ct; r = ct.run('scenes/tests/test1.yaml', set={'stages[0].path': '[TC1, TC2, TC3]'}); print(r.table(['time', 'q_over_p']).tail()); ct.plot(r, 'time', 'q_over_p', out='q_over_p.png')"
run @@ build/bin/pipeline new my_study.yaml --from paper
run @@ build/bin/pipeline my_study.yaml --plan
skip @@ build/bin/pipeline my_study.yaml --profile quick -j 2 @@ 54 runs of 1,000 spheres, minutes of CPU beyond this test's budget; its plan ran above
EOF
)
# Field N (1: what, 2: the README line, 3: the command or the reason, 4: why) of an entry.
field() { awk -v n="$2" -F' @@ ' '{print $n}' <<< "$1"; }

# The README's command lines: ```sh blocks, comments after "  #" dropped, blank lines skipped.
readme_lines=$(awk '/^```sh/ {inside = 1; next} /^```/ {inside = 0} inside' "$src/README.md" |
               sed -E 's/[[:space:]]+#[[:space:]].*$//; s/[[:space:]]+$//' | grep -v '^$')
fail=0
listed_lines=$(awk -F' @@ ' '{print $2}' <<< "$list")
while IFS= read -r line; do
  printf '%s\n' "$listed_lines" | grep -qxF -- "$line" ||
    { echo "FAIL: README command not in this test's list (add it, run or with a reason): $line"; fail=1; }
done <<< "$readme_lines"
while IFS= read -r line; do
  printf '%s\n' "$readme_lines" | grep -qxF -- "$line" || { echo "FAIL: listed here but not in the README: $line"; fail=1; }
done <<< "$listed_lines"

# Python lines need Debian's h5py and pandas (make tools installs them).
have_python() { /usr/bin/python3 -c 'import h5py, pandas' 2> /dev/null; }
ran=0 skipped=0
while IFS= read -r entry; do
  what=$(field "$entry" 1) line=$(field "$entry" 2)
  case $what in
    skip) echo "skip: $line ($(field "$entry" 3))"; skipped=$((skipped + 1)); continue ;;
    run) command=$line ;;
    instead) command=$(field "$entry" 3); echo "instead of: $line -> $command ($(field "$entry" 4))" ;;
    *) echo "FAIL: a list entry of unknown kind: $entry"; fail=1; continue ;;
  esac
  if [[ $command == */usr/bin/python3* ]] && ! have_python; then
    echo "skip: $line (no h5py/pandas for /usr/bin/python3: make tools installs them)"; skipped=$((skipped + 1)); continue
  fi
  ran=$((ran + 1))
  if ! (cd "$clone" && bash -o pipefail -c "$command" < /dev/null) > "$work/out.txt" 2>&1; then
    echo "FAIL: $command"; sed 's/^/  /' "$work/out.txt" | tail -20; fail=1
  fi
done <<< "$list"

# The frames line on every example, shortened (the overrides of tests/CMakeLists.txt's scene tests):
# a complete result whose frames are at steps 0, 1000, 2000, ... and the end.
frames="output.frames={interval: 1000, contacts: true}"
declare -A short=(
  [cyclic_simple_shear]='stages[1].duration=0.002' [cyclic_strain_shear]='stages[0].duration=0.002'
  [hertz_mindlin_rolling]='stages[1].path=[TC1]' [triaxial_compression]='stages[0].duration=0.002'
  [true_triaxial_constant_p]='stages[0].duration=0.002' [undrained_cyclic_triaxial]='stages[1].duration=0.002')
for scene in "$src"/scenes/examples/*.yaml; do
  name=$(basename "$scene" .yaml)
  [ -n "${short[$name]:-}" ] || { echo "FAIL: example $name has no shortening here; add one"; fail=1; continue; }
  out=$work/frames_$name.h5
  ran=$((ran + 1))
  if ! (cd "$clone" && build/bin/dem run "scenes/examples/$name.yaml" --out "$out" --set "$frames" --set "${short[$name]}" \
          --threads 1 --quiet) > "$work/out.txt" 2>&1; then
    echo "FAIL: the frames line on $name:"; sed 's/^/  /' "$work/out.txt" | tail -10; fail=1; continue
  fi
  steps=$(h5dump -y -d /particles/all/position/step "$out" 2> /dev/null | awk '/DATA \{/ {f = 1; next} /\}/ {f = 0} f' |
          grep -oE '[0-9]+' | tr '\n' ' ')
  case " $steps" in
    *" 0 "*"1000 "*) set -- $steps; echo "frames of $name: $# at steps $1, $2, $3 ... ${!#}" ;;
    *) echo "FAIL: $name's frames are at steps '$steps', not every 1000 from 0"; fail=1 ;;
  esac
done
echo "README commands: $ran run, $skipped skipped"
exit $fail
