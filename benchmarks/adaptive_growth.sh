#!/usr/bin/env bash
# The cost of one growth of the adaptive PD zone against the cells it converts and the size of
# the zone, in time steps of the same run (so that the machine's drift cancels): the program
# benchmarks/growth_cost.cc (target periarlequin-growth-cost) on a 2D plate 50 mm high, lattice
# 0.25 mm, FE cells 2 mm, a PD zone over the plate's height and ZONES metres long (25,000 to
# 100,000 particles), growing by a square patch of SIDES cells a side (1, 9, 36 cells) every
# 10 steps, 5 growths a run, 1 rank, REPEATS (3) runs of each; medians. Threads as the
# application (DEAL_II_NUM_THREADS, else every core); the records up to 2026-12-07 ran on one.
#
#   benchmarks/adaptive_growth.sh [build-dir] [other-build-dir]
#
# With a second build (the same program built from another commit, or a directory holding a
# copy of periarlequin-growth-cost and libperiarlequin.so), both are run alternated and the
# ratio of their growth costs is printed; LABELS names the builds in the figure
# ("build 1,build 2"). Writes adaptive_growth.csv and, with
# gnuplot, adaptive_growth.png (growth cost in steps against the converted cells) in the
# current directory.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/benchmarks/common.sh"
builds_repeats_and_work "$@"
zones=${ZONES:-"0.032 0.064 0.126"}
sides=${SIDES:-"1 3 6"}
IFS=, read -r -a labels <<< "${LABELS:-build 1,build 2}"
growths=5
for b in "${builds[@]}"; do
  [ -f "$b/CMakeCache.txt" ] && cmake --build "$b" --target periarlequin-growth-cost > /dev/null
done

# One run: particles, growth [ms], step [ms] (the loop's time without the growths, per step).
measure() { # build zone side
  (cd "$work" && LD_LIBRARY_PATH="$1${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    "$1/periarlequin-growth-cost" 2.5e-4 "$2" "$3" "$growths") | awk -v g="$growths" '
    /PD particles/ {for (i = 1; i <= NF; ++i) if ($i == "PD") n = $(i - 1)}
    /^Time loop:/ {steps = $3; loop = $6}
    /^\| PD zone growth/ {split($0, f, "|"); split(f[6], t, " "); growth = t[1]}  # the slowest rank
    END {printf "%d %.3f %.3f\n", n, 1e3 * growth / g, 1e3 * (loop - growth) / steps}'
}

echo "zone [particles], converted cells a growth: growth [ms], step [ms], growth [steps]; medians of $repeats"
echo "build,particles,cells,growth_ms,step_ms,growth_steps" > adaptive_growth.csv
for zone in $zones; do
  for side in $sides; do
    for k in "${!builds[@]}"; do : > "$work/runs_$k"; done
    for r in $(seq "$repeats"); do
      for k in "${!builds[@]}"; do measure "${builds[$k]}" "$zone" "$side" >> "$work/runs_$k"; done
    done
    line="$(head -1 "$work/runs_0" | cut -d' ' -f1) particles, $((side * side)) cells:"
    for k in "${!builds[@]}"; do
      growth=$(cut -d' ' -f2 "$work/runs_$k" | median)
      step=$(cut -d' ' -f3 "$work/runs_$k" | median)
      in_steps=$(awk '{print $2 / $3}' "$work/runs_$k" | median)
      line+=" build $((k + 1)): $growth ms, step $step ms, $in_steps steps;"
      echo "$((k + 1)),$(head -1 "$work/runs_$k" | cut -d' ' -f1),$((side * side)),$growth,$step,$in_steps" >> adaptive_growth.csv
    done
    if [ "${#builds[@]}" = 2 ]; then
      line+=" build 2 / build 1 (growth): $(paste -d' ' "$work/runs_0" "$work/runs_1" | awk '{print $5 / $2}' | median)"
    fi
    echo "$line"
  done
done

if command -v gnuplot > /dev/null; then
  {
    echo "set datafile separator ','; set terminal pngcairo size 900,600 noenhanced"
    echo "set output 'adaptive_growth.png'; set key left top; set logscale x"
    echo "set xlabel 'FE cells converted in one growth'; set ylabel 'cost of one growth [time steps]'"
    printf "plot "
    sep=""
    for k in "${!builds[@]}"; do
      for n in $(awk -F, -v b=$((k + 1)) '$1 == b {print $2}' adaptive_growth.csv | sort -un); do
        printf "%s\"< awk -F, '\$1 == %d && \$2 == %d' adaptive_growth.csv\" using 3:6 with linespoints title '%s, %d particles'" \
          "$sep" $((k + 1)) "$n" "${labels[$k]}" "$n"
        sep=", "
      done
    done
    echo
  } | gnuplot
fi
