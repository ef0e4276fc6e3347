#!/bin/bash
# LAMMPS test: the contact stress tensor and the mean normal contact force of one static
# packing, evaluated by our engine and by LAMMPS (Debian's `lammps`, /usr/bin/lmp), must agree to
# 1e-9 relative for the linear law and for Hertz. Skipped (exit 77) where LAMMPS is not installed.
#
#   tests/lammps/contact_stress_test.sh BUILD_BIN WORKDIR
#
# 1. The packing: `dem run` compresses 1,000 spheres (3.0-4.5 mm) to 100 kPa (linear law, mu = 0.5,
#    about 47,000 steps, 2 s); `dem state` writes its final positions and radii, which become
#    particles.csv and a LAMMPS data file. Both codes read the same decimal numbers (`dem state`
#    prints 10 significant digits: the CSV packing is that packing to 1e-12 m, i.e. a packing of
#    its own, which is what both codes evaluate).
# 2. Ours: a scene reading the CSV (`particles: {csv: ..., cell: [...]}`) runs one step; the row
#    every stage writes at its start, before the first step, is measured from the positions alone
#    (analysis/measurements.cpp; before the fix this row saw no contacts, the neighbour list being
#    built only by the first step): stress_11 ... stress_23, mean_normal_force and contacts, read
#    from the HDF5 file at full precision (h5dump -m %.17g; `dem table` prints only 10 digits).
# 3. LAMMPS: the same positions (atom_style sphere, periodic box 0..L), `run 0`, with
#      - the pressure tensor of `compute pressure NULL virial`: the virial alone, so no kinetic
#        term (the velocities are zero anyway). LAMMPS's virial sum over pairs of r_ij (x) f_ij / V,
#        r_ij = x_i - x_j and f_ij the force on i, is positive for repulsive contacts, so its
#        pressure is compression positive like our stress (tension negative); its components
#        [1..6] are xx yy zz xy xz yz = our stress_11 22 33 12 13 23;
#      - `compute pair/local force`, the magnitude of each listed pair's force, dumped at 17 digits;
#        pairs out of contact give 0. The mean normal force is the sum over pairs with a non-zero
#        force divided by their number (the contact count, compared with ours exactly).
#    Springs zero: the shear history of LAMMPS's gran styles starts at zero and `run 0` does not
#    update it (update->setupflag), and our history read from a CSV is zero; velocities and spins
#    are zero, so no damping force in either code (gamma_n = gamma_t = 0 anyway).
#
# Parameters (SI; LAMMPS `units si`):
#   linear:  ours kn = 1e6 N/m: f_n = kn delta.
#            LAMMPS gran/hooke/history kn kt 0 0 mu 0: f_n = kn delta (its kn in force/distance),
#            and pair granular `hooke kn 0`: the same law written by another code path.
#   Hertz:   ours E = 1e9 Pa, nu = 0.3 (engine/contact/hertz_mindlin.hpp):
#              f_n = 4/3 E* sqrt(R* delta) delta, E* = E / (2 (1 - nu^2)), R* = r_i r_j / (r_i + r_j).
#            LAMMPS gran/hertz/history (pair_gran_hertz_history.cpp): f_n = kn delta sqrt(delta R*)
#              with R* = r_i r_j / (r_i + r_j) (its `polyhertz`): its kn is per unit of
#              sqrt(delta R*) and so kn_LAMMPS = 4/3 E* = 4/3 E / (2 (1 - nu^2)) = 7.326007326e8 Pa,
#              computed below to 17 digits (SI: nktv2p = 1, so LAMMPS's division of kn by it is
#              exact). Its tangential stiffness kt sqrt(delta R*) equals Mindlin's 8 G* sqrt(R* delta)
#              for kt = 8 G*, G* = G / (2 (2 - nu)), G = E / (2 (1 + nu)) (irrelevant here: the
#              springs are zero, but it is the like-for-like setting).
#            LAMMPS pair granular `hertz/material E 0 nu`: k_n = 4/3 E_eff, E_eff = 1 / ((1 - nu_i^2)/E_i
#              + (1 - nu_j^2)/E_j) = E / (2 (1 - nu^2)) = our E*: LAMMPS derives E* itself from E
#              and nu, an independent check of our definition.
#
# Agreement: the two codes sum the same terms in other orders and compute the branch vector in
# other ways (ours: L (s_j - s_i) from fractional coordinates s = x / L; LAMMPS: x_i - x_j with
# periodic images x + L), so the overlaps differ by ~ulp(L) ~ 1e-17 m, a relative 1e-11 of a
# typical overlap of 1e-6 m. The stress is compared component by component relative to the
# largest component |sigma|_max (the off-diagonal components are sums of terms of size ~p that
# cancel to ~1 % of p, so their own round-off is of order ulp(p), not of their own size); the
# mean normal force relative to itself. Required: < 1e-9, and the same contact count. Measured:
# 5e-14 (stress) and 1.7e-14 (mean force) for both laws and both LAMMPS pair styles, 2080 contacts.
set -u
bin=$(cd "$1" && pwd) work=$2
LMP=${LMP:-lmp}
if ! command -v "${LMP%% *}" > /dev/null; then
  echo "lammps test: skipped, '${LMP%% *}' not found (apt-get install lammps)"
  exit 77
fi
command -v h5dump > /dev/null || { echo "lammps test: h5dump not found (apt-get install hdf5-tools)"; exit 1; }
export OMP_NUM_THREADS=1
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
start=$(date +%s.%N)
elapsed() { awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f s", b - a}'; }
status=0
fail() { echo "lammps test: FAILED: $*"; status=1; }

tol=1e-9
E=1.0e9 nu=0.3 kn=1.0e6 ks=1.0e6 mu=0.5
# 4/3 E*, 8 G* (awk computes in double precision; %.17g round-trips).
kn_hertz=$(awk -v E="$E" -v nu="$nu" 'BEGIN { printf "%.17g", 4.0 / 3.0 * (E / (2 * (1 - nu * nu))) }')
kt_hertz=$(awk -v E="$E" -v nu="$nu" 'BEGIN { printf "%.17g", 8 * (E / (2 * (1 + nu))) / (2 * (2 - nu)) }')

# 1. The packing.
cat > packing.yaml << 'EOF'
name: lammps_packing
particles:
  lattice: {n: [10, 10, 10], spacing: 4.6e-3, seed: 5}
  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}
material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}
numerics: {time_step: 1.0e-6}
output: {interval: 5000}
stages:
  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e8, max_strain_rate: 50,
     hold: {stress_tolerance: 0.01, unbalanced_force_ratio: 0.01, max_duration: 1.0}}
EOF
"$bin/dem" run packing.yaml --out packing.h5 --quiet 2> packing.log || { echo "lammps test: the packing run failed:"; cat packing.log; exit 1; }
"$bin/dem" state packing.h5 > state.txt || exit 1
read -r lx ly lz < <(awk 'NR == 1 { print $(NF - 2), $(NF - 1), $NF }' state.txt)
awk 'BEGIN { print "x,y,z,radius" } !/^#/ { print $1 "," $2 "," $3 "," $4 }' state.txt > particles.csv
n=$(($(wc -l < particles.csv) - 1))
echo "packing: $n spheres, cell $lx x $ly x $lz m, after $(elapsed)"
[ "$n" = 1000 ] || { echo "lammps test: expected 1000 spheres"; exit 1; }

# 2. Ours: one step from the CSV; the row at step 0.
first_value() {  # FILE COLUMN: the first value of a time-series column, 17 digits
  h5dump -m '%.17g' -d "/timeseries/$2" -s 0 -c 1 "$1" | awk '/^ *\(0\):/ { print $2; found = 1; exit } END { exit !found }'
}
ours() {  # NAME MATERIAL DAMPING
  cat > "$1.yaml" << EOF
name: $1
particles: {csv: particles.csv, cell: [$lx, $ly, $lz]}
material: $2
damping: $3
numerics: {time_step: 1.0e-6}
output: {interval: 1}
stages:
  - {name: evaluate, type: strain_rate, strain_rate: [0, 0, 0], duration: 1.0e-6}
EOF
  "$bin/dem" run "$1.yaml" --out "$1.h5" --quiet 2> "$1.log" || { echo "lammps test: dem run $1 failed:"; cat "$1.log"; exit 1; }
  local step
  step=$(first_value "$1.h5" step)
  [ "$step" = 0 ] || { echo "lammps test: $1: the first row is at step $step, not 0"; exit 1; }
  for c in stress_11 stress_22 stress_33 stress_12 stress_13 stress_23 mean_normal_force contacts; do
    printf '%s ' "$(first_value "$1.h5" "$c")"
  done > "$1.values"
  echo >> "$1.values"
}
ours linear "{density: 2650, kn: $kn, ks: $ks, friction: $mu}" "{form: viscous}"
ours hertz "{density: 2650, law: hertz_mindlin, young_modulus: $E, poisson_ratio: $nu, friction: $mu}" "{form: local}"

# 3. LAMMPS: data file (atom_style sphere: id type diameter density x y z; 2 r is exact in binary).
awk -v lx="$lx" -v ly="$ly" -v lz="$lz" -v n="$n" -F, '
  NR == 1 {
    printf "spheres from dem state\n\n%d atoms\n1 atom types\n\n", n
    printf "0 %s xlo xhi\n0 %s ylo yhi\n0 %s zlo zhi\n\nAtoms # sphere\n\n", lx, ly, lz
    next
  }
  { printf "%d 1 %.17g 2650 %s %s %s\n", NR - 1, 2 * $4, $1, $2, $3 }' particles.csv > spheres.data
lammps() {  # NAME PAIR_STYLE PAIR_COEFF
  cat > "$1.in" << EOF
units           si
atom_style      sphere
boundary        p p p
comm_modify     vel yes
read_data       spheres.data
pair_style      $2
pair_coeff      $3
neighbor        2.0e-4 bin
timestep        1.0e-6
compute         virial all pressure NULL virial
compute         pairs all pair/local force
compute         nc all contact/atom
compute         ncsum all reduce sum c_nc
thermo_style    custom step c_virial[1] c_ncsum
dump            forces all local 1 $1.forces c_pairs
dump_modify     forces format float %.17g
run             0
print           "VIRIAL \$(c_virial[1]:%.17g) \$(c_virial[2]:%.17g) \$(c_virial[3]:%.17g) \$(c_virial[4]:%.17g) \$(c_virial[5]:%.17g) \$(c_virial[6]:%.17g) \$(c_ncsum:%.17g)"
EOF
  "$LMP" -in "$1.in" -log "$1.log" -screen none > /dev/null 2>&1 && grep -q '^VIRIAL' "$1.log" ||
    { echo "lammps test: LAMMPS run $1 failed; end of its log:"; tail -n 20 "$1.log"; exit 1; }
  # Pressure tensor, then mean normal force and contact count from the pairs with a force, then
  # LAMMPS's own contact count (contact/atom summed, halved) and the smallest force / mean force.
  { awk '/^VIRIAL/ { printf "%s %s %s %s %s %s ", $2, $3, $4, $5, $6, $7; nc = $8 } END { printf "%.17g ", nc / 2 }' "$1.log"
    awk 'f && NF == 1 && $1 > 0 { s += $1; c++; if (min == "" || $1 < min) min = $1 }
         /^ITEM: ENTRIES/ { f = 1 }
         END { printf "%.17g %d %.3g\n", s / c, c, min / (s / c) }' "$1.forces"; } > "$1.values"
}
lammps lammps_hooke "gran/hooke/history $kn $ks 0 0 $mu 0" "* *"
lammps lammps_granular_hooke "granular" "* * hooke $kn 0 tangential linear_history $ks 0 $mu"
lammps lammps_hertz "gran/hertz/history $kn_hertz $kt_hertz 0 0 $mu 0" "* *"
lammps lammps_granular_hertz "granular" "* * hertz/material $E 0 $nu tangential mindlin NULL 0 $mu"
echo "LAMMPS ($(head -n 1 lammps_hooke.log | sed 's/^LAMMPS (\(.*\))$/\1/')): 4 evaluations, after $(elapsed)"

# 4. Compare.
compare() {  # OURS LAMMPS
  read -r -a a < "$1.values"
  read -r -a b < "$2.values"
  # b: pxx pyy pzz pxy pxz pyz contacts(contact/atom) mean_fn contacts(pairs) min_fn/mean_fn
  local line
  line=$(awk -v tol="$tol" -v s11="${a[0]}" -v s22="${a[1]}" -v s33="${a[2]}" -v s12="${a[3]}" -v s13="${a[4]}" -v s23="${a[5]}" \
    -v fn="${a[6]}" -v nc="${a[7]}" -v p11="${b[0]}" -v p22="${b[1]}" -v p33="${b[2]}" -v p12="${b[3]}" -v p13="${b[4]}" \
    -v p23="${b[5]}" -v nc_atom="${b[6]}" -v lfn="${b[7]}" -v lnc="${b[8]}" -v minratio="${b[9]}" '
    function abs(x) { return x < 0 ? -x : x }
    BEGIN {
      ours[1] = s11; ours[2] = s22; ours[3] = s33; ours[4] = s12; ours[5] = s13; ours[6] = s23
      them[1] = p11; them[2] = p22; them[3] = p33; them[4] = p12; them[5] = p13; them[6] = p23
      scale = 0
      for (k = 1; k <= 6; k++) if (abs(them[k]) > scale) scale = abs(them[k])
      worst = 0; own = 0
      for (k = 1; k <= 6; k++) {
        d = abs(ours[k] - them[k]) / scale; if (d > worst) worst = d
        if (them[k] != 0) { d = abs(ours[k] - them[k]) / abs(them[k]); if (d > own) own = d }
      }
      dfn = abs(fn - lfn) / abs(lfn)
      ok = worst < tol && dfn < tol && nc == lnc && nc == nc_atom && scale > 1e3 && nc > 1500
      printf "%s p %.6g Pa, contacts %d (LAMMPS %d pairs, contact/atom %d), smallest f_n / mean %.2g; stress rel. diff %.2e (largest component %.2e of its own size), mean f_n %.17g vs %.17g, rel. diff %.2e\n", \
        ok ? "ok" : "FAIL", (p11 + p22 + p33) / 3, nc, lnc, nc_atom, minratio, worst, own, fn, lfn, dfn
    }')
  echo "$1 vs $2: $line"
  [ "${line%% *}" = ok ]
}
for pair in "linear lammps_hooke" "linear lammps_granular_hooke" "hertz lammps_hertz" "hertz lammps_granular_hertz"; do
  compare $pair || fail "${pair/ / vs } does not agree to $tol"
done

# Control: the comparison is sensitive. Our Hertz scene with E larger by 1e-8 (relative) must
# differ from LAMMPS by about 1e-8 in both stress and mean force, i.e. fail the 1e-9 test.
E_off=$(awk -v E="$E" 'BEGIN { printf "%.17g", E * (1 + 1e-8) }')
ours hertz_off "{density: 2650, law: hertz_mindlin, young_modulus: $E_off, poisson_ratio: $nu, friction: $mu}" "{form: local}"
if compare hertz_off lammps_hertz > control.txt; then
  fail "the control (E off by 1e-8) passed the comparison: $(cat control.txt)"
else
  echo "control, E x (1 + 1e-8), is told apart: $(sed 's/.*stress rel. diff/stress rel. diff/' control.txt)"
fi
echo "lammps test: $([ $status = 0 ] && echo passed || echo FAILED) after $(elapsed)"
exit $status
