#!/usr/bin/env bash
# Cost of the coupled model against the pure-PD reference at the same PD resolution: the
# paper's section 6.1 wave, parameter_files/pd_wave_2d_reference.prm (PD on the whole plate)
# and arlequin_wave_2d_weak_dt1e-7.prm (weak coupling, diagonal multipliers, damping), both
# cut to STEPS steps (1000 by default) and run alternately REPEATS times (3) on 1 rank, with
# their own output settings (PD and FE files every 200 steps, energies every 10).
#
#   benchmarks/coupling_cost.sh [build-dir]
#
# Prints the median wall time of each, their ratio and the ratio of PD particles, the
# criterion "coupled / reference <= particles coupled / particles reference + 0.1" (the
# coupled run saves at least the share of particles it drops, minus 10 %), and the share of
# each TimerOutput section of the median coupled and reference runs.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
steps=${STEPS:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

for case in pd_wave_2d_reference arlequin_wave_2d_weak_dt1e-7; do
  sed -e "s|set Directory .*|set Directory = $work/$case|" \
      -e "s|set End time .*|set End time = $(awk "BEGIN{print $steps*1e-7}")|" \
      -e "s|set Progress interval .*|set Progress interval = 0|" \
      "$top/parameter_files/$case.prm" > "$work/$case.prm"
done

# run <case> <repeat>: the run's log in $work/<case>.<repeat>.log; prints its wall time
run() {
  "$build/periarlequin" "$work/$1.prm" > "$work/$1.$2.log"
  awk -F'|' '/Total wallclock time elapsed/ {split($3, a, " "); print a[1] + 0}' "$work/$1.$2.log"
}

for r in $(seq "$repeats"); do
  echo "$(run pd_wave_2d_reference "$r") $r" >> "$work/reference.times"
  echo "$(run arlequin_wave_2d_weak_dt1e-7 "$r") $r" >> "$work/coupled.times"
done

median_run() { sort -g "$1" | awk '{a[NR]=$2} END{print a[int((NR+1)/2)]}'; }
median_time() { cut -d' ' -f1 "$1" | median; }
particles() { awk '/PD particles/ {for (i = 1; i <= NF; ++i) if ($i == "PD") print $(i-1)}' "$1"; }

reference_log=$work/pd_wave_2d_reference.$(median_run "$work/reference.times").log
coupled_log=$work/arlequin_wave_2d_weak_dt1e-7.$(median_run "$work/coupled.times").log
t_ref=$(median_time "$work/reference.times")
t_coupled=$(median_time "$work/coupled.times")
n_ref=$(particles "$reference_log")
n_coupled=$(particles "$coupled_log")

echo "section 6.1 wave, $steps steps at dt = 1e-7 s, 1 rank, median of $repeats (runs alternated)"
printf "pure-PD reference: %8d particles, %8.2f s\n" "$n_ref" "$t_ref"
printf "weak coupling:     %8d particles, %8.2f s\n" "$n_coupled" "$t_coupled"
awk -v tc="$t_coupled" -v tr="$t_ref" -v nc="$n_coupled" -v nr="$n_ref" 'BEGIN {
  printf "wall time ratio coupled / reference: %.3f; particle ratio: %.3f\n", tc / tr, nc / nr
  printf "criterion (wall ratio <= particle ratio + 0.1): %s\n", (tc / tr <= nc / nr + 0.1) ? "met" : "NOT met" }'
for log in "$reference_log" "$coupled_log"; do
  echo
  echo "TimerOutput shares, $(basename "$log" | sed 's/\.[0-9]*\.log$//'):"
  awk -F'|' '/Total wallclock time elapsed/ {split($3, a, " "); total = a[1] + 0}
             NF == 7 && $3 ~ /[0-9]/ && $2 !~ /Section/ {
               gsub(/^ +| +$/, "", $2); split($4, t, " "); name[++n] = $2; time[n] = t[1] + 0 }
             END { for (i = 1; i <= n; ++i) { printf "  %-20s %8.3f s  %5.1f %%\n", name[i], time[i], 100 * time[i] / total; rest -= time[i] }
                   printf "  %-20s %8.3f s  %5.1f %%  (time integration, ghost exchange)\n", "outside sections", total + rest, 100 * (total + rest) / total }' "$log"
done
