#!/usr/bin/env bash
# A crack released in a plate that stores elastic energy, against the same plate loaded
# suddenly with the crack in it: the glass plate of studies/crack_branching (100 x 40 mm,
# pure PD, 41,000 particles, sigma = 2 MPa on its long edges, a crack from the left edge to
# the middle). "sudden": the traction from t = 0 on the cracked plate (the branching case);
# "preloaded": Time/Integration = static then explicit, the intact plate brought to
# equilibrium under the traction, then the crack released (Static solve/Released cracks).
# One run each, one after the other; prints the table of README.md.
#
#   studies/preload/run.sh <build directory> <work directory> [<mpi ranks>]
set -euo pipefail
usage="usage: studies/preload/run.sh <build directory> <work directory> [<mpi ranks>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
mkdir -p "$work"
cd "$work"
crack="0, 0.02 : 0.05, 0.02"
for run in sudden preloaded; do
  {
    echo "include $top/studies/crack_branching/plate.prm"
    echo "subsection Geometry"
    echo "  set Upper corner = 0.1, 0.04"
    echo "  set Subdivisions = 40, 16"
    echo "end"
    echo "subsection Peridynamics"
    echo "  set Region = 0, 0 : 0.1, 0.04"
    if [ $run = sudden ]; then
      echo "  set Pre-cracks = $crack"
      echo "end"
    else
      echo "  set Pre-cracks ="
      echo "end"
      echo "subsection Time"
      echo "  set Integration = static then explicit"
      echo "end"
      echo "subsection Static solve"
      echo "  set Released cracks = $crack"
      echo "end"
    fi
    echo "subsection Output"
    echo "  set Directory = $work/$run"
    echo "end"
  } > "$run.prm"
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$run.prm" > "$run.log" 2>&1
done
# History columns by name; the first record with a broken bond beyond the released ones, the
# tip of the leading branch and the broken-bond energy at 10, 20, 30 and 40 us.
column() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
echo "| run | static solve | stored strain energy at t = 0 [J/m] | first new break [us] | branches at 43 us | tip x at 10 / 20 / 30 / 40 us [mm] | broken-bond energy at 10 / 20 / 30 / 40 us [J/m] |"
echo "|---|---|---|---|---|---|---|"
for run in sudden preloaded; do
  csv=$run/solution_energy.csv
  t=$(column "$csv" time); u=$(column "$csv" strain_energy); b=$(column "$csv" broken_bonds)
  n=$(column "$csv" branches); x=$(column "$csv" branch_0_x); e=$(column "$csv" broken_bond_energy)
  solve=$(grep -o "equilibrium after [0-9]* iterations" "$run.log" | cut -d' ' -f3 || true)
  awk -F, -v t="$t" -v u="$u" -v b="$b" -v n="$n" -v x="$x" -v e="$e" -v run="$run" -v solve="${solve:--}" '
    NR == 2 {u0 = $u; b0 = $b}
    NR > 1 && first == "" && $b > b0 {first = sprintf("%.2f", 1e6 * $t)}
    NR > 1 {for (k = 1; k <= 4; ++k) if (tips[k] == "" && $t >= k * 1e-5 - 1e-12) {tips[k] = sprintf("%.1f", 1e3 * $x); energy[k] = sprintf("%.4f", $e)}; branches = $n}
    END {printf "| %s | %s iterations | %.4f | %s | %s | %s / %s / %s / %s | %s / %s / %s / %s |\n", run, solve, u0, first, branches, tips[1], tips[2], tips[3], tips[4], energy[1], energy[2], energy[3], energy[4]}' "$csv"
done
