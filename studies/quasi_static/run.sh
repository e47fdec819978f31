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
# and the single-edge-notched beam in three-point bending of three_point_bending.prm (PD around
# the notch coupled to FE on the mesh three_point_bending.msh)
#   seb          as shipped, dx = 0.5 mm
#   seb_fine     dx = 0.25 mm (the horizon halves too), from 90 % of the LEFM failure deflection
# one after the other, one thread each, and prints the README's tables (peak and first-break
# forces over the LEFM failure load, wall times) and draws the load-displacement curves
# (gnuplot) into <work>/load_displacement.png and <work>/bending.png:
#   studies/quasi_static/run.sh <build directory> <work directory> [<runs>]
# About 4 minutes for the M(T) runs on one core (pd_fine 2 of them), 6 for seb, 40 for seb_fine.
set -euo pipefail
usage="usage: studies/quasi_static/run.sh <build directory> <work directory> [<runs>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
runs=${3:-pd pd_fine band_force band_energy adaptive seb seb_fine}
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
    case $run in
      seb*) echo "include $here/three_point_bending.prm"
            printf '%s\n' "subsection Geometry" "  set Mesh file = $here/three_point_bending.msh" "end" ;;
      *) echo "include $top/parameter_files/quasi_static_middle_tension_2d.prm" ;;
    esac
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
      seb) ;;
      seb_fine)
        printf '%s\n' "subsection Peridynamics" "  set Lattice spacing = 2.5e-4" "end" \
          "subsection Boundary conditions" "  subsection Boundary 2" "    subsection Function" \
          "      set Function expression = 0; -8.82e-6 * (0.9 + 0.02 * t)" "    end" "  end" "end" \
          "subsection Time" "  set End time = 20" "end" ;;
      *) echo "unknown run '$run'; known: pd pd_fine band_force band_energy adaptive seb seb_fine" >&2; exit 1 ;;
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
middle_tension_runs=$(printf '%s\n' $runs | grep -v '^seb' | tr '\n' ' ' || true)
bending_runs=$(printf '%s\n' $runs | grep '^seb' | tr '\n' ' ' || true)
if [ -n "$middle_tension_runs" ]; then
  echo "LEFM failure load sigma_c W = $lefm N/m"
  echo "| run | PD particles at the end | grip force at the first break / LEFM | peak grip force / LEFM | grip displacement at the peak [um] | increments with breaks before the peak | broken bond ends at the end | static-solve iterations | wall time [s] |"
  echo "|---|---|---|---|---|---|---|---|---|"
fi
solver_figures() { # run -> "iterations seconds" of its static solves
  sed -n 's/^Quasi-static: .*increments, \([0-9]*\) static-solve iterations in \([0-9.e+-]*\) s.*/\1 \2/p' "$1.log"
}
for run in $middle_tension_runs; do
  read -r iterations seconds <<< "$(solver_figures "$run")"
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

# The curves <run>/<data> of the runs <runs> into <figure>: plot_curves data figure xlabel ylabel runs...
plot_curves() {
  local data=$1 figure=$2 xlabel=$3 ylabel=$4 plots="" run
  shift 4
  for run in "$@"; do
    plots="$plots${plots:+, }'$run/$data' using 1:2 with linespoints title '$run'"
  done
  [ -z "$plots" ] || gnuplot -e "set terminal pngcairo size 800,550 noenhanced;
    set output '$figure'; set key top left; set xlabel '$xlabel'; set ylabel '$ylabel';
    set yrange [0:1.2]; plot $plots"
}
plot_curves load_displacement.dat load_displacement.png 'grip displacement [um]' \
  'grip force / LEFM failure load' $middle_tension_runs

# The beam: the LEFM load of a crack a deep, P(a) = K_Ic W^{3/2} / (S f(a / W)), f of ASTM
# E399 for S / W = 4; P_c = P(25 mm).
if [ -n "$bending_runs" ]; then
  echo
  echo "| run | PD particles | punch force at the first break / P_c | peak / P_c | deflection at the peak / 8.82 um | increments with breaks before the peak | crack extension at the end [mm] | force at the end / LEFM force of that crack | static-solve iterations | wall time [s] |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
fi
for run in $bending_runs; do
  read -r iterations seconds <<< "$(solver_figures "$run")"
  particles=$(sed -n 's/.* FE DoFs, \([0-9]*\) PD particles.*/\1/p' "$run.log")
  awk -F, -v run="$run" -v its="$iterations" -v s="$seconds" -v particles="$particles" '
    function lefm(a,   x, f) {
      x = a / 0.05
      f = 3 * sqrt(x) * (1.99 - x * (1 - x) * (2.15 - 3.93 * x + 2.7 * x * x)) / (2 * (1 + 2 * x) * (1 - x) ^ 1.5)
      return sqrt(72e9 * 3.8) * 0.05 ^ 1.5 / (0.2 * f)
    }
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; pc = lefm(0.025); next }
    {
      f = -$col["reaction_boundary2_y"]; u = -$col["displacement_boundary2_y"]; b = $col["broken_bonds"]
      if (NR == 2) start = b
      if (first == "" && b > start) first = f
      if (NR > 2 && b > previous) ++growing
      if (f > peak) { peak = f; upeak = u; growing_at_peak = growing }
      previous = b; extension = $col["crack_extension"]
      print 1e6 * u / 8.82, f / pc > (run "/load_deflection.dat")
    }
    END { printf "| %s | %s | %.3f | %.3f | %.2f | %d | %.1f | %.3f | %s | %.1f |\n", run, particles,
                 first / pc, peak / pc, 1e6 * upeak / 8.82, growing_at_peak, 1e3 * extension,
                 f / lefm(0.025 + extension), its, s }' "$run/solution_energy.csv"
done
plot_curves load_deflection.dat bending.png 'punch deflection / LEFM failure deflection' \
  'punch force / LEFM failure load' $bending_runs
echo "wrote the runs, the tables' histories and the figures to $work"
