#!/bin/bash
# The mixed-mode kinking study of this folder's README (section 6.4 of the paper): the square
# of square.prm, loaded by the crack-tip field of eq. 82 on its four sides with K_eff = Kdot t
# at phase angle psi, Kdot set so that G reaches G0 at the time T_c.
# Pure PD, coupled (PD box around the crack and the tip, overlaps of 2 FE cells, FE
# beyond, weak coupling, force blending, damping constant 10: the paper's 30 over-damps the
# narrow overlaps at this time step) and adaptive (PD on the crack only, growing with it,
# ../adaptive_zone). Prints the table of the README and draws each
# run's final damage map (scripts/plot_cracks.sh, gnuplot-nox):
#   studies/mixed_mode/run.sh <build directory> <work directory> [<mpi ranks>] [<groups>]
# <groups> (default: all) names the groups to run: angles, angles_m6, ramp, convergence,
# coupled, m6_coupled, m6_coupled_angles, adaptive, bond_energy, stress. Takes about three hours for all
# on one core. Every run is <work directory>/<name>.prm, a file that includes square.prm and
# sets what the run changes.
set -euo pipefail
usage="usage: studies/mixed_mode/run.sh <build directory> <work directory> [<mpi ranks>] [<groups>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
groups=${4:-angles angles_m6 ramp convergence coupled m6_coupled m6_coupled_angles adaptive bond_energy stress}
here=$(cd "$(dirname "$0")" && pwd)
scripts=$(cd "$here/../../scripts" && pwd)
mkdir -p "$work"
cd "$work"
source "$scripts/study_lib.sh"

# case_file <name> <plane: strain|stress> <psi [deg]> <T_c [s]> <lattice sites per side>
#           <horizon factor> <FE cells per side> <coupled: 0|1|2 (adaptive)> [<fracture criterion>]
# writes the run's parameters: square.prm and what this run changes.
case_file() {
  local name=$1 plane=$2 psi=$3 tc=$4 n=$5 m=$6 cells=$7 coupled=$8 criterion=${9:-critical stretch}
  local L=0.03125 dx c kc kdot end
  dx=$(calc "2 * $L / $n")
  c=$(calc "2 * $L / $cells")
  # K_c = sqrt(G0 E'), E' = E / (1 - nu^2) in plane strain, E in plane stress.
  if [ "$plane" = strain ]; then kc=$(calc "sqrt(36e3 * 29e9 / (1 - 0.29 ^ 2))"); else kc=$(calc "sqrt(36e3 * 29e9)"); fi
  kdot=$(calc "$kc / $tc")
  end=$(calc "1.6 * $tc")
  cat << EOF
include $here/square.prm
subsection Geometry
  set Subdivisions = $cells, $cells
end
subsection Material
  set Two-dimensional model = plane $plane
end
subsection Peridynamics
  set Lattice spacing    = $dx
  set Horizon factor     = $m
  set Fracture criterion = $criterion
EOF
  if [ "$coupled" = 2 ]; then
    # Adaptive: PD on the crack and the tip, two horizons around them (rounded up to cells),
    # an overlap band of 2 cells; FE cells within 3 horizons of damage become PD, checked
    # every 20 steps.
    local delta h
    delta=$(calc "$m * $dx")
    h=$(calc "int((2 * $delta) / $c + 0.999) * $c")
    echo "  set Region = -$L, -$h : $h, $h"
    echo "end"
    cat << EOF
subsection Coupling
  set Method           = weak
  set Blending         = force
  set Damping constant = 10
  set Overlap width    = $(calc "2 * $c")
end
subsection Adaptive PD zone
  set Conversion criterion = damage distance
  set Check interval       = 20
  subsection damage distance
    set Distance = $(calc "3 * $delta")
  end
end
EOF
  elif [ "$coupled" = 1 ]; then
    # PD: x <= A c, |y| <= H c, with H and A from the kink (5 horizons at up to 61 degrees
    # plus 2 horizons of margin); overlaps of W = 2 cells.
    local delta H A W x1 y1 ox oy
    delta=$(calc "$m * $dx")
    H=$(calc "int((7 * $delta) / $c + 0.999)")
    A=$(calc "int((6 * $delta) / $c + 0.999)")
    W=2
    x1=$(calc "$A * $c"); y1=$(calc "$H * $c")
    ox=$(calc "($A + $W) * $c"); oy=$(calc "($H + $W) * $c")
    echo "  set Region = -$L, -$y1 : $x1, $y1"
    echo "end"
    cat << EOF
subsection Coupling
  set Method                = weak
  set Blending              = force
  set Damping constant      = 10
  set Overlap region        = -$L, $y1 : $ox, $oy ; -$L, -$oy : $ox, -$y1 ; $x1, -$y1 : $ox, $y1
  set Finite element region = -$L, $oy : $L, $L ; -$L, -$L : $L, -$oy ; $ox, -$oy : $L, $oy
end
EOF
  else
    echo "end"
  fi
  cat << EOF
subsection Boundary conditions
  subsection Crack tip field
    set Stress intensity factor = $kdot*t
    set Phase angle             = $psi
  end
end
subsection Time
  set Time step = $(calc "1e-7 * 128 / $n")
  set End time  = $end
end
subsection Output
  set Directory       = $name
  set Output interval = $(calc "int($end / (1e-7 * 128 / $n) + 0.5)")
end
EOF
}

# Each run writes its first and last state; the damage map of the last goes to
# <name>/damage.png.
run() {
  run_case "$@"
  "$scripts/plot_cracks.sh" "$1" > /dev/null 2>&1 || true
}

# Phase angles psi = atan(K_II / K_I): 0, and K_II / K_I = 0.25, 0.5, 1, 2.
angles="0 14.036 26.565 45 63.435"
tc=3e-4
for group in $groups; do
  case $group in
    angles)
      for psi in $angles; do run "pd_strain_$psi" strain "$psi" $tc 128 3 32 0; done ;;
    angles_m6)
      for psi in $angles; do run "pd_strain_${psi}_m6" strain "$psi" $tc 128 6 16 0; done ;;
    ramp)
      for psi in 0 45; do run "pd_strain_${psi}_slow" strain "$psi" 6e-4 128 3 32 0; done ;;
    convergence)
      # Mode I: dx halved at a fixed horizon factor (delta halved), and horizon factors
      # 4 to 12 at a fixed lattice (delta growing), 6 at the fine lattice.
      run pd_strain_0_n256_m3 strain 0 $tc 256 3 64 0
      run pd_strain_0_n256_m6 strain 0 $tc 256 6 32 0
      for m in 4 6; do run "pd_strain_0_n128_m$m" strain 0 $tc 128 $m 16 0; done
      for m in 8 12; do run "pd_strain_0_n128_m$m" strain 0 $tc 128 $m 8 0; done ;;
    coupled)
      for psi in $angles; do run "coupled_strain_$psi" strain "$psi" $tc 128 3 32 1; done
      run coupled8_strain_45 strain 45 $tc 128 3 16 1 ;;
    m6_coupled)
      # m = 6 through the coupling: the 256-site lattice leaves room for the PD box.
      run pd_strain_45_n256_m6 strain 45 $tc 256 6 32 0
      run coupled8_strain_45_n256_m6 strain 45 $tc 256 6 32 1 ;;
    m6_coupled_angles)
      # The same at the other phase angles.
      for psi in 14.036 26.565 63.435; do
        run "pd_strain_${psi}_n256_m6" strain "$psi" $tc 256 6 32 0
        run "coupled8_strain_${psi}_n256_m6" strain "$psi" $tc 256 6 32 1
      done ;;
    adaptive)
      # The m = 6 kinks of m6_coupled_angles with a PD zone that grows from the crack.
      for psi in 26.565 63.435; do
        run "adaptive8_strain_${psi}_n256_m6" strain "$psi" $tc 256 6 32 2
      done ;;
    bond_energy)
      # The "critical bond energy" criterion: mode I at m = 3, 6, 8 and three phase angles
      # at m = 6 (crack_energy_table.sh compares the mode-I runs with the critical stretch).
      for m in 3 6 8; do
        cells=$((m == 3 ? 32 : (m == 6 ? 16 : 8)))
        run "pd_strain_0_n128_m${m}_energy" strain 0 $tc 128 $m $cells 0 "critical bond energy"
      done
      for psi in 26.565 45 63.435; do
        run "pd_strain_${psi}_m6_energy" strain "$psi" $tc 128 6 16 0 "critical bond energy"
      done ;;
    stress)
      for psi in 0 45; do run "pd_stress_$psi" stress "$psi" $tc 128 3 32 0; done ;;
    *) echo "unknown group $group"; exit 1 ;;
  esac
done
# Every run is a directory (names may hold a decimal point).
runs=$({ ls -d pd_*/ coupled*/ adaptive*/ 2> /dev/null || true; } | sed 's|/$||' | grep -v '_energy$' | sort -u)
"$here/table.sh" $runs
energy_runs=$({ ls -d pd_*_energy/ 2> /dev/null || true; } | sed 's|/$||' | sort -u)
if [ -n "$energy_runs" ]; then
  "$here/table.sh" $energy_runs
  "$here/crack_energy_table.sh" pd_strain_0 pd_strain_0_n128_m6 pd_strain_0_n128_m8 \
    $(echo "$energy_runs" | grep '^pd_strain_0_') 2> /dev/null || true
fi
