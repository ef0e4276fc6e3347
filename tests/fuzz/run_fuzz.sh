#!/usr/bin/env bash
# make fuzz's runs: each libFuzzer target of BUILD_FUZZ (fuzz_scene, fuzz_study, fuzz_csv) for
# SECONDS, its corpus started from the project's own files; a crash is written to
# BUILD_FUZZ/crashes/<target>-..., the log to BUILD_FUZZ/<target>.log. Exit 1 on the first target
# that finds a bug.
#   tests/fuzz/run_fuzz.sh BUILD_FUZZ SECONDS
set -u
out=${1:?usage: run_fuzz.sh BUILD_FUZZ SECONDS}
seconds=${2:?usage: run_fuzz.sh BUILD_FUZZ SECONDS}
mkdir -p "$out/crashes" "$out/corpus/scene" "$out/corpus/study" "$out/corpus/csv"
cp scenes/*.yaml scenes/tests/*.yaml "$out/corpus/scene/"
cp pipeline/studies/*.yaml "$out/corpus/study/"
printf 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.02,0.01,0.01,0.002\n' > "$out/corpus/csv/two.csv"
for t in scene study csv; do
  "$out/bin/fuzz_$t" "$out/corpus/$t" -max_total_time="$seconds" -timeout=10 \
    -artifact_prefix="$out/crashes/$t-" -print_final_stats=1 > "$out/$t.log" 2>&1
  rc=$?
  tail -n 14 "$out/$t.log"
  [ $rc = 0 ] || { echo "fuzz_$t found a bug: $out/$t.log"; exit 1; }
done
