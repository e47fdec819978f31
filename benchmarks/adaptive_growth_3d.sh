#!/usr/bin/env bash
# Where a 3D growth's time goes, on a real case: the glass plate of
# studies/adaptive_zone/plate_3d.prm at lattice 0.5 mm (0.1-0.3 million particles while the
# zone grows), the adaptive zone of the study (PD on [0, 40] x [20, 30] mm, band 5 mm, default
# adaptive settings), 24 µs, 1 rank, 1 thread: the time loop, all growth and its phases
# (timing summary), REPEATS (3) runs; medians. About 45 s a run.
#
#   benchmarks/adaptive_growth_3d.sh [build-dir] [other-build-dir]
#
# With a second build (a directory holding periarlequin and libperiarlequin.so of another
# commit), both are run alternated, so that ratios of the medians mean something on a machine
# whose speed drifts.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/benchmarks/common.sh"
builds_repeats_and_work "$@"
cat > "$work/case.prm" <<PRM
include $top/studies/adaptive_zone/plate_3d.prm
subsection Peridynamics
  set Region = 0, 0.02, 0 : 0.04, 0.03, 0.01
  set Lattice spacing = 5e-4
end
subsection Coupling
  set Method        = weak
  set Blending      = force
  set Overlap width = 0.005
end
subsection Adaptive PD zone
  set Conversion criterion = damage distance
end
subsection Time
  set End time = 2.4e-5
end
subsection Output
  set Directory = $work/out
  set Output interval = 0
  set Progress interval = 0
  set Print timing summary = true
end
PRM
phases="PD zone growth|growth: criteria|growth: PD zone|growth: FE zone|growth: coupling and accelerations"
for r in $(seq "$repeats"); do
  for b in "${!builds[@]}"; do
    log="$work/run_${b}_$r.log"
    (cd "$work" && DEAL_II_NUM_THREADS=1 LD_LIBRARY_PATH="${builds[$b]}" \
      "${builds[$b]}/periarlequin" case.prm > "$log" 2>&1)
  done
done
printf "%-36s" "median of $repeats [s]"
for b in "${!builds[@]}"; do printf " %12s" "build $((b + 1))"; done
[ "${#builds[@]}" = 2 ] && printf " %8s" "2 / 1"
echo
row() { # label, extractor command reading a log -> one number
  local label=$1; shift
  printf "%-36s" "$label"
  local values=()
  for b in "${!builds[@]}"; do
    values[$b]=$(for r in $(seq "$repeats"); do "$@" "$work/run_${b}_$r.log"; done | median)
    printf " %12.3f" "${values[$b]}"
  done
  [ "${#builds[@]}" = 2 ] && printf " %8.3f" "$(awk "BEGIN{print ${values[1]}/${values[0]}}")"
  echo
}
loop_time() { awk '/^Time loop/ {for (i = 1; i <= NF; ++i) if ($i == "in") print $(i+1)}' "$1"; }
phase_time() { awk -F'|' -v p="$1" '{l = $2; gsub(/^ +| +$/, "", l)} l == p {t = $4; gsub(/[ s]/, "", t); print t}' "$2"; }
row "time loop" loop_time
IFS='|' read -r -a names <<< "$phases"
for p in "${names[@]}"; do row "$p" phase_time "$p"; done
