#!/usr/bin/env bash
# Writes the study report reports/index.md from a results folder, the validation output and the
# figures. Usage: [CONVERGENCE=DIR] reports/make_report.sh [BIN_DIR] [RESULTS_DIR] [REPORT_DIR]
# BIN_DIR holds dem and figure-data (build/bin). Every setting the text quotes (time step, frictions,
# lattice, stress path, ...) is read from the resolved scenes of the results (figure-data settings),
# and the paper's values from reference_data/paper.yaml (figure-data samples-table).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/bin}
dem=$bin/dem
results=${2:-$here/results/study/paper}
report=${3:-$here/reports}
convergence=${CONVERGENCE:-$here/results/convergence/paper}
decisions=${DECISIONS:-$here/results/decisions/paper}
stability=${STABILITY:-$here/results/stability/paper}
# settings KEY: a setting of the study's runs; conv KEY: of the convergence study's reference runs.
study_settings=$("$bin/figure-data" settings "$results" 2> /dev/null || true)
conv_settings=$("$bin/figure-data" settings "$convergence" --prefix reference_ 2> /dev/null || true)
decisions_settings=$("$bin/figure-data" settings "$decisions" --prefix baseline_ 2> /dev/null || true)
stability_settings=$("$bin/figure-data" settings "$stability" --run base 2> /dev/null || true)
setting() { awk -F'\t' -v k="$1" '$1 == k { print $2 }' <<< "$study_settings"; }
conv() { awk -F'\t' -v k="$1" '$1 == k { print $2 }' <<< "$conv_settings"; }
decision() { awk -F'\t' -v k="$1" '$1 == k { print $2 }' <<< "$decisions_settings"; }
stab() { awk -F'\t' -v k="$1" '$1 == k { print $2 }' <<< "$stability_settings"; }
percent() { awk -v x="$1" 'BEGIN { if (x == "") print "?"; else printf "%g %%", 100 * x }'; }
spheres() { awk -v n="$1" 'BEGIN { if (n == "") print "?"; else if (n >= 1000) printf "%d,%03d", n / 1000, n % 1000; else print n }'; }
microseconds() { awk -v s="$1" 'BEGIN { if (s == "") print "?"; else printf "%g µs", s * 1e6 }'; }
scaled() { awk -v x="$1" -v f="$2" -v u="$3" 'BEGIN { if (x == "") print "?"; else printf "%g %s", x / f, u }'; }   # scaled VALUE FACTOR UNIT
# A section's table.md (REPORT_DIR/DIR/table.md) with its figures' paths made relative to the
# report; a figure that was not drawn (no gnuplot, a script that failed) is said so.
section_table() {
  local dir=$1 line png
  while IFS= read -r line; do
    if [[ $line =~ ^!\[(.*)\]\(([^/\)]+\.png)\)$ ]]; then
      png=${BASH_REMATCH[2]}
      if [ -f "$report/$dir/$png" ]; then echo "![${BASH_REMATCH[1]}]($dir/$png)"; else echo "*Figure \`$dir/$png\` not drawn.*"; fi
    else
      echo "$line"
    fi
  done < "$report/$dir/table.md"
}
shopt -s nullglob
out=$report/index.md
mkdir -p "$report"
{
  echo "# cyclic-triax: reproduction of the seed paper's study"
  echo
  echo "Generated on $(date -u +%Y-%m-%d) from \`$(realpath -s --relative-to="$here" "$results")\`${REPORT_NOTE:+ — $REPORT_NOTE}."
  echo "Source: commit \`$(git -C "$here" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)\`$(git -C "$here" diff --quiet HEAD -- . ':!reports' 2>/dev/null || echo ' (with uncommitted changes)'); engine: \`$("$dem" --version)\`."
  shopt -s globstar
  engines=$(for f in "$results"/**/*.h5; do [ -f "$f" ] || continue; h5dump -a software_version "$f" 2>/dev/null | sed -n 's/.*(0): "\(.*\)".*/\1/p'; done | sort | uniq -c | awk '{printf "%s%s (%d runs)", (NR > 1 ? ", " : ""), $2, $1}')
  echo "The results were written by: ${engines:-unknown}."
  # The samples of the ensemble: results/.../seed<N>/ (or the folder itself for one sample).
  samples=()
  for d in "$results"/seed*/; do [ -d "$d" ] && samples+=("${d%/}"); done
  [ ${#samples[@]} -gt 0 ] || samples=("$results")
  mapfile -t samples < <(printf '%s\n' "${samples[@]}" | sort -V)
  first=${samples[0]}
  echo
  echo "## Verdicts"
  echo
  if [ -f "$report/verdicts.md" ]; then cat "$report/verdicts.md"; else echo "No validation output yet (\`build/bin/validate\`)."; fi
  echo
  echo "Readings of the paper's open choices used (SPEC §7; read from the resolved scenes of the first sample):"
  echo "grading read by $(setting grading_basis);"
  echo "damping $(setting damping_form), translational $(setting damping_translational);"
  echo "hold until the unbalanced force ratio is below $(setting hold_unbalanced_force_ratio) and every principal stress within $(setting hold_stress_tolerance) of the target;"
  echo "strain-rate cap while compressing $(setting max_strain_rate_per_s) s⁻¹;"
  echo "shearing friction $(for d in loose medium dense; do printf '%s %s, ' "$d" "$(setting friction_shear_$d)"; done | sed 's/, $//');"
  echo "vertices at p = $(scaled "$(setting mean_stress_Pa)" 1e3 kPa) with R = $(setting stress_ratio);"
  echo "Test 3 visits $(setting test3_path | sed -n 's/.*\(TC1, A, [A-Z0-9]*, A, [A-Z0-9]*\).*/\1/p'), …;"
  echo "the cell is kept orthorhombic (its shear stresses are not controlled)."
  echo
  echo "## What the paper's open choices change"
  echo
  if [ -f "$report/decisions/table.md" ]; then
    echo "\`make decisions\` (\`pipeline/studies/decisions.yaml\`): each alternative reading of SPEC §7, one at a time from the"
    echo "baseline, each on its own ensemble ($(awk -F'\t' '$1 == "baseline" && $3 == "-" { n[$9] = 1 } END { print length(n) }' "$decisions/runs.tsv" 2>/dev/null || echo '?') samples"
    echo "of $(spheres "$(decision particles)") spheres; the cell side is scaled to 8,000 spheres). Every validation row is judged by the same rule as above."
    echo
    sed 's#](\(tornado[^)]*\))#](decisions/\1)#g' "$report/decisions/table.md"
  else
    echo "Not run yet (\`make decisions\`)."
  fi
  echo
  echo "## What was run"
  echo
  echo "${#samples[@]} sample(s) per density (seeds of the diameter sampler); each sample is prepared (SPEC §2: isotropic"
  echo "compression of the $(setting lattice) lattice ($(spheres "$(setting particles)") spheres) to $(setting target_pressure_kPa) kPa with the density's friction,"
  echo "$(setting friction_prepare) for loose / medium / dense, Δt = $(microseconds "$(setting time_step_prepare_s)")) and sheared along the five cyclic"
  echo "true-triaxial paths (SPEC §3; p = $(scaled "$(setting mean_stress_Pa)" 1e3 kPa), R = $(setting stress_ratio), $(scaled "$(setting stress_rate_Pa_per_s)" 1e6 MPa/s), shearing friction"
  echo "$(setting friction_shear), Δt = $(microseconds "$(setting time_step_test_s)")). Per sample:"
  echo
  echo "| sample | runs | steps | wall time of the runs (s) |"
  echo "|---|---|---|---|"
  total=0
  for dir in "${samples[@]}"; do
    runs=0; steps=0; wall=0
    for f in "$dir"/*.h5; do
      line=$("$dem" summary "$f" 2>/dev/null | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { printf "%d\t%.0f", $c["step"], $2 }') || continue
      [ -n "$line" ] || continue
      IFS=$'\t' read -r st w <<< "$line"
      runs=$((runs + 1)); steps=$((steps + st)); wall=$((wall + ${w%.*}))
    done
    echo "| $(basename "$dir") | $runs | $steps | $wall |"
    total=$((total + wall))
  done
  echo
  echo "Total wall time of the runs: $total s of one core (runs in parallel overlap)."
  echo
  echo "## The samples before shearing"
  echo
  echo "Each sample's last row of its preparation, with the paper's value in brackets (\`reference_data/paper.yaml\`)"
  echo "and the difference from it; the cell side is scaled to 8,000 spheres."
  echo
  "$bin/figure-data" samples-table "$results" --references "$here/reference_data/paper.yaml" --per-sample
  echo
  echo "## Validation against the paper"
  echo
  if [ -f "$report/validation.md" ]; then
    echo "Every row of SPEC §6 (\`reference_data/paper.yaml\`: value, tolerance, reason, source), per sample of the ensemble,"
    echo "with the mean, standard deviation, the 95 % prediction interval of one sample and the verdict; machine-readable in"
    echo "\`reports/validation.json\`."
    echo
    cat "$report/validation.md"
  else
    echo "No validation output yet (\`build/bin/validate\`)."
  fi
  echo
  echo "## Figures"
  echo
  echo "Figures 7, 10 and 11 show the mean of the ensemble with a band of one standard deviation; the others show the runs of"
  echo "one stated sample, $(basename "$first"); the slope of Figures 13–14 of every sample is in the validation table above."
  echo
  if [ -f "$report/figures/README.md" ]; then
    sed -e 's#](\(fig[^)]*\))#](figures/\1)#g' "$report/figures/README.md" | sed '1{/^# /d}'
  fi
  # One sentence per figure comparing it with the paper's text, written by a person who looked at
  # both: reports/figure_notes.tsv (file<TAB>sentence). A figure without one says so.
  notes=$report/figure_notes.tsv
  for png in "$report"/figures/fig[0-9]*.png; do
    name=$(basename "$png")
    note=""
    if [ -f "$notes" ]; then note=$(awk -F'\t' -v f="$name" '$1 == f { print $2 }' "$notes"); fi
    echo
    echo "![${name%.png}](figures/$name)"
    echo
    echo "${note:-*No comparison with the paper written for this figure yet.*}"
  done
  for png in "$report"/figures/render_*.png; do
    echo
    echo "### A sample in ParaView"
    echo
    echo "The XDMF view of a result (written beside every complete result) opened in ParaView by \`make render\`"
    echo "(\`reports/render/render.sh\`, pvbatch): the spheres of the last frame at their own radius, coloured by it, axis 1 vertical."
    echo
    echo "![$(basename "$png" .png)](figures/$(basename "$png"))"
  done
  echo
  echo "## Energy balance"
  echo
  echo "Every run books the work the cell does on the sample against the energy stored in the springs and in"
  echo "motion and the energy the damping and the sliding contacts took (engine/README.md, \`Energy balance\`); below, the"
  echo "runs of sample $(basename "$first")."
  echo
  "$here/reports/energy/energy.sh" "$report/figures" "$(setting max_energy_error)" > "$report/energy.md"
  cat "$report/energy.md"
  echo
  echo "![energy balance](figures/fig_energy.png)"
  echo
  echo "## Convergence: error against run time"
  echo
  if [ -f "$report/convergence/table.md" ]; then
    echo "\`pipeline/studies/convergence.yaml\`: the loose sample and Test 1 (2 cycles) at the paper's settings"
    echo "($(spheres "$(conv particles)") spheres, Δt = $(microseconds "$(conv time_step_test_s)"), $(scaled "$(conv stress_rate_Pa_per_s)" 1e6 MPa/s)) as the reference, and variants that change the time step (with their own"
    echo "preparation), the stress rate (test only) or the particle count, alone and together. Errors are relative to the"
    echo "reference; wall times are those of this machine while the study ran (\`reports/convergence/errors.dat\`)."
    echo
    cat "$report/convergence/table.md"
    if [ -f "$report/convergence/error_vs_time.png" ]; then
      echo
      echo "![error against wall time](convergence/error_vs_time.png)"
    fi
  else
    echo "Not run yet (\`make study\` runs it, \`make report\` draws it)."
  fi
  echo
  echo "## Stability"
  echo
  if [ -f "$report/stability/table.md" ]; then
    echo "\`pipeline/studies/stability.yaml\`: $(spheres "$(stab particles)") spheres (\`scenes/stability/base.yaml\`: fast isotropic compression"
    echo "to $(stab target_pressure_kPa) kPa, then A → TC1 → A) with one setting pushed per case. A case either runs to the end (finite values; the"
    echo "energy closure error is the largest over the rows once 1 % of the energy has come in, limit 1 %) or stops early"
    echo "with the engine's message (its own energy guard stops a run above \`numerics.max_energy_error\` = $(percent "$(stab max_energy_error)")); a time step"
    echo "above $(stab max_time_step_fraction) × critical runs once as written (refused) and once with \`numerics.max_time_step_fraction\` raised to 2 on"
    echo "purpose. ⚠ marks a case that does neither (\`reports/stability/table.md\`, \`build/bin/compare-runs stability\`)."
    echo
    cat "$report/stability/table.md"
  else
    echo "Not run yet (\`make study\` runs it, \`make report\` writes the table)."
  fi
  echo
  echo "## Critical state: friction, void ratio and coordination against μ"
  echo
  if [ -f "$report/critical_state/table.md" ]; then
    echo "\`make critical-state\` (\`pipeline/studies/critical_state.yaml\`, \`build/bin/compare-runs critical-state\`): the dense sample"
    echo "sheared drained at constant p to 40 % axial strain with the shearing friction μ = 0 … 1, in compression and extension,"
    echo "and true-triaxial at μ = 0.5 with b = 0 … 1; data in \`reports/critical_state/\` (\`critical_state.dat\`, \`pi_plane.dat\`)."
    echo
    section_table critical_state
  else
    echo "Not run yet (\`make critical-state\` runs it and writes the section; \`make study\` runs it too)."
  fi
  echo
  echo "## Liquefaction: cyclic stress ratio against cycles"
  echo
  if [ -f "$report/liquefaction/table.md" ]; then
    echo "\`make liquefaction\` (\`pipeline/studies/liquefaction_loose.yaml\`, \`liquefaction_medium.yaml\`, \`build/bin/compare-runs liquefaction\`):"
    echo "undrained cyclic triaxial tests of the loose and the medium sample at p0' = 100 kPa and the same samples held undrained with"
    echo "nothing applied; data in \`reports/liquefaction/\` (\`csr_nl.dat\`, \`ru.dat\`)."
    echo
    section_table liquefaction
  else
    echo "Not run yet (\`make liquefaction\` runs it and writes the section; \`make study\` runs it too)."
  fi
  echo
  echo "## Performance"
  echo
  if [ -f "$report/bench.md" ]; then
    echo "\`make bench\` (engine and LAMMPS on the same packings; \`reports/bench.json\`):"
    echo
    cat "$report/bench.md"
  else
    echo "No benchmark yet (\`make bench\`)."
  fi
  echo
  echo "## Provenance"
  echo
  echo "- Resolved scenes of every run: \`$(realpath -s --relative-to="$here" "$results")/scenes/\` (also inside each result, attribute \`scene_yaml\`)."
  echo "- Libraries: $(for p in libeigen3-dev libhdf5-dev libyaml-cpp-dev catch2 gnuplot-nox; do printf '%s %s; ' "$p" "$(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo '?')"; done)"
  echo "- Compiler: $(g++ --version | head -1); machine: $(nproc) cores."
} > "$out"
echo "report written to $out"
