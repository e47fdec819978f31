#!/bin/bash
# The quasi-static fracture study of this folder's README, in one command: the middle-tension
# specimen of parameter_files/quasi_static_middle_tension_2d.prm (glass, 40 x 80 mm, centre
# crack 2a = 12 mm, grips pulled apart in increments of 2 % of the LEFM failure displacement)
#   pd           pure PD, dx = 0.5 mm (the shipped case)
#   pd_fine      pure PD, dx = 0.25 mm (the same horizon factor: the horizon halves too)
#   band_force   PD in a 30 mm band around the crack plane, Q1 cells of 2.5 mm outside, strict
#                coupling with force blending (solved by relaxation)
#   band_energy  the same band with energy blending (solved by conjugate gradients)
#   adaptive     PD around the pre-crack only (15 x 10 mm), energy blending, growing with the
#                crack (damage distance)
# one after the other, one thread each, and prints the README's table (peak and first-break
# grip forces over the LEFM failure load, wall times) and draws the load-displacement curves
# (gnuplot) into <work>/load_displacement.png:
#   studies/quasi_static/run.sh <build directory> <work directory> [<runs>]
# About 4 minutes in all on one core (pd_fine 2 of them).
set -euo pipefail
usage="usage: studies/quasi_static/run.sh <build directory> <work directory> [<runs>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
runs=${3:-pd pd_fine band_force band_energy adaptive}
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$work"

# The coupled variants: FE cells of 2.5 mm, a 5 mm overlap of strict multipliers; FE grips
# are stiffer than the PD boundary layers of pure PD, so these runs go on to 24 increments.
coupled_lines() {
  local region=$1 blending=$2
  printf '%s\n' "subsection Geometry" "  set Subdivisions = 16, 32" "end" \
    "subsection Peridynamics" "  set Region = $region" "end" \
    "subsection Coupling" "  set Method = strict" "  set Blending = $blending" \
    "  set Overlap width = 0.005" "end" \
    "subsection Time" "  set Time step = 5e-8" "  set End time = 24" "end"
}

for run in $runs; do
  {
    echo "include $top/parameter_files/quasi_static_middle_tension_2d.prm"
    case $run in
      pd) ;;
      pd_fine)
        printf '%s\n' "subsection Peridynamics" "  set Lattice spacing = 2.5e-4" "end" \
          "subsection Time" "  set End time = 20" "end" ;;
      band_force) coupled_lines "0, 0.025 : 0.04, 0.055" force ;;
      band_energy) coupled_lines "0, 0.025 : 0.04, 0.055" energy ;;
      adaptive)
        coupled_lines "0.0125, 0.035 : 0.0275, 0.045" energy
        printf '%s\n' "subsection Adaptive PD zone" \
          "  set Conversion criterion = damage distance" "end" ;;
      *) echo "unknown run '$run'; known: pd pd_fine band_force band_energy adaptive" >&2; exit 1 ;;
    esac
    printf '%s\n' "subsection Output" "  set Directory = $work/$run" "  set Output interval = 0" \
      "  set Print timing summary = false" "end"
  } > "$run.prm"
  DEAL_II_NUM_THREADS=1 "$build/periarlequin" "$run.prm" > "$run.log" 2>&1
done

# The LEFM failure load per unit thickness: K_Ic = sqrt(E G0) with Feddersen's width
# correction, sigma_c W = K_Ic W / sqrt(pi a sec(pi a / W)).
lefm=$(awk 'BEGIN { pi = atan2(0, -1); E = 72e9; G0 = 3.8; W = 0.04; a = 0.006;
                    printf "%.6g", sqrt(E * G0) * W / sqrt(pi * a / cos(pi * a / W)) }')
echo "LEFM failure load sigma_c W = $lefm N/m"
echo "| run | PD particles at the end | grip force at the first break / LEFM | peak grip force / LEFM | grip displacement at the peak [um] | increments with breaks before the peak | broken bond ends at the end | static-solve iterations | wall time [s] |"
echo "|---|---|---|---|---|---|---|---|---|"
for run in $runs; do
  iterations=$(sed -n 's/^Quasi-static: .*increments, \([0-9]*\) static-solve iterations in \([0-9.e+-]*\) s.*/\1/p' "$run.log")
  seconds=$(sed -n 's/^Quasi-static: .*increments, \([0-9]*\) static-solve iterations in \([0-9.e+-]*\) s.*/\2/p' "$run.log")
  # The start-up line's particles, or the last growth's.
  particles=$(sed -n -e 's/.* FE DoFs, \([0-9]*\) PD particles.*/\1/p' \
    -e 's/.* FE cells became PD; now \([0-9]*\) particles.*/\1/p' "$run.log" | tail -1)
  awk -F, -v run="$run" -v lefm="$lefm" -v its="$iterations" -v s="$seconds" -v particles="$particles" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    {
      f = $col["reaction_boundary3_y"]; u = $col["displacement_boundary3_y"]; b = $col["broken_bonds"]
      if (NR == 2) start = b
      if (first == "" && b > start) first = f
      if (NR > 2 && b > previous) ++growing
      if (f > peak) { peak = f; upeak = u; growing_at_peak = growing }
      previous = b
      print 1e6 * u, f / lefm > (run "/load_displacement.dat")
    }
    END { printf "| %s | %s | %.3f | %.3f | %.2f | %d | %d | %s | %.1f |\n", run, particles,
                 first / lefm, peak / lefm, 1e6 * upeak, growing_at_peak, b - start, its, s }' \
    "$run/solution_energy.csv"
done

plots=""
for run in $runs; do
  plots="$plots${plots:+, }'$run/load_displacement.dat' using 1:2 with linespoints title '$run'"
done
gnuplot -e "set terminal pngcairo size 800,550 noenhanced;
  set output 'load_displacement.png'; set key top left;
  set xlabel 'grip displacement [um]'; set ylabel 'grip force / LEFM failure load';
  set yrange [0:1.2]; plot $plots"
echo "wrote the runs, the table's histories and load_displacement.png to $work"
