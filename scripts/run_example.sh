#!/usr/bin/env bash
# Set up, build, and run the small default case: the paper's 1D wave on the FE model.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
cd "$build"
./periarlequin "$top/parameter_files/fe_wave_2d.prm"
echo "Fields: $build/output-fe-wave-2d/solution_fe.pvd (ParaView); energies: solution_energy.csv"
