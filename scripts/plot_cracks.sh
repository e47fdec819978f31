#!/bin/bash
# Figures of a crack run (Postprocess/List of postprocessors with "cracks") from its output
# directory (Debian: gnuplot-nox):
#   scripts/plot_cracks.sh <output directory> [<reference output directory>] [<step>]
# writes <dir>/damage.png, the damage map of the last written step (or <step>) like the
# paper's figs. 13 and 18 (particles coloured by damage, the cracked ones dark), and
# <dir>/tips.png, the tip position x and path length of each branch against time, with the
# reference's dashed if given (e.g. pure PD for a coupled run).
set -euo pipefail
dir=${1:?usage: plot_cracks.sh <output directory> [<reference output directory>] [<step>]}
ref=${2:-}
step=${3:-}
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
energy=$(ls "$dir"/*_energy.csv | head -1)
if [ -n "$step" ]; then
  map=$(ls "$dir"/*_damage_$(printf %06d "$step").csv)
else
  map=$(ls "$dir"/*_damage_*.csv | sort | tail -1)
fi
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
time_of() { head -1 "$1" | sed 's/^# t = \([^ ]*\) s.*/\1/'; }
# x and y ranges of the model from the map's first line "# t = <t> s; domain x0 y0 [z0] x1 y1 [z1]"
ranges() { head -1 "$1" | awk '{ n = (NF - 6) / 2; printf "set xrange [%s:%s]; set yrange [%s:%s]", $7, $(7 + n), $8, $(8 + n) }'; }
branches() { head -1 "$1" | tr ',' '\n' | sed -n 's/^branch_\([0-9]*\)_x$/\1/p'; }
{
  echo "set datafile separator ','; set terminal pngcairo size 1000,500 noenhanced"
  echo "set output '$dir/damage.png'; set size ratio -1; set xlabel 'x [m]'; set ylabel 'y [m]'"
  echo "set title 'damage at t = $(time_of "$map") s'; set cbrange [0:0.6]; $(ranges "$map")"
  echo "set palette defined (0 '#f0f0f0', 0.2 '#fdae61', 0.35 '#d7191c', 0.6 '#2b0000')"
  # The damage column: 3 in 2D, 4 in 3D (a 3D map is seen along z, its layers overlaid).
  echo "plot '$map' skip 2 using 1:2:$(sed -n 2p "$map" | tr ',' '\n' | grep -nx damage | cut -d: -f1) with points pt 5 ps 0.25 palette notitle"
  echo "set output '$dir/tips.png'; set size noratio; unset cbrange; set autoscale; set title ''"
  echo "set xlabel 'time [s]'; set ylabel 'tip x, path length [m]'; set key left top"
  t=$(column "$energy" time)
  plots=()
  for b in $(branches "$energy"); do
    plots+=("'$energy' using $t:$(column "$energy" branch_${b}_x) with lines lw 2 title 'branch $b: tip x'")
    plots+=("'$energy' using $t:$(column "$energy" branch_${b}_path_length) with lines title 'branch $b: path length'")
  done
  if [ -n "$ref" ]; then
    re=$(ls "$ref"/*_energy.csv | head -1)
    for b in $(branches "$re"); do
      plots+=("'$re' using $(column "$re" time):$(column "$re" branch_${b}_x) with lines dt 2 lw 2 title 'reference branch $b: tip x'")
    done
  fi
  (IFS=','; echo "plot ${plots[*]}")
} | gnuplot
echo "wrote $dir/damage.png and $dir/tips.png"
