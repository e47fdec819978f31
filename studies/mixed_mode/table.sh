#!/bin/bash
# The table of studies/mixed_mode/README.md from the output of studies/mixed_mode/run.sh (run in its work
# directory): for each run <name> (files <name>.prm, <name>.log, <name>/solution_energy.csv)
# the phase angle, K_II / K_I, the maximum-circumferential-stress kink angle
# theta_c = 2 atan((1 - sqrt(1 + 8 r^2)) / (4 r)), the measured kink angle (last record, with
# the number of particles fitted), G at initiation (first new broken bond near the tip) and at
# growth by one horizon over G0 = 36 kJ/m^2, particles and wall time of the time loop.
#   studies/mixed_mode/table.sh <name> ...
set -euo pipefail
printf '| run | psi [deg] | K_II/K_I | MTS angle [deg] | kink angle [deg] | fitted particles | G_init / G0 | G_growth / G0 | growth at [us] | particles | loop [s] | end |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for name in "$@"; do
  psi=$(sed -n 's/.*set Phase angle *= *\([-0-9.e]*\).*/\1/p' "$name.prm")
  particles=$(sed -n 's/.* FE DoFs, \([0-9]*\) PD particles.*/\1/p' "$name.log" | head -1)
  [ -z "$particles" ] && particles=$(sed -n 's/.*, \([0-9]*\) PD particles.*/\1/p' "$name.log" | head -1)
  loop=$(sed -n 's/^Time loop: [0-9]* steps in \([0-9.]*\) s.*/\1/p' "$name.log" | head -1)
  end=$(grep -o 'Damage reached the overlap at t = [^ ]* s' "$name.log" | head -1 || true)
  [ -z "$end" ] && end=$( [ -n "$loop" ] && echo "end time" || echo "stopped")
  awk -F, -v name="$name" -v psi="$psi" -v particles="${particles:--}" -v loop="${loop:--}" -v end="$end" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    { last = $0; split($0, row, ","); angle = row[col["kink_angle"]]; fitted = row[col["kink_particles"]]
      gi = row[col["initiation_G"]]; gg = row[col["growth_G"]]; tg = row[col["growth_time"]] }
    END {
      pi = 3.14159265358979; r = sin(psi * pi / 180) / cos(psi * pi / 180)
      mts = (r == 0) ? 0 : 2 * atan2(1 - sqrt(1 + 8 * r * r), 4 * r) * 180 / pi
      printf "| %s | %.1f | %.2f | %.1f | %s | %s | %s | %s | %s | %s | %s | %s |\n", name, psi, r, mts,
        (angle == "nan" ? "-" : sprintf("%.1f", angle)), fitted,
        (gi == "nan" ? "-" : sprintf("%.3f", gi / 36e3)), (gg == "nan" ? "-" : sprintf("%.3f", gg / 36e3)),
        (tg == "nan" ? "-" : sprintf("%.1f", tg * 1e6)), particles, loop, end
    }' "$name/solution_energy.csv"
done
