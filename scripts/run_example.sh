#!/usr/bin/env bash
# Set up, build, and run the small default case: the paper's section 6.1 wave, PD coupled to FE
# (weak coupling with fine-scale damping) at half the paper's resolution, and its figures.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
cd "$build"
./periarlequin "$top/parameter_files/arlequin_wave_2d_coarse.prm"
out="$build/output-arlequin-wave-coarse"
"$top/scripts/plot_wave.sh" "$out"
echo "Fields: $out/solution_fe.pvd and solution_pd.pvd (ParaView); energies: solution_energy.csv"
echo "Figures: $out/energy.png (energy of the pure PD zone against time), $out/centre_line.png (u_x along the centre line at the end)"
