#!/bin/bash
# Figures of an adaptive PD zone (Postprocess/List of postprocessors with "zone sizes" and
# "cracks") from its output directory (Debian: gnuplot-nox):
#   scripts/plot_zone.sh <output directory> [<step> ...]
# writes <dir>/zone_<step>.png for each step given (default: every written step): the pure PD
# region (shaded boxes, and on a 2D Gmsh mesh the converted cells) with the damaged particles
# of the same step on top, and
# <dir>/zone_size.png, the PD particles and FE DoFs against time.
set -euo pipefail
dir=${1:?usage: plot_zone.sh <output directory> [<step> ...]}
shift
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
steps=("$@")
if [ ${#steps[@]} = 0 ]; then
  for f in "$dir"/*_pd_region_*.csv; do
    s=${f##*_pd_region_}
    steps+=("${s%.csv}")
  done
fi
energy=$(ls "$dir"/*_energy.csv | head -1)
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
for step in "${steps[@]}"; do
  step=$(printf %06d "$((10#$step))")
  region=$(ls "$dir"/*_pd_region_"$step".csv)
  map=$(ls "$dir"/*_damage_"$step".csv 2> /dev/null || true)
  {
    echo "set datafile separator ','; set terminal pngcairo size 900,900 noenhanced"
    echo "set output '$dir/zone_$step.png'; set size ratio -1; set xlabel 'x [m]'; set ylabel 'y [m]'"
    if [ -n "$map" ]; then
      head -1 "$map" | awk '{ printf "set xrange [%s:%s]; set yrange [%s:%s]\n", $7, $9, $8, $10 }'
    fi
    echo "set title 'pure PD region (shaded) and damage > 0.35 at $(head -1 "$region" | sed 's/^# //')'"
    plot="plot '$region' skip 2 using (\$1+\$3)/2:(\$2+\$4)/2:1:3:2:4 with boxxyerror fs solid 0.25 lc rgb '#4575b4' title 'PD region'"
    cells=$(ls "$dir"/*_pd_cells_"$step".csv 2> /dev/null || true)
    if [ -n "$cells" ]; then
      # Each cell a closed polygon (vertices 0, 1, 3, 2 in deal.II's order), blank-line separated.
      awk -F, 'NR > 1 { printf "%s,%s\n%s,%s\n%s,%s\n%s,%s\n%s,%s\n\n", $1, $2, $3, $4, $7, $8, $5, $6, $1, $2 }' \
        "$cells" > "$dir/zone_cells_$step.csv"
      plot="$plot, '$dir/zone_cells_$step.csv' using 1:2 with filledcurves closed fs solid 0.25 lc rgb '#4575b4' notitle"
    fi
    if [ -n "$map" ]; then
      plot="$plot, '$map' skip 2 using 1:(\$3 > 0.35 ? \$2 : 1/0) with points pt 5 ps 0.2 lc rgb '#b2182b' title 'cracked'"
    fi
    echo "$plot"
  } | gnuplot
done
t=$(column "$energy" time)
{
  echo "set datafile separator ','; set terminal pngcairo size 900,500 noenhanced"
  echo "set output '$dir/zone_size.png'; set xlabel 'time [s]'; set ylabel 'PD particles'"
  echo "set y2label 'FE DoFs'; set y2tics; set ytics nomirror; set key left top"
  echo "plot '$energy' using $t:$(column "$energy" pd_particles) with lines lw 2 title 'PD particles', '$energy' using $t:$(column "$energy" fe_dofs) axes x1y2 with lines title 'FE DoFs'"
} | gnuplot
echo "wrote the zone figures in $dir"
