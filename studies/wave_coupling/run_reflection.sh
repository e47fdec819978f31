#!/bin/bash
# The reflection study of the overlap (studies/wave_coupling/README.md, "Reflection against wavelength"):
# R(lambda / h) and T(lambda / h) of a wave packet sent from the pure PD zone into the
# overlap (PeriArlequin::WaveReflection, build/periarlequin-wave-reflection), for FE/PD size
# ratios, overlap widths, couplings and damping settings. Writes <work>/reflection.csv
# (configuration, lambda / h, h / dx, overlap cells, R, T, time) and, with gnuplot (Debian
# gnuplot-nox), <work>/reflection.png:
#   studies/wave_coupling/run_reflection.sh <build directory> <work directory> [<mpi ranks>] [<groups>]
# <groups>: defaults (weak coupling, defaults: lambda-mesh of 2 FE cells, C = 10; ratios 4
# and 8, overlaps 3 and 5 cells), from_fe (the packet coming from the FE side; ratios 4 and
# 8, overlap 5), fe_nodes (the paper's lambda-mesh, the FE nodes, and C = 30; ratios 4 and 8,
# overlap 5), couplings (bad, strict, weak without damping; ratio 8, overlap 5), damping
# (C = 5 and 30 on the default lambda-mesh; spacing 1.5 and 3 cells; ratio 8, overlap 5),
# robustness (the default lambda-mesh moved by 1/4, 1/2, 3/4 of its spacing; overlap 4 cells;
# half and a quarter of the time step; exact (CG) multipliers; ratio 8). About 70 minutes on
# one core for all. <groups> = table: only the table and the figure of
# an existing <work>/reflection.csv (e.g. the concatenation of runs made in parallel).
set -euo pipefail
usage="usage: wave_reflection_study.sh <build directory> <work directory> [<mpi ranks>] [<groups>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
groups=${4:-defaults from_fe fe_nodes couplings damping robustness}
mkdir -p "$work"
cd "$work"
wavelengths="1.5 2 2.5 3 4 6 9 12 18 24"

# measure <configuration name> <ratio> <overlap cells> <coupling entries, ';'-separated> [<side>
#         [<time step fraction>]]
measure() {
  local name=$1 ratio=$2 cells=$3 coupling=$4 side=${5:-pd} fraction=${6:-1} wl
  for wl in $wavelengths; do
    cat > case.prm << EOF2
subsection Wave reflection
  set Size ratio         = $ratio
  set Overlap cells      = $cells
  set Wavelength         = $wl
  set Coupling           = $coupling
  set Incident side      = $side
  set Time step fraction = $fraction
end
EOF2
    echo -n "$name,"
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin-wave-reflection" case.prm 2> /dev/null | tail -1
  done
}

[ "$groups" = table ] || {
  echo "configuration,wavelength_cells,size_ratio,overlap_cells,R,T,time"
  for group in $groups; do
    case $group in
      defaults)
        for ratio in 4 8; do
          for cells in 3 5; do
            measure "weak_r${ratio}_o${cells}" $ratio $cells "set Method = weak"
          done
        done ;;
      from_fe)
        for ratio in 4 8; do
          measure "from_fe_weak_r${ratio}_o5" $ratio 5 "set Method = weak" fe
        done ;;
      fe_nodes)
        for ratio in 4 8; do
          measure "fe_nodes_C30_r${ratio}_o5" $ratio 5 \
            "set Method = weak; set Damping constant = 30; subsection weak; set Multiplier spacing = 1; end"
        done ;;
      couplings)
        measure bad_r8_o5 8 5 "set Method = bad"
        measure strict_r8_o5 8 5 "set Method = strict"
        measure weak_undamped_r8_o5 8 5 "set Method = weak; set Fine-scale damping = false" ;;
      damping)
        for constant in 5 30; do
          measure "weak_C${constant}_r8_o5" 8 5 "set Method = weak; set Damping constant = $constant"
        done
        for spacing in 1.5 3; do
          measure "weak_k${spacing}_r8_o5" 8 5 \
            "set Method = weak; subsection weak; set Multiplier spacing = $spacing; end"
        done ;;
      robustness)
        for offset in 0.25 0.5 0.75; do
          measure "weak_offset${offset}_r8_o5" 8 5 \
            "set Method = weak; subsection weak; set Multiplier grid offset = $offset; end"
        done
        measure weak_r8_o4 8 4 "set Method = weak"
        for fraction in 0.5 0.25; do
          measure "weak_dt${fraction}_r8_o5" 8 5 "set Method = weak" pd $fraction
        done
        measure weak_cg_r8_o5 8 5 "set Method = weak; set Multiplier solver = cg" ;;
      *) echo "unknown group $group" >&2; exit 1 ;;
    esac
  done
} | tee reflection.csv

# The table of studies/wave_coupling/README.md: R and T in percent, a row per configuration.
awk -F, 'NR > 1 && NF == 7 {
    if (!($1 in seen)) { seen[$1] = 1; names[++n] = $1 }
    if (!($2 in seen_wl)) { seen_wl[$2] = 1; wl[++m] = $2 }
    cell[$1, $2] = sprintf("%.2g / %.3g", 100 * $5, 100 * $6) }
  END {
    printf "| R / T [%%] at lambda / h = |"; for (j = 1; j <= m; j++) printf " %s |", wl[j]; print ""
    printf "|---|"; for (j = 1; j <= m; j++) printf "---|"; print ""
    for (i = 1; i <= n; i++) {
      printf "| %s |", names[i]
      for (j = 1; j <= m; j++) printf " %s |", ((names[i], wl[j]) in cell) ? cell[names[i], wl[j]] : "-"
      print ""
    } }' reflection.csv

command -v gnuplot > /dev/null || { echo "gnuplot is missing (apt-get install gnuplot-nox): no figure" >&2; exit 0; }
{
  echo "set datafile separator ','; set terminal pngcairo size 900,600 noenhanced"
  echo "set output 'reflection.png'; set logscale xy; set xlabel 'wavelength / FE cell'; set ylabel 'reflected energy / incident energy'"
  echo "set key outside right; set xrange [1:30]; set yrange [1e-5:1]"
  echo -n "plot "
  separator=""
  for name in $(tail -n +2 reflection.csv | cut -d, -f1 | uniq); do
    echo -n "$separator'< grep ^$name, reflection.csv' using 2:5 with linespoints title '$name'"
    separator=", "
  done
  echo ", 0.01 with lines dt 2 lc rgb 'black' title '1 %', 0.05 with lines dt 3 lc rgb 'black' title '5 %'"
} | gnuplot
echo "wrote $work/reflection.csv and $work/reflection.png"
