#!/bin/bash
# The projectile impact study of this folder's README in one command: the glass plate of
# plate.prm struck by a rigid steel disc, as pure PD and as adaptive runs that start PD on a
# 30 x 20 mm box under the impact point (weak coupling, force blending, a band of two FE cells,
# 5 mm; conversion by damage distance, and by damage distance and strain, default settings
# otherwise), one after the other on <mpi ranks> ranks (default 1) of the default threads:
#   studies/projectile_impact/run.sh <build directory> <work directory> [<mpi ranks>] [<runs>]
# <runs> (default: pd adaptive adaptive_strain). Prints the table of the README and draws the
# damage maps (pure PD) and zone figures (adaptive) at 20, 40 and 60 us into <work>. About a
# minute and a half for pure PD on two threads.
set -euo pipefail
usage="usage: studies/projectile_impact/run.sh <build directory> <work directory> [<mpi ranks>] [<runs>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
runs=${4:-pd adaptive adaptive_strain}
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work"

for run in $runs; do
  {
    echo "include $here/plate.prm"
    case $run in
      adaptive | adaptive_strain)
        criterion="damage distance"
        [ "$run" = adaptive_strain ] && criterion="damage distance, strain"
        printf '%s\n' "subsection Peridynamics" "  set Region = 0.085, 0.08 : 0.115, 0.1" "end" \
          "subsection Coupling" "  set Method        = weak" "  set Blending      = force" \
          "  set Overlap width = 0.005" "end" \
          "subsection Adaptive PD zone" "  set Conversion criterion = $criterion" "end" ;;
    esac
    echo "subsection Output"
    echo "  set Directory = $work/$run"
    echo "end"
  } > "$run.prm"
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$run.prm" > "$run.log" 2>&1
done

echo "| run | time loop [s] | growth [s] | PD particles at the end | broken-bond energy at 20 / 40 / 60 us [J/m] | largest contact force [MN/m] | rebound velocity [m/s] |"
echo "|---|---|---|---|---|---|---|"
for run in $runs; do
  loop=$(sed -n 's/^Time loop: .* in \([0-9.e+-]*\) s.*/\1/p' "$run.log")
  growth=$(awk -F'|' '$2 ~ /^ *PD zone growth/ { gsub(/[ s]/, "", $4); print $4 }' "$run.log")
  awk -F, -v run="$run" -v loop="$loop" -v growth="${growth:-0}" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    { step = $1; force = -$col["contact_force_y"]; if (force > largest) largest = force }
    step == 800 || step == 1600 || step == 2400 { energy = energy (energy == "" ? "" : " / ") sprintf("%.2f", $col["broken_bond_energy"]) }
    { particles = $col["pd_particles"]; rebound = $col["projectile_velocity_y"] }
    END { printf "| %s | %.1f | %.1f | %d | %s | %.2f | %.2f |\n", run, loop, growth, particles, energy, 1e-6 * largest, rebound }' \
    "$run/solution_energy.csv"
done

for step in 800 1600 2400; do
  for run in $runs; do
    if [ "$run" = pd ]; then
      gnuplot -e "set datafile separator ','; set terminal pngcairo size 1000,560 noenhanced;
        set output '$work/pd/damage_$step.png'; set size ratio -1; set xrange [0:0.2]; set yrange [0:0.1];
        set title 'pure PD, damage > 0.35, step $step'; set xlabel 'x [m]'; set ylabel 'y [m]';
        plot '$work/pd/solution_damage_$(printf %06d "$step").csv' skip 2 using 1:(\$3 > 0.35 ? \$2 : 1/0) with points pt 5 ps 0.2 lc rgb '#b2182b' notitle"
    else
      "$top/scripts/plot_zone.sh" "$work/$run" "$step" > /dev/null
    fi
  done
done
echo "wrote the runs and figures to $work"
