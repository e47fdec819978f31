#!/usr/bin/env bash
# Two builds side by side on the same cases, runs alternated (this machine's speed drifts
# by tens of per cent over minutes, and some runs land in a mode 1.6x slower, so only ratios
# of alternated runs mean something): medians and minima of REPEATS (7) time-loop wall times
# of each build and their ratios, per case.
#
#   benchmarks/compare_builds.sh BUILD_A BUILD_B case.prm [case.prm ...]
#
# Output, progress and timing summary are switched off in each case (files are not timed).
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/benchmarks/common.sh"
a=$(cd "$1" && pwd); b=$(cd "$2" && pwd); shift 2
repeats=${REPEATS:-7}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

loop_time() { # build prm -> wall time of the time loop [s]
  # Each build's own library, also for a program copied out of its build directory.
  (cd "$work" && LD_LIBRARY_PATH="$1${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$1/periarlequin" "$2") | awk '/^Time loop/ {for (i = 1; i <= NF; ++i) if ($i == "in") print $(i+1)}'
}

printf "%-32s %10s %10s %8s %10s %10s %8s\n" case "A median" "B median" "B / A" "A min" "B min" "B / A"
for prm in "$@"; do
  { cat "$prm"; silent_output; } > "$work/case.prm"
  : > "$work/a"; : > "$work/b"
  for r in $(seq "$repeats"); do
    loop_time "$a" "$work/case.prm" >> "$work/a"
    loop_time "$b" "$work/case.prm" >> "$work/b"
  done
  ta=$(median < "$work/a"); tb=$(median < "$work/b")
  ma=$(sort -g "$work/a" | head -1); mb=$(sort -g "$work/b" | head -1)
  printf "%-32s %10.3f %10.3f %8.3f %10.3f %10.3f %8.3f\n" "$(basename "$prm")" "$ta" "$tb" \
    "$(awk "BEGIN{print $tb/$ta}")" "$ma" "$mb" "$(awk "BEGIN{print $mb/$ma}")"
done
