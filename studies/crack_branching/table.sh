#!/bin/bash
# The table of studies/crack_branching/README.md from the output of studies/crack_branching/run.sh (run in
# its work directory): for each run <name> (files <name>.log and <name>/solution_energy.csv)
# the particle and FE DoF counts, wall time of the time loop and the timer shares, crack
# initiation (crack extension past one horizon, 1 mm), branching (first record with two tips:
# time, and the main tip x at the record before), the branch angles (from the tip at the
# record before branching to each tip 4 us after branching), the x of the leading tip at
# 20-43 us, the
# broken-bond energy, and where a run stopped early, why.
#   studies/crack_branching/table.sh <name> ...
set -euo pipefail
printf '| run | particles | FE DoFs | loop [s] | PD forces | coupling | FE forces | output + diagnostics | initiation [us] | branching [us] | branching x [mm] | branch angles [deg] | leading tip x at 20/25/30/35/40/43 us [mm] | broken-bond energy [J/m] | end |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for name in "$@"; do
  log=$name.log
  csv=$name/solution_energy.csv
  particles=$(sed -n 's/.* FE DoFs, \([0-9]*\) PD particles.*/\1/p' "$log" | head -1)
  dofs=$(sed -n 's/.*cells, \([0-9]*\) FE DoFs.*/\1/p' "$log" | head -1)
  loop=$(sed -n 's/^Time loop: [0-9]* steps in \([0-9.]*\) s.*/\1/p' "$log" | head -1)
  share() { awk -v s="$1" -v loop="${loop:-0}" -F'|' '$2 ~ s { gsub(/ /, "", $5); t = $5; sub(/s$/, "", t); if (loop > 0) printf "%.0f %%", 100 * t / loop; found = 1 } END { if (!found) printf "-" }' "$log"; }
  pd=$(share "PD forces"); cp=$(share "coupling"); fe=$(share "FE forces")
  out=$(awk -v loop="${loop:-0}" -F'|' '$2 ~ /output|energies/ { gsub(/ /, "", $5); t = $5; sub(/s$/, "", t); sum += t } END { if (loop > 0) printf "%.0f %%", 100 * sum / loop }' "$log")
  end=$(grep -o 'Damage reached the overlap at t = [^ ]* s' "$log" | head -1 || true)
  [ -z "$end" ] && end="43 us"
  awk -F, -v name="$name" -v particles="$particles" -v dofs="${dofs:-0}" -v loop="${loop:-stopped}" \
      -v pd="$pd" -v cp="$cp" -v fe="$fe" -v out="$out" -v end="$end" '
    NR == 1 { for (c = 1; c <= NF; ++c) col[$c] = c; next }
    {
      t = $col["time"] * 1e6
      if (init == "" && $col["crack_extension"] > 1e-3) init = sprintf("%.1f", t)
      n = $col["branches"]
      if (branch == "" && n >= 2) {
        branch = sprintf("%.1f", t); bx = last_x; by = last_y
      }
      if (n == 1) { last_x = $col["branch_0_x"]; last_y = $col["branch_0_y"] }
      # Tips 4 us after branching give the branch angles: the final tips of arrested
      # branches are too close to the branching point.
      for (k = 0; k < 4; ++k) {
        x = $col["branch_" k "_x"]
        if (x != "nan" && x != "" && branch != "" && t <= branch + 4 + 1e-6) { fx[k] = x; fy[k] = $col["branch_" k "_y"] }
      }
      lead = "-"
      for (k = 0; k < 4; ++k) {
        x = $col["branch_" k "_x"]
        if (x != "nan" && x != "" && (lead == "-" || x * 1e3 > lead + 0)) lead = sprintf("%.1f", x * 1e3)
      }
      for (s = 20; s <= 40; s += 5)
        if (tip[s] == "" && t >= s - 1e-6) tip[s] = lead
      if (tip[43] == "" && t >= 43 - 1e-6) tip[43] = lead
      energy = $col["broken_bond_energy"]
    }
    END {
      angles = "-"
      if (branch != "") {
        angles = ""
        for (k = 0; k < 4; ++k)
          if (k in fx && fx[k] != bx) angles = angles sprintf("%s%.0f", (angles == "" ? "" : ", "), atan2(fy[k] - by, fx[k] - bx) * 180 / 3.14159265)
      }
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s/%s/%s/%s/%s/%s | %.3g | %s |\n", name, particles, dofs, loop, pd, cp, fe, out, (init == "" ? "-" : init), (branch == "" ? "-" : branch), (branch == "" ? "-" : sprintf("%.1f", bx * 1e3)), angles, (tip[20] == "" ? "-" : tip[20]), (tip[25] == "" ? "-" : tip[25]), (tip[30] == "" ? "-" : tip[30]), (tip[35] == "" ? "-" : tip[35]), (tip[40] == "" ? "-" : tip[40]), (tip[43] == "" ? "-" : tip[43]), energy, end
    }' "$csv"
done
