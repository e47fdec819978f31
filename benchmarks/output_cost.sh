#!/usr/bin/env bash
# Cost of the field output: the default example (parameter_files/arlequin_wave_2d_coarse.prm,
# 5000 steps, FE and PD files every 500 steps) and the coupled case of coupling_cost.sh
# (arlequin_wave_2d_weak_dt1e-7.prm cut to 1000 steps, files every 200), each run with every
# Output/Compression level (fast, small, none) and once without field files, alternated,
# REPEATS times (3) on 1 rank.
#
#   benchmarks/output_cost.sh [build-dir]
#
# Prints per case and level the median wall time, the median time of the TimerOutput section
# "output", its share of the run, the time per write, the size of the files one write leaves,
# and the criterion of issue 14: output at most 5 % of the default example's run.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

# prepare <case> <end time> <level>: <work>/<case>.<level>.prm
prepare() {
  local case=$1 end=$2 level=$3 interval
  interval=$([ "$level" = off ] && echo 0 || grep -h "set Output interval" "$top/parameter_files/$case.prm" | awk '{print $NF}')
  sed -e "s|set Directory .*|set Directory = $work/$case.$level|" \
      -e "s|set End time .*|set End time = $end|" \
      -e "s|set Progress interval .*|set Progress interval = 0|" \
      -e "s|set Output interval .*|set Output interval = $interval|" \
      "$top/parameter_files/$case.prm" > "$work/$case.$level.prm"
  [ "$level" = off ] || printf "subsection Output\n  set Compression = %s\nend\n" "$level" >> "$work/$case.$level.prm"
}

levels="fast small none off"
for level in $levels; do
  prepare arlequin_wave_2d_coarse 5e-4 "$level"
  prepare arlequin_wave_2d_weak_dt1e-7 1e-4 "$level"
done

# section <log> <name>: that TimerOutput section's wall time (0 if absent)
section() { awk -F'|' -v s="$2" '{n = $2; gsub(/^ +| +$/, "", n)} n == s {split($4, t, " "); v = t[1]} END {print v + 0}' "$1"; }
total() { awk -F'|' '/Total wallclock time elapsed/ {split($3, a, " "); print a[1] + 0}' "$1"; }

for r in $(seq "$repeats"); do
  for case in arlequin_wave_2d_coarse arlequin_wave_2d_weak_dt1e-7; do
    for level in $levels; do
      log=$work/$case.$level.$r.log
      rm -rf "$work/$case.$level"
      "$build/periarlequin" "$work/$case.$level.prm" > "$log"
      echo "$(total "$log")" >> "$work/$case.$level.total"
      echo "$(section "$log" output)" >> "$work/$case.$level.output"
      awk -F'|' '{n = $2; gsub(/^ +| +$/, "", n)} n == "output" {print $3 + 0}' "$log" > "$work/$case.$level.writes"
    done
  done
done

for case in arlequin_wave_2d_coarse arlequin_wave_2d_weak_dt1e-7; do
  echo "$case, 1 rank, median of $repeats (runs alternated):"
  printf "  %-6s %10s %10s %7s %12s %12s\n" level "run [s]" "output [s]" share "per write" "one write"
  for level in $levels; do
    t=$(median < "$work/$case.$level.total")
    o=$(median < "$work/$case.$level.output")
    writes=$(cat "$work/$case.$level.writes" 2> /dev/null || echo 0)
    size=0
    if [ "$level" != off ]; then
      # the files of the last write: FE and PD .vtu (and .pvtu) of the highest step number
      last=$(ls "$work/$case.$level" | sed -n 's/.*_\([0-9]\{6\}\)\..*/\1/p' | sort | tail -1)
      size=$(cat "$work/$case.$level"/*_"$last".* | wc -c)
    fi
    awk -v l="$level" -v t="$t" -v o="$o" -v w="${writes:-0}" -v b="$size" 'BEGIN {
      printf "  %-6s %10.3f %10.3f %6.1f%% %9.1f ms %9.0f kB\n", l, t, o, 100 * o / t, (w > 0 ? 1000 * o / w : 0), b / 1024 }'
  done
  if [ "$case" = arlequin_wave_2d_coarse ]; then
    t=$(median < "$work/$case.fast.total")
    o=$(median < "$work/$case.fast.output")
    awk -v t="$t" -v o="$o" 'BEGIN {
      printf "  criterion (output <= 5 %% of the default example, default level fast): %s\n", (o <= 0.05 * t) ? "met" : "NOT met" }'
  fi
done
