#!/bin/bash
# The fracture-energy table of studies/mixed_mode/README.md from runs of studies/mixed_mode/run.sh (in its
# work directory): for each run <name> (files <name>.prm and <name>/solution_energy.csv,
# energies and cracks postprocessors, a crack-tip field ramped so that G = G0 = 36 kJ/m^2 at
# T_c) the fracture criterion, the horizon factor, G at initiation and when the new crack
# (broken-bond measure crack_area) reaches 1 and 5 mm, over G0, and the energy dissipated per
# unit area of new crack between 1 and 5 mm (in brackets: 0.1 to 1 mm), over G0: the energy
# the balance leaves unaccounted for, the drop of total_energy = kinetic + strain - external
# work.
#   studies/mixed_mode/crack_energy_table.sh <name> ...
set -euo pipefail
printf '| run | criterion | m | G_init / G0 | G at 1 mm / G0 | G at 5 mm / G0 | dissipated / G0 |\n'
printf '|---|---|---|---|---|---|---|\n'
for name in "$@"; do
  criterion=$(sed -n 's/.*set Fracture criterion *= *\(.*\)$/\1/p' "$name.prm")
  m=$(sed -n 's/.*set Horizon factor *= *\([0-9.e]*\).*/\1/p' "$name.prm")
  awk -F, -v name="$name" -v criterion="${criterion:-critical stretch}" -v m="$m" '
    function g(k) { return k ? sprintf("%.2f", row_G[k] / 36e3) : "-" }
    function dissipated(a, b) {
      return (a && b) ? sprintf("%.2f", (total[a] - total[b]) / (area[b] - area[a]) / 36e3) : "-"
    }
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    { k = NR - 1; area[k] = $col["crack_area"]; total[k] = $col["total_energy"]; row_G[k] = $col["G"]
      gi = $col["initiation_G"]
      if (!a01 && area[k] >= 1e-4) a01 = k
      if (!a1 && area[k] >= 1e-3) a1 = k
      if (!a5 && area[k] >= 5e-3) a5 = k }
    END {
      printf "| %s | %s | %s | %s | %s | %s | %s (%s) |\n", name, criterion, m,
        (gi == "nan" ? "-" : sprintf("%.3f", gi / 36e3)), g(a1), g(a5), dissipated(a1, a5), dissipated(a01, a1)
    }' "$name/solution_energy.csv"
done
