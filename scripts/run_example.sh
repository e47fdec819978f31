#!/usr/bin/env bash
# Set up, build, and run the small default case: the paper's section 6.1 wave, PD coupled to FE
# (weak coupling with fine-scale damping) at half the paper's resolution.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
cd "$build"
./periarlequin "$top/parameter_files/arlequin_wave_2d_coarse.prm"
echo "Fields: $build/output-arlequin-wave-coarse/solution_fe.pvd and solution_pd.pvd (ParaView); energies: solution_energy.csv"
