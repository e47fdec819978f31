#!/bin/bash
# The adaptive PD zone study of this folder's README, in one command: the crack-branching plate
# (pure PD, the best fixed strip and the adaptive runs of ../crack_branching, made by its
# run.sh into <work>/branching), the mixed-mode kinks that the zone follows (the adaptive group
# of ../mixed_mode and the pure-PD and fixed-box runs it is compared with, into
# <work>/mixed_mode), and the zone figures of the shipped case
# parameter_files/adaptive_crack_branching_2d.prm (scripts/plot_zone.sh, into <work>/zone):
#   studies/adaptive_zone/run.sh <build directory> <work directory> [<mpi ranks>] [<parts>]
# <parts> (default: all but 3d): branching, kink, figures, impact, spall, gmsh, 3d. About 40
# minutes for branching, 50 for kink, 2 for impact, 1 for spall and 1 for gmsh on one core;
# 3d: the 3D plate of plate_3d.prm (1.1 million particles in pure PD, 2 GB) as pure PD and
# adaptive from PD around the notch (the default band of two FE cells, 5 mm, and a band of
# 10 mm; RUNS_3D selects among pd, damage_distance and band_10mm), each once, on <mpi ranks>
# ranks of one thread (two ranks: about 10 minutes); prints
# the table of the README and draws the damage maps. impact: the impact-driven
# mode II plate of impact_mode_ii.prm as pure PD and adaptive (default adaptive settings; with
# the strain criterion added; checked every 50 steps), one thread each, one after the other;
# prints the table of the README and draws the damage maps (into <work>/impact). spall: the
# strip of spall_strip.prm as pure PD and adaptive from PD on [40, 50] mm (damage distance;
# with strain; with strain and without settling); prints the table of the README. gmsh: the
# plate with a hole of hole_stretch.prm (a Gmsh mesh) as pure PD and adaptive from PD around
# the hole (damage distance; with strain), three repeats side by side, one thread each; prints
# the tables of the README.
set -euo pipefail
usage="usage: studies/adaptive_zone/run.sh <build directory> <work directory> [<mpi ranks>] [<parts>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
parts=${4:-branching kink figures impact spall gmsh}
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)

# The lines that make a pure-PD case adaptive: PD first on <region>, weak coupling with force
# blending across a band of width $band (default two FE cells of the box meshes, 5 mm),
# Conversion criterion = <criterion>, then any further lines of subsection "Adaptive PD zone".
band=0.005
adaptive_lines() {
  local region=$1 criterion=$2
  shift 2
  printf '%s\n' "subsection Peridynamics" "  set Region = $region" "end" \
    "subsection Coupling" "  set Method        = weak" "  set Blending      = force" \
    "  set Overlap width = $band" "end" \
    "subsection Adaptive PD zone" "  set Conversion criterion = $criterion" "$@" "end"
}

for part in $parts; do
  case $part in
    branching)
      "$here/../crack_branching/run.sh" "$build" "$work/branching" "$ranks" \
        "pd_120 coupled8_120_narrow adaptive8_120 adaptive16_120 adaptive8_120_d3.75 adaptive8_120_d7.5 adaptive8_120_band3" ;;
    kink)
      "$here/../mixed_mode/run.sh" "$build" "$work/mixed_mode" "$ranks" "m6_coupled_angles adaptive" ;;
    figures)
      mkdir -p "$work/zone"
      {
        echo "include $top/parameter_files/adaptive_crack_branching_2d.prm"
        echo "subsection Output"
        echo "  set Directory = $work/zone"
        echo "end"
      } > "$work/zone.prm"
      mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$work/zone.prm" > "$work/zone.log" 2>&1
      "$top/scripts/plot_zone.sh" "$work/zone" > /dev/null
      echo "wrote the zone figures to $work/zone" ;;
    impact)
      mkdir -p "$work/impact"
      cd "$work/impact"
      for run in pd adaptive adaptive_strain adaptive_interval50; do
        {
          echo "include $here/impact_mode_ii.prm"
          # PD first on the notches and the struck edge between them.
          case $run in
            adaptive) adaptive_lines "0, 0.07 : 0.0525, 0.13" "damage distance" ;;
            adaptive_strain) adaptive_lines "0, 0.07 : 0.0525, 0.13" "damage distance, strain" ;;
            adaptive_interval50)
              adaptive_lines "0, 0.07 : 0.0525, 0.13" "damage distance" "  set Check interval = 50" ;;
          esac
          echo "subsection Output"
          echo "  set Directory = $work/impact/$run"
          echo "end"
        } > "$run.prm"
        DEAL_II_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$ranks" \
          "$build/periarlequin" "$run.prm" > "$run.log" 2>&1
      done
      echo "| run | time loop [s] | growth [s] | PD particles at the end | broken-bond energy at 30 / 60 / 90 us [J/m] | tips at 30 us (x, y) [mm] |"
      echo "|---|---|---|---|---|---|"
      for run in pd adaptive adaptive_strain adaptive_interval50; do
        loop=$(sed -n 's/^Time loop: .* in \([0-9.e+-]*\) s.*/\1/p' "$run.log")
        growth=$(awk -F'|' '$2 ~ /^ *PD zone growth/ { gsub(/[ s]/, "", $4); print $4 }' "$run.log")
        awk -F, -v run="$run" -v loop="$loop" -v growth="${growth:-0}" '
          NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
          { step = $1 }
          step == 300 { tips = sprintf("(%.1f, %.1f), (%.1f, %.1f)", 1e3 * $col["branch_0_x"], 1e3 * $col["branch_0_y"],
                                       1e3 * $col["branch_1_x"], 1e3 * $col["branch_1_y"]) }
          step == 300 || step == 600 || step == 900 { energy = energy (energy == "" ? "" : " / ") sprintf("%.0f", $col["broken_bond_energy"]) }
          { particles = $col["pd_particles"] }
          END { printf "| %s | %.1f | %.1f | %d | %s | %s |\n", run, loop, growth, particles, energy, tips }' \
          "$run/solution_energy.csv"
      done
      for step in 300 600 900; do
        "$top/scripts/plot_zone.sh" adaptive "$step" > /dev/null
        "$top/scripts/plot_zone.sh" adaptive_strain "$step" > /dev/null
        gnuplot -e "set datafile separator ','; set terminal pngcairo size 500,900 noenhanced;
          set output 'pd/damage_$step.png'; set size ratio -1; set xrange [0:0.1]; set yrange [0:0.2];
          set title 'pure PD, damage > 0.35, step $step'; set xlabel 'x [m]'; set ylabel 'y [m]';
          plot 'pd/solution_damage_$(printf %06d "$step").csv' skip 2 using 1:(\$3 > 0.35 ? \$2 : 1/0) with points pt 5 ps 0.2 lc rgb '#b2182b' notitle"
      done
      cd "$top"
      echo "wrote the impact runs and figures to $work/impact" ;;
    spall)
      mkdir -p "$work/spall"
      cd "$work/spall"
      for run in pd damage_distance strain strain_unsettled; do
        {
          echo "include $here/spall_strip.prm"
          case $run in
            damage_distance) adaptive_lines "0.04, 0 : 0.05, 0.01" "damage distance" ;;
            strain) adaptive_lines "0.04, 0 : 0.05, 0.01" "damage distance, strain" ;;
            strain_unsettled)
              adaptive_lines "0.04, 0 : 0.05, 0.01" "damage distance, strain" "  set Settling time = -1" ;;
          esac
          echo "subsection Output"
          echo "  set Directory = $work/spall/$run"
          echo "end"
        } > "$run.prm"
        DEAL_II_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$ranks" \
          "$build/periarlequin" "$run.prm" > "$run.log" 2>&1 || true
      done
      echo "| run | end [µs] | first break beyond x = 50 mm [µs] | its mean x [mm] | damaged particles beyond 50 mm at the end, mean x [mm] | broken bonds at the end | PD particles at the end |"
      echo "|---|---|---|---|---|---|---|"
      for run in pd damage_distance strain strain_unsettled; do
        # The damage maps in time order: the first with damage beyond mid-length, and the last.
        first=$(for f in "$run"/solution_damage_*.csv; do
                  awk -F, 'NR == 1 { t = $0; sub(/^# t = /, "", t); sub(/ s.*/, "", t) }
                           NR > 2 && $1 > 0.05 && $3 > 0 { n++; x += $1 }
                           END { if (n > 0) printf "%.2f %.1f\n", 1e6 * t, 1e3 * x / n }' "$f"
                done | awk 'NR == 1')
        last=$(ls "$run"/solution_damage_*.csv | tail -1)
        awk -F, -v run="$run" -v first="${first:--}" -v last="$last" '
          NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
          { t = $col["time"]; broken = $col["broken_bonds"]; particles = $col["pd_particles"] }
          END {
            n = 0; x = 0
            while ((getline line < last) > 0) { split(line, v, ","); if (v[1] + 0 > 0.05 && v[3] + 0 > 0) { n++; x += v[1] } }
            split(first, f, " ")
            printf "| %s | %.2f | %s | %s | %s | %d | %d |\n", run, 1e6 * t, (f[1] == "" ? "-" : f[1]),
                   (f[2] == "" ? "-" : f[2]), (n > 0 ? sprintf("%.1f (%d)", 1e3 * x / n, n) : "-"), broken, particles }' \
          "$run/solution_energy.csv"
      done
      cd "$top"
      echo "wrote the spall runs to $work/spall" ;;
    gmsh)
      mkdir -p "$work/gmsh"
      cd "$work/gmsh"
      runs="pd damage_distance strain"
      band=0.008 # the unstructured cells are about 4.5 mm
      for run in $runs; do
        {
          echo "include $here/hole_stretch.prm"
          echo "subsection Geometry"
          echo "  set Mesh file = $top/examples/gmsh/plate_with_hole.msh"
          echo "end"
          case $run in
            damage_distance) adaptive_lines "0.035, 0.01 : 0.065, 0.04" "damage distance" ;;
            strain) adaptive_lines "0.035, 0.01 : 0.065, 0.04" "damage distance, strain" ;;
          esac
          echo "subsection Output"
          echo "  set Directory = $work/gmsh/$run"
          echo "end"
        } > "$run.prm"
      done
      # Three repeats, the runs of a repeat one after the other (ratios within a repeat).
      for repeat in 1 2 3; do
        for run in $runs; do
          DEAL_II_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$ranks" \
            "$build/periarlequin" "$run.prm" > "$run.$repeat.log" 2>&1
        done
      done
      echo "| run | time loop [s], 3 repeats | median / pure PD | growth [s] (median) | PD particles at the end | first break [µs] | broken-bond energy at 10 / 16 / 24 µs [J/m] |"
      echo "|---|---|---|---|---|---|---|"
      pd_median=""
      for run in $runs; do
        loops=$(for repeat in 1 2 3; do sed -n 's/^Time loop: .* in \([0-9.e+-]*\) s.*/\1/p' "$run.$repeat.log"; done)
        median=$(echo "$loops" | sort -g | sed -n 2p)
        pd_median=${pd_median:-$median}
        growth=$(for repeat in 1 2 3; do awk -F'|' '$2 ~ /^ *PD zone growth/ { gsub(/[ s]/, "", $4); print $4 }' "$run.$repeat.log"; done | sort -g | sed -n 2p)
        awk -F, -v run="$run" -v loops="$(echo $loops | sed 's/ /, /g')" -v ratio="$(awk -v a="$median" -v b="$pd_median" 'BEGIN { printf "%.2f", a / b }')" -v growth="${growth:-0}" '
          NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
          first == "" && $col["broken_bonds"] > 0 { first = sprintf("%.1f", 1e6 * $col["time"]) }
          $1 == 250 || $1 == 400 || $1 == 600 { energy = energy (energy == "" ? "" : " / ") sprintf("%.3f", $col["broken_bond_energy"]) }
          { particles = $col["pd_particles"] }
          END { printf "| %s | %s | %s | %.2f | %d | %s | %s |\n", run, loops, ratio, growth, particles, first, energy }' \
          "$run/solution_energy.csv"
      done
      echo
      echo "Crack tips (x, y) [mm] of the branches, in the order of their text:"
      for run in $runs; do
        awk -F, -v run="$run" '
          NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
          $1 == 250 || $1 == 300 || $1 == 350 || $1 == 400 {
            n = 0
            for (b = 0; b < 4; ++b)
              if ($col["branch_" b "_x"] != "nan")
                {
                  tip = sprintf("(%.1f, %.1f)", 1e3 * $col["branch_" b "_x"], 1e3 * $col["branch_" b "_y"])
                  for (k = n++; k > 0 && tips[k - 1] > tip; --k)
                    tips[k] = tips[k - 1]
                  tips[k] = tip
                }
            line = ""
            for (k = 0; k < n; ++k)
              line = line " " tips[k]
            printf "%s at %.0f us:%s\n", run, 1e6 * $col["time"], line
          }' "$run/solution_energy.csv"
      done
      for step in 300 400; do
        "$top/scripts/plot_zone.sh" damage_distance "$step" > /dev/null
        gnuplot -e "set datafile separator ','; set terminal pngcairo size 900,900 noenhanced;
          set output 'pd/damage_$step.png'; set size ratio -1; set xrange [0:0.1]; set yrange [0:0.05];
          set title 'pure PD, damage > 0.35, step $step'; set xlabel 'x [m]'; set ylabel 'y [m]';
          plot 'pd/solution_damage_$(printf %06d "$step").csv' skip 2 using 1:(\$3 > 0.35 ? \$2 : 1/0) with points pt 5 ps 0.2 lc rgb '#b2182b' notitle"
      done
      cd "$top"
      echo "wrote the Gmsh runs and figures to $work/gmsh" ;;
    3d)
      mkdir -p "$work/3d"
      cd "$work/3d"
      runs="${RUNS_3D:-pd damage_distance band_10mm}"
      for run in $runs; do
        {
          echo "include $here/plate_3d.prm"
          case $run in
            damage_distance) band=0.005 adaptive_lines "0, 0.02, 0 : 0.04, 0.03, 0.01" "damage distance" ;;
            band_10mm) band=0.01 adaptive_lines "0, 0.02, 0 : 0.04, 0.03, 0.01" "damage distance" ;;
          esac
          echo "subsection Output"
          echo "  set Directory = $work/3d/$run"
          echo "end"
        } > "$run.prm"
        DEAL_II_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np "$ranks" \
          "$build/periarlequin" "$run.prm" > "$run.log" 2>&1 || true
      done
      echo "| run | set-up [s] | time loop [s] | growth [s] | PD particles at 0 / 12 / 24 / 36 µs | broken-bond energy at 12 / 24 / 36 µs [J] | leading tip x at 12 / 24 / 36 µs [mm] |"
      echo "|---|---|---|---|---|---|---|"
      for run in $runs; do
        setup=$(awk -F'|' '$2 ~ /^ *setup *$/ { gsub(/[ s]/, "", $4); print $4 }' "$run.log")
        loop=$(sed -n 's/^Time loop: .* in \([0-9.e+-]*\) s.*/\1/p' "$run.log")
        growth=$(awk -F'|' '$2 ~ /^ *PD zone growth/ { gsub(/[ s]/, "", $4); print $4 }' "$run.log")
        awk -F, -v run="$run" -v setup="$setup" -v loop="$loop" -v growth="${growth:-0}" '
          NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
          { lead = 0
            for (b = 0; b < 4; ++b)
              if ($col["branch_" b "_x"] != "nan" && $col["branch_" b "_x"] > lead) lead = $col["branch_" b "_x"] }
          $1 == 0 || $1 == 120 || $1 == 240 || $1 == 360 { particles = particles (particles == "" ? "" : " / ") $col["pd_particles"] }
          $1 == 120 || $1 == 240 || $1 == 360 {
            energy = energy (energy == "" ? "" : " / ") sprintf("%.4f", $col["broken_bond_energy"])
            tips = tips (tips == "" ? "" : " / ") sprintf("%.1f", 1e3 * lead) }
          END { printf "| %s | %s | %s | %s | %s | %s | %s |\n", run, setup, loop, growth, particles, energy, tips }' \
          "$run/solution_energy.csv"
      done
      for run in $runs; do
        for map in "$run"/solution_damage_*.csv; do
          step=${map##*_}
          step=${step%.csv}
          gnuplot -e "set datafile separator ','; set terminal pngcairo size 900,600 noenhanced;
            set output '$run/damage_$step.png'; set size ratio -1; set xrange [0:0.1]; set yrange [0:0.05];
            set title '$run, damage > 0.35 (all z), step $((10#$step))'; set xlabel 'x [m]'; set ylabel 'y [m]';
            plot '$map' skip 2 using 1:(\$4 > 0.35 ? \$2 : 1/0) with points pt 5 ps 0.2 lc rgb '#b2182b' notitle"
        done
      done
      cd "$top"
      echo "wrote the 3D runs and figures to $work/3d" ;;
    *) echo "unknown part $part" >&2; exit 1 ;;
  esac
done
