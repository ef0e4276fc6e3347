#!/usr/bin/env bash
# lammps_bench.sh: time LAMMPS (Debian package `lammps`) on the same sphere packing as `make bench`,
# so that LAMMPS and our engine can be shown side by side. Speed is in particle-steps per second.
#
#   reports/bench/lammps_bench.sh PARTICLES.txt LX LY LZ [XY XZ YZ] STEPS REPS OUT.json
#
# PARTICLES.txt: "x y z radius" (m), one sphere per line, '#' comment lines (`dem state R.h5`).
# LX LY LZ: periodic box 0..L (m). XY XZ YZ: the cell's tilts (m; `dem table` cell_tilt_12, _13, _23),
# LAMMPS's triclinic box, edges (LX,0,0), (XY,LY,0), (XZ,YZ,LZ), as the engine's; 0 0 0 if left out.
# A cell that holds its shear stresses at zero (a preparation with zero_shear_stress) tilts: read as
# orthogonal, its spheres overlap across the boundary (a tilt of 0.4 mm on a 70 mm packing gave LAMMPS
# 361.7 kPa and 2Nc/N 4.37 where the engine had 100 kPa and 6.11).
#
# Settings as in dem-bench: SI units, density 2650 kg/m^3, Hookean
# contacts kn = kt = 1e6 N/m with tangential history and Coulomb friction mu, dt = 1e-6 s, neighbour
# skin $SKIN m (default 2e-4) checked every step. Serial, one core (OMP_NUM_THREADS=1), mu = 0.5 then mu = 0
# (FRICTIONS="0.5" or "0" times one only, e.g. each on the packing jammed with that friction).
#
# Like dem-bench, every repetition starts again from the packing: read it, `run 200` (warm-up), then
# `run STEPS`, timed by LAMMPS's "Loop time of T ... for N steps with A atoms": rate = N A / T.
# Median = sorted[REPS/2] (as dem-bench), min, max; cpu_rate_median: the same per CPU-second (from LAMMPS's
# "% CPU use" of each timed run), which time-slicing on a busy machine inflates less.
#
# Damping (5% of critical, for the mean sphere mass m): contact damping gamma_n = 2*0.05*sqrt(kn/m_eff),
# m_eff = m/2, gamma_t = gamma_n/2; and, as the engine's viscous damping, a body force
# -2*0.05*sqrt(kn*m)*v (fix viscous). Without the body force the packing, which loses its
# tangential springs when read as bare positions, unjams within ~2000 steps and LAMMPS then times a
# nearly contact-free gas (about 3x faster). LAMMPS 2021 has no cheap spin damping (the engine damps
# spins too), so the box being fixed, the mu = 0.5 packing still relaxes slowly; mu = 0 unjams
# at once (as it does in the engine at fixed volume; dem-bench's stress servo re-compacts it).
# The table shows contacts per sphere (2Nc/N) and pressure after the warm-up -> after the timed run.
# Set LMP to use another launcher, e.g. LMP="mpirun -np 1 lmp". The logs are read and OUT.json written
# by `bench-report lammps-json` (BENCH_REPORT, default build/bin/bench-report; run_bench.sh passes its own).
#
# TILES=n (default 1) times the packing tiled n x n x n (LAMMPS's `replicate n n n` after reading
# it: n^3 times the spheres in a box n times as long, the same packing as `dem-bench size`). Like
# every `run`, LAMMPS sorts the atoms spatially when it sets the run up (atom_modify sort, on by
# default), so it times a spatially sorted order. The peak memory of the LAMMPS process (all
# repetitions, GNU time's maximum resident set size) goes into the JSON when /usr/bin/time exists.
set -euo pipefail

die() { echo "lammps_bench: $*" >&2; exit 1; }
usage="usage: $0 PARTICLES.txt LX LY LZ [XY XZ YZ] STEPS REPS OUT.json"
xy=0 xz=0 yz=0
case $# in
  7) particles=$1 lx=$2 ly=$3 lz=$4 steps=$5 reps=$6 out=$7 ;;
  10) particles=$1 lx=$2 ly=$3 lz=$4 xy=$5 xz=$6 yz=$7 steps=$8 reps=$9 out=${10} ;;
  *) die "$usage" ;;
esac
[ -r "$particles" ] || die "cannot read $particles"
[[ $steps =~ ^[1-9][0-9]*$ && $reps =~ ^[1-9][0-9]*$ ]] || die "STEPS and REPS must be positive integers"
LMP=${LMP:-lmp}
BENCH_REPORT=${BENCH_REPORT:-$(cd "$(dirname "$0")/../.." && pwd)/build/bin/bench-report}
[ -x "$BENCH_REPORT" ] || die "'$BENCH_REPORT' not found (make tools; or set BENCH_REPORT)"
command -v "${LMP%% *}" >/dev/null || die "'${LMP%% *}' not found: install the Debian package lammps (apt-get install -y lammps)"
export OMP_NUM_THREADS=1

density=2650 kn=1.0e6 kt=1.0e6 zeta=0.05 dt=1.0e-6 skin=${SKIN:-2.0e-4} warmup=200
tiles=${TILES:-1}
[[ $tiles =~ ^[1-9][0-9]*$ ]] || die "TILES must be a positive integer"
replicate=""
[ "$tiles" -gt 1 ] && replicate="replicate       $tiles $tiles $tiles"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. LAMMPS data file (atom_style sphere: id type diameter density x y z); prints the atom count,
#    gamma_n (1/s; the Hooke damping force is m_eff gamma_n v_n) and the fix viscous gamma (kg/s).
read -r natoms gamman gammav < <(awk -v lx="$lx" -v ly="$ly" -v lz="$lz" -v xy="$xy" -v xz="$xz" -v yz="$yz" -v rho="$density" -v kn="$kn" -v zeta="$zeta" \
    -v data="$tmp/data.spheres" '
  /^[[:space:]]*(#|$)/ { next }
  NF < 4 { print "lammps_bench: bad line " NR ": " $0 > "/dev/stderr"; exit 1 }
  { n++; x[n] = $1; y[n] = $2; z[n] = $3; r[n] = $4; msum += 4 / 3 * 3.141592653589793 * $4^3 * rho }
  END {
    if (n == 0) { print "lammps_bench: no particles" > "/dev/stderr"; exit 1 }
    printf "spheres from dem state\n\n%d atoms\n1 atom types\n\n", n > data
    printf "0 %s xlo xhi\n0 %s ylo yhi\n0 %s zlo zhi\n", lx, ly, lz > data
    if (xy != 0 || xz != 0 || yz != 0) printf "%s %s %s xy xz yz\n", xy, xz, yz > data
    printf "\nAtoms # sphere\n\n" > data
    for (i = 1; i <= n; i++) printf "%d 1 %.17g %s %s %s %s\n", i, 2 * r[i], rho, x[i], y[i], z[i] > data
    m = msum / n
    printf "%d %.6g %.6g\n", n, 2 * zeta * sqrt(kn / (m / 2)), 2 * zeta * sqrt(kn * m)
  }' "$particles") || die "could not convert $particles"
gammat=$(awk -v g="$gamman" 'BEGIN { printf "%.6g", g / 2 }')

# 2. The input; ${mu} comes from the command line. Contacts (compute contact/atom) and pressure are
#    evaluated only outside the timed runs.
cat >"$tmp/in.setup" <<EOF
units           si
atom_style      sphere
boundary        p p p
comm_modify     vel yes
read_data       $tmp/data.spheres
$replicate
pair_style      gran/hooke/history $kn $kt $gamman $gammat \${mu} 1
pair_coeff      * *
neighbor        $skin bin
neigh_modify    delay 0 every 1 check yes
fix             integrate all nve/sphere
fix             damping all viscous $gammav
timestep        $dt
compute         nc all contact/atom
compute         z all reduce ave c_nc
variable        z equal c_z
variable        p equal press
EOF
for ((i = 0; i < reps; i++)); do cat <<EOF
include         $tmp/in.setup
thermo_style    custom step atoms ke press c_z
thermo_modify   lost error
run             $warmup
print           "BENCH warm contacts_per_atom \${z} pressure_Pa \${p}"
thermo_style    custom step atoms ke
thermo_modify   lost error
print           "BENCH timed"
run             $steps
thermo_style    custom step atoms ke press c_z
thermo_modify   lost error
run             0
print           "BENCH end contacts_per_atom \${z} pressure_Pa \${p}"
clear
EOF
done >"$tmp/in.bench"

# 3. Run mu = 0.5 and mu = 0, each log kept in $tmp (log.mu<mu>, and GNU time's rss.mu<mu>).
frictions=${FRICTIONS:-0.5 0}
for mu in $frictions; do
  log=$tmp/log.mu$mu
  timer=()
  [ -x /usr/bin/time ] && timer=(/usr/bin/time -f %M -o "$tmp/rss.mu$mu")
  if ! "${timer[@]}" $LMP -var mu "$mu" -in "$tmp/in.bench" -log "$log" -screen none >"$tmp/stdout" 2>&1 ||
     [ "$(grep -c '^BENCH end' "$log")" -ne "$reps" ]; then
    echo "lammps_bench: LAMMPS run with mu = $mu failed; end of its log:" >&2
    tail -n 25 "$log" "$tmp/stdout" >&2 2>/dev/null || true
    exit 1
  fi
done

# 4. The JSON: bench-report reads the logs (rates, contacts, pressure, neighbours, list builds:
#    engine/bench/lammps_log.hpp) and writes OUT.json with nlohmann-json; the version is LAMMPS's
#    banner plus the Debian package version.
pkg=$(dpkg-query -W -f='${Version}' lammps 2>/dev/null || echo unknown)
"$BENCH_REPORT" lammps-json "$tmp" "$out" --frictions "$frictions" --atoms "$natoms" --tiles "$tiles" --steps "$steps" \
  --reps "$reps" --package "$pkg" \
  --settings "pair_style gran/hooke/history $kn $kt $gamman $gammat MU 1; fix nve/sphere; fix viscous $gammav; fixed periodic box, tilts $xy $xz $yz m" ||
  die "could not write $out from the logs"
