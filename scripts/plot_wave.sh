#!/bin/bash
# Figures like the paper's fig. 9-11 from a run's output directory (Debian: gnuplot-nox):
#   scripts/plot_wave.sh <output directory> [<reference output directory>]
# writes <dir>/energy.png (total, kinetic and strain energy of the pure PD zone against time,
# with the reference's pure-PD energy if given) and <dir>/centre_line.png (u_x along the
# sample line at the last written step, FE nodes and PD particles, with the reference).
set -euo pipefail
dir=${1:?usage: plot_wave.sh <output directory> [<reference output directory>]}
ref=${2:-}
command -v gnuplot > /dev/null || { echo "gnuplot is missing: apt-get install gnuplot-nox" >&2; exit 1; }
energy=$(ls "$dir"/*_energy.csv | head -1)
line=$(ls "$dir"/*_line_*.csv 2> /dev/null | sort | tail -1 || true)
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
t=$(column "$energy" time); k=$(column "$energy" pure_pd_kinetic_energy)
s=$(column "$energy" pure_pd_strain_energy); e=$(column "$energy" pure_pd_energy)
{
  echo "set datafile separator ','; set terminal pngcairo size 900,600 noenhanced"
  echo "set output '$dir/energy.png'; set xlabel 'time [s]'; set ylabel 'energy of the pure PD zone [J]'"
  echo -n "plot '$energy' using $t:$e with lines title 'total', '' using $t:$k with lines title 'kinetic', '' using $t:$s with lines title 'strain'"
  if [ -n "$ref" ]; then
    re=$(ls "$ref"/*_energy.csv | head -1)
    echo -n ", '$re' using $(column "$re" time):$(column "$re" pure_pd_energy) with lines dt 2 title 'pure-PD reference'"
  fi
  echo
  if [ -n "$line" ]; then
    echo "set output '$dir/centre_line.png'; set xlabel 'x [m]'; set ylabel 'u_x [m]'"
    echo -n "plot '< grep ^pd $line' using 2:4 with points pt 7 ps 0.3 title 'PD', '< grep ^fe $line' using 2:4 with linespoints pt 6 title 'FE'"
    if [ -n "$ref" ]; then
      rl=$(ls "$ref"/*_line_*.csv | sort | tail -1)
      echo -n ", '< grep ^pd $rl' using 2:4 with lines dt 2 title 'pure-PD reference'"
    fi
    echo
  fi
} | gnuplot
echo "wrote $dir/energy.png${line:+ and $dir/centre_line.png}"
