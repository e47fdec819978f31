#!/bin/bash
# Results table of the section 6.1 study (markdown), from the output directories of a pure-PD
# reference run and of coupled runs at the same time step and PD lattice:
#   studies/wave_coupling/table.sh <reference dir> <label>=<run dir> [<label>=<run dir> ...]
# Columns, at the end time t_end of the reference unless said:
#   E_pure/E0      energy left in the pure PD zone (pure_pd_energy) over its initial value,
#                  also at the paper's end time T_PAPER (default 2.4e-4 s);
#   excess         the same minus the reference's own value (what the coupling sent back);
#   L2 error       max over the line samples of ||u - u_ref|| / ||u_ref(t = 0)|| on the PD
#                  particles of the sample line with |x| <= PURE_PD_HALF_WIDTH (default 0.9 m);
#   H/H0           total Hamiltonian over its initial value.
set -euo pipefail
ref=${1:?usage: wave_table.sh <reference dir> <label>=<run dir> ...}
shift
half_width=${PURE_PD_HALF_WIDTH:-0.9}
t_paper=${T_PAPER:-2.4e-4}

# energy_at_end <csv>: prints "time pure_pd_energy/initial total_energy/initial" of the last row
energy_at_end() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
           NR == 2 { e0 = $column["pure_pd_energy"]; h0 = $column["total_energy"] }
           { last_t = $column["time"]; e = $column["pure_pd_energy"]; h = $column["total_energy"] }
           END { printf "%s %.6g %.6g\n", last_t, e / e0, h / h0 }' "$1"
}

# fraction_at <csv> <time>: pure_pd_energy / initial in the first record at or after time
fraction_at() {
  awk -F, -v t="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
           NR == 2 { e0 = $column["pure_pd_energy"] }
           $column["time"] >= t * (1 - 1e-9) { printf "%.6g\n", $column["pure_pd_energy"] / e0; found = 1; exit }
           END { if (!found) print "nan" }' "$1"
}

# first_time_below <csv> <fraction>: first time the pure-PD energy falls below fraction * initial
first_time_below() {
  awk -F, -v f="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
           NR == 2 { e0 = $column["pure_pd_energy"] }
           $column["pure_pd_energy"] < f * e0 { print $column["time"]; found = 1; exit }
           END { if (!found) print "never" }' "$1"
}

# line_error <run dir>: max over the reference's line samples of the relative L2 error
line_error() {
  local run=$1 worst=0 norm0 error file
  norm0=$(awk -F, -v w="$half_width" '$1 == "pd" && ($2 <= w && $2 >= -w) { s += $4 * $4 + $5 * $5 } END { print sqrt(s) }' \
            "$ref/solution_line_000000.csv")
  for file in "$ref"/solution_line_*.csv; do
    [ -f "$run/$(basename "$file")" ] || continue
    error=$(awk -F, -v w="$half_width" -v n0="$norm0" '
      FNR == 1 { ++pass; next }
      $1 != "pd" || $2 > w || $2 < -w { next }
      { key = sprintf("%.6f %.6f", $2, $3) }
      pass == 1 { ux[key] = $4; uy[key] = $5; next }
      key in ux { s += ($4 - ux[key]) ^ 2 + ($5 - uy[key]) ^ 2; ++matched }
      END { if (matched == 0) print "nan"; else print sqrt(s) / n0 }' "$file" "$run/$(basename "$file")")
    worst=$(awk -v a="$worst" -v b="$error" 'BEGIN { print (b == "nan" || b > a) ? b : a }')
  done
  echo "$worst"
}

read -r t_end ref_fraction ref_h <<< "$(energy_at_end "$ref/solution_energy.csv")"
printf 'reference: E_pure/E0 = %.4f at t_end = %s s, %.4f at %s s (first below 1 %%: %s), H/H0 = %.5f\n\n' \
  "$ref_fraction" "$t_end" "$(fraction_at "$ref/solution_energy.csv" "$t_paper")" "$t_paper" \
  "$(first_time_below "$ref/solution_energy.csv" 0.01)" "$ref_h"
echo "| run | E_pure/E0 at $t_paper s | E_pure/E0 at t_end | excess over reference | L2 error in pure PD (max over samples) | H/H0 at t_end |"
echo "|---|---|---|---|---|---|"
for entry in "$@"; do
  label=${entry%%=*}
  run=${entry#*=}
  read -r t fraction h <<< "$(energy_at_end "$run/solution_energy.csv")"
  [ "$t" = "$t_end" ] || echo "warning: $label ends at $t s, the reference at $t_end s" >&2
  printf '| %s | %.4f | %.4f | %+.4f | %.4f | %.4f |\n' "$label" "$(fraction_at "$run/solution_energy.csv" "$t_paper")" "$fraction" \
    "$(awk -v a="$fraction" -v b="$ref_fraction" 'BEGIN { print a - b }')" "$(line_error "$run")" "$h"
done
