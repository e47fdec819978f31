#!/bin/bash
# The section 6.3 study of this folder's README: a steel bar 100 x 10 x 10 mm at 1 m/s hits a
# clamped plate, pure FE and coupled FE-PD-FE (parameter_files/bar_impact_3d_{fe,coupled}.prm,
# hexahedra of 1 mm, PD lattice 0.5 mm), and with the fine group the same with every cell
# and lattice spacing halved (dt 20 ns for FE, 10 ns for the coupled run). Prints the table
# of the README and, with gnuplot (Debian gnuplot-nox), draws
# <work>/bar_impact_point_a.png (point A's velocity against time, fig. 16 of the paper) and
# <work>/bar_impact_axis.png (the velocity along the bar's axis at four times, fig. 15):
#   studies/bar_impact/run.sh <build directory> <work directory> [<mpi ranks>] [<groups>]
# <groups>: paper (default), fine. About 1.5 minutes for paper, 25 minutes for fine, on one core.
set -euo pipefail
usage="usage: studies/bar_impact/run.sh <build directory> <work directory> [<mpi ranks>] [<groups>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
groups=${4:-paper}
here=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work"
cd "$work"

run() { # run <parameter file> <log>
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$1" > "$2" 2>&1
}
# refine <shipped case> <output directory> <time step> <energy interval>: the case with every
# length halved (one more refinement of its mesh, half its lattice spacing if it has PD)
refine() {
  echo "include $here/parameter_files/$1.prm"
  echo "subsection Geometry"
  echo "  set Mesh file          = $here/examples/bar_impact/bar_and_plate.msh"
  echo "  set Global refinements = 2"
  echo "end"
  if grep -q "^subsection Peridynamics" "$here/parameter_files/$1.prm"; then
    echo "subsection Peridynamics"
    echo "  set Lattice spacing = 2.5e-4"
    echo "end"
  fi
  echo "subsection Time"
  echo "  set Time step = $3"
  echo "end"
  echo "subsection Output"
  echo "  set Directory       = $2"
  echo "  set Output interval = 0"
  echo "  set Energy interval = $4"
  echo "end"
}

for group in $groups; do
  case $group in
    paper)
      run "$here/parameter_files/bar_impact_3d_fe.prm" fe.log
      run "$here/parameter_files/bar_impact_3d_coupled.prm" coupled.log ;;
    fine)
      refine bar_impact_3d_fe output-bar-impact-3d-fe-fine 2e-8 4 > fe_fine.prm
      refine bar_impact_3d_coupled output-bar-impact-3d-coupled-fine 1e-8 8 > coupled_fine.prm
      run fe_fine.prm fe_fine.log
      run coupled_fine.prm coupled_fine.log ;;
    *) echo "unknown group $group" >&2; exit 1 ;;
  esac
done

history() { echo "$1/solution_energy.csv"; }
reference=$(history output-bar-impact-3d-fe)
# Per run: contact duration, rebound velocity of the bar (momentum over the bar's mass
# 7.823e-2 kg, the plate's share is nil once it is released), H at the end over H0, the
# times point A's v_x falls below 0.5 and -0.5 m/s, and the relative L2 difference of
# point A's history from the pure-FE run with 1 mm cells at the records they share.
summary() {
  awk -F, -v name="$2" '
    FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    NR == FNR { ref[sprintf("%.9f", $col["time"])] = $col["probe_0_v_x"]; next }
    { t = $col["time"]; v = $col["probe_0_v_x"]
      if ($col["contact_nodes"] > 0) { if (first == "") first = t; last = t }
      if (h0 == "") h0 = $col["total_energy"]
      h = $col["total_energy"]; p = $col["linear_momentum_x"]
      if (v < 0.5 && front1 == "") front1 = t
      if (v < -0.5 && front2 == "") front2 = t
      key = sprintf("%.9f", t)
      if (key in ref) { d += (v - ref[key]) ^ 2; n += ref[key] ^ 2 } }
    END { printf "| %s | %.2f | %.4f | %.4f | %.2f | %.2f | %.4f |\n", name, (last - first) * 1e6,
            -p / 7.823e-2, h / h0, front1 * 1e6, front2 * 1e6, sqrt(d / n) }' "$reference" "$1"
}
echo "| run | contact [us] | rebound / v0 | H_end / H0 | front 1 at A [us] | front 2 at A [us] | L2 at A vs FE 1 mm |"
echo "|---|---|---|---|---|---|---|"
for run in fe coupled fe-fine coupled-fine; do
  file=$(history "output-bar-impact-3d-$run")
  [ -f "$file" ] && summary "$file" "$run"
done
echo "1D theory: contact 2 L / c0 = 39.56 us (+ 1 us to close the gap), rebound 1, fronts at A at 6.43 and 33.13 us (+ 1 us)"

# Point A split at 33 us (before: only what came through the FE end and what the overlap sent
# back; after: what crossed the PD zone twice), raw and averaged over 2 us (the ringing of
# the lateral modes removed), both histories interpolated to 0.08 us; and the mean v_x at A
# over 42-60 us (after the rebound).
compare() { # compare <run> <reference run>
  awk -F, -v name="$1 vs $2" '
    FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; file++; n[file] = 0; next }
    { k = ++n[file]; t[file, k] = $col["time"]; v[file, k] = $col["probe_0_v_x"] }
    function at(f, time,   k) {
      for (k = 1; k < n[f] && t[f, k + 1] < time; k++);
      if (k >= n[f]) return v[f, n[f]]
      return v[f, k] + (v[f, k + 1] - v[f, k]) * (time - t[f, k]) / (t[f, k + 1] - t[f, k])
    }
    END {
      m = 750; step = 8e-8; half = 12
      for (i = 0; i <= m; i++) { a[i] = at(1, i * step); b[i] = at(2, i * step) }
      for (i = 0; i <= m; i++) {
        sa = sb = c = 0
        for (j = i - half; j <= i + half; j++) if (j >= 0 && j <= m) { sa += a[j]; sb += b[j]; c++ }
        part = (i * step < 33e-6) ? 1 : 2
        d[part] += (a[i] - b[i]) ^ 2; r[part] += b[i] ^ 2
        ds[part] += (sa / c - sb / c) ^ 2; rs[part] += (sb / c) ^ 2
        if (i * step >= 42e-6) { ma += a[i]; mb += b[i]; mc++ }
      }
      printf "| %s | %.3f | %.3f | %.3f | %.3f | %.3f / %.3f |\n", name, sqrt(d[1] / r[1]),
        sqrt(d[2] / r[2]), sqrt(ds[1] / rs[1]), sqrt(ds[2] / rs[2]), ma / mc, mb / mc }' \
    "$(history "output-bar-impact-3d-$1")" "$(history "output-bar-impact-3d-$2")"
}
echo
echo "| relative L2 at A | raw, t < 33 us | raw, t > 33 us | 2 us average, t < 33 us | 2 us average, t > 33 us | mean v_x at A, 42-60 us [m/s] |"
echo "|---|---|---|---|---|---|"
compare coupled fe
if [ -f "$(history output-bar-impact-3d-fe-fine)" ]; then
  compare fe-fine fe
  compare coupled-fine fe-fine
fi

command -v gnuplot > /dev/null || { echo "gnuplot is missing (apt-get install gnuplot-nox): no figures" >&2; exit 0; }
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
t=$(column "$reference" time); a=$(column "$reference" probe_0_v_x)
{
  echo "set datafile separator ','; set terminal pngcairo size 900,550 noenhanced"
  echo "set output 'bar_impact_point_a.png'; set xlabel 'time [us]'; set ylabel 'v_x at point A [m/s]'; set key bottom left"
  echo -n "plot '$reference' using (\$$t*1e6):$a with lines lw 2 title 'pure FE, 1 mm'"
  echo -n ", '$(history output-bar-impact-3d-coupled)' using (\$$t*1e6):$a with lines title 'coupled, 1 mm / 0.5 mm'"
  for run in fe-fine coupled-fine; do
    file=$(history "output-bar-impact-3d-$run")
    [ -f "$file" ] && echo -n ", '$file' using (\$$t*1e6):$a with lines dt 2 title '$run (halved)'"
  done
  echo
  # fig. 15: probes 1..41 sit on the axis at x = 2.5 mm (k - 1); one line per time and run.
  echo "set output 'bar_impact_axis.png'; set xlabel 'x [mm]'; set ylabel 'v_x on the axis [m/s]'; set key outside right"
  echo -n "plot "
  separator=""
  colour=0
  for time in 1e-05 2e-05 3e-05 4e-05; do
    colour=$((colour + 1))
    for run in fe coupled; do
      file=$(history "output-bar-impact-3d-$run")
      awk -F, -v time="$time" 'FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
        sprintf("%.9g", $col["time"]) == sprintf("%.9g", time) {
          for (k = 1; k <= 41; k++) print 2.5 * (k - 1) "," $col["probe_" k "_v_x"] }' "$file" > "axis_${run}_$time.csv"
      style=$([ $run = fe ] && echo "lines lw 2" || echo "points pt 7 ps 0.7")
      echo -n "$separator'axis_${run}_$time.csv' using 1:2 with $style lc $colour title '$run, $(awk "BEGIN { print $time * 1e6 }") us'"
      separator=", "
    done
  done
  echo
} | gnuplot
echo "wrote $work/bar_impact_point_a.png and $work/bar_impact_axis.png"
