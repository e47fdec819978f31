#!/usr/bin/env bash
# Cost of the adaptive PD zone on the crack-branching case of studies/crack_branching/README.md (glass
# plate 100 x 120 mm, lattice 0.3125 mm, 43 us): pure PD (pd_120), the best fixed PD strip
# (coupled8_120_narrow, |y - 60| <= 10 mm chosen from the pure-PD crack path) and the
# adaptive zone grown from the notch (adaptive8_120), made by studies/crack_branching/run.sh, one
# after the other, REPEATS times (3) on 1 rank.
#
#   benchmarks/adaptive_branching.sh [build-dir]
#
# Prints per repeat the time-loop wall time of each run and the ratios pure PD / adaptive and
# fixed strip / adaptive measured side by side, then their medians; the PD particles at the
# end against the pure-PD count, and the share of the adaptive run's loop spent converting
# cells (TimerOutput section "PD zone growth": the criterion's checks and the conversions).
# Then the adaptive run on 2 ranks, side by side with and without repartitioning after the
# conversions (Load imbalance tolerance 0.1 against 1e9): loop times, their ratio, the time
# spent repartitioning, the load imbalance at the end, and the speed-up over 1 rank.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"
runs="pd_120 coupled8_120_narrow adaptive8_120"

loop_time() { awk '/^Time loop:/ {print $6}' "$1"; }
section() { awk -F'|' -v s="$2" '$2 ~ "^ *"s" *$" {split($4, t, " "); print t[1] + 0}' "$1"; }
last_column() { # csv, column name
  awk -F',' -v c="$2" 'NR == 1 {for (i = 1; i <= NF; ++i) if ($i == c) k = i; next} {v = $k} END {print v}' "$1"
}

for r in $(seq "$repeats"); do
  bash "$top/studies/crack_branching/run.sh" "$build" "$work/$r" 1 "$runs" > /dev/null 2>&1 || true
  t_pd=$(loop_time "$work/$r/pd_120.log")
  t_fixed=$(loop_time "$work/$r/coupled8_120_narrow.log")
  t_adaptive=$(loop_time "$work/$r/adaptive8_120.log")
  growth=$(section "$work/$r/adaptive8_120.log" "PD zone growth")
  echo "$t_pd $t_fixed $t_adaptive $growth" >> "$work/times"
  awk -v a="$t_pd" -v b="$t_fixed" -v c="$t_adaptive" -v g="$growth" -v r="$r" 'BEGIN {
    printf "repeat %d: pure PD %.1f s, fixed strip %.1f s, adaptive %.1f s (growth %.1f s); pure PD / adaptive %.2f, fixed / adaptive %.2f\n", r, a, b, c, g, a / c, b / c }'
done

col() { cut -d' ' -f"$1" "$work/times" | median; }
ratio() { awk -v i="$1" -v j="$2" '{print $i / $j}' "$work/times" | median; }
n_pd=$(last_column "$work/1/pd_120/solution_energy.csv" pd_particles)
n_fixed=$(last_column "$work/1/coupled8_120_narrow/solution_energy.csv" pd_particles)
n_adaptive=$(last_column "$work/1/adaptive8_120/solution_energy.csv" pd_particles)
echo
echo "crack branching, 100 x 120 mm, 1720 steps, 1 rank, medians of $repeats"
printf "pure PD:      %7d particles, loop %7.1f s\n" "$n_pd" "$(col 1)"
printf "fixed strip:  %7d particles, loop %7.1f s\n" "$n_fixed" "$(col 2)"
printf "adaptive:     %7d particles at the end, loop %7.1f s, of which %.1f s (%.0f %%) growing the zone\n" \
  "$n_adaptive" "$(col 3)" "$(col 4)" "$(awk -v g="$(col 4)" -v t="$(col 3)" 'BEGIN {print 100 * g / t}')"
printf "pure PD / adaptive: %.2f; fixed strip / adaptive: %.2f (medians of the ratios of each repeat)\n" \
  "$(ratio 1 3)" "$(ratio 2 3)"
printf "particles at the end, adaptive / pure PD: %.3f\n" "$(awk -v a="$n_adaptive" -v b="$n_pd" 'BEGIN {print a / b}')"

echo
echo "adaptive, 2 ranks: repartitioned after conversions (tolerance 0.1) / not (1e9)"
for r in $(seq "$repeats"); do
  for tol in 0.1 1e9; do
    LOAD_IMBALANCE_TOLERANCE=$tol bash "$top/studies/crack_branching/run.sh" "$build" "$work/np2_${tol}_$r" 2 \
      adaptive8_120 > /dev/null 2>&1 || true
  done
  t_on=$(loop_time "$work/np2_0.1_$r/adaptive8_120.log")
  t_off=$(loop_time "$work/np2_1e9_$r/adaptive8_120.log")
  t_re=$(section "$work/np2_0.1_$r/adaptive8_120.log" "repartition")
  i_on=$(last_column "$work/np2_0.1_$r/adaptive8_120/solution_energy.csv" load_imbalance)
  i_off=$(last_column "$work/np2_1e9_$r/adaptive8_120/solution_energy.csv" load_imbalance)
  n_re=$(last_column "$work/np2_0.1_$r/adaptive8_120/solution_energy.csv" repartitions)
  echo "${t_on:-nan} ${t_off:-nan} ${t_re:-0}" >> "$work/times2"
  awk -v a="$t_on" -v b="$t_off" -v t="$t_re" -v n="$n_re" -v i="$i_on" -v j="$i_off" -v r="$r" 'BEGIN {
    printf "repeat %d: repartitioned %.1f s (%d repartitions, %.2f s; imbalance at the end %.3f), not %.1f s (imbalance %.3f); not / repartitioned %.2f\n", r, a, n, t, i, b, j, b / a }'
done
col2() { cut -d' ' -f"$1" "$work/times2" | median; }
printf "medians: repartitioned %.1f s, not %.1f s, not / repartitioned %.2f; 1 rank / 2 ranks repartitioned %.2f\n" \
  "$(col2 1)" "$(col2 2)" "$(awk '{print $2 / $1}' "$work/times2" | median)" \
  "$(awk -v t="$(col 3)" -v u="$(col2 1)" 'BEGIN {print t / u}')"
