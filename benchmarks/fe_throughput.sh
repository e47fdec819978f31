#!/usr/bin/env bash
# FE zone throughput in DoF-steps per second (DoFs x steps / wall time of the time loop),
# 2D and 3D, 1 and 2 MPI ranks, sizes up to about 1e6 DoFs. Prints the median of REPEATS
# runs per configuration and the parallel efficiency T1 / (2 T2) measured in the same run.
#
#   benchmarks/fe_throughput.sh [build-dir]      (REPEATS=3 STEPS=200 by default)
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
steps=${STEPS:-200}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

write_prm() { # dim, subdivisions, upper corner
  cat > "$work/case.prm" <<PRM
set Dimension = $1
subsection Geometry
  set Lower corner = $( [ "$1" = 2 ] && echo "0, 0" || echo "0, 0, 0" )
  set Upper corner = $3
  set Subdivisions = $2
end
subsection Time
  set Time step = 1e-9
  set End time = $(awk "BEGIN{print $steps*1e-9}")
end
subsection Initial conditions
  subsection function
    subsection Velocity
      set Function expression = $( [ "$1" = 2 ] && echo "sin(x); 0" || echo "sin(x); 0; 0" )
    end
  end
end
PRM
  silent_output >> "$work/case.prm"
}


run() { # ranks -> prints "dofs throughput" (median)
  local ranks=$1 out dofs
  for r in $(seq "$repeats"); do
    out=$(launch "$ranks" "$build/periarlequin" "$work/case.prm")
    echo "$out" | awk '/Time loop/{print $(NF-2)}'
    dofs=$(echo "$out" | awk '/FE DoFs/{for(i=1;i<=NF;i++) if($i=="FE") print $(i-1)}')
    echo "$dofs" > "$work/dofs"
  done | median
}

printf "%-4s %-14s %10s %16s %16s %11s\n" dim cells DoFs "1 rank DoF.s/s" "2 ranks DoF.s/s" efficiency
for config in "2 70,70 1,1" "2 220,220 1,1" "2 700,700 1,1" \
              "3 15,15,15 1,1,1" "3 32,32,32 1,1,1" "3 68,68,68 1,1,1"; do
  set -- $config
  write_prm "$1" "$2" "$3"
  t1=$(run 1); dofs=$(cat "$work/dofs")
  t2=$(run 2)
  printf "%-4s %-14s %10s %16.3e %16.3e %10.0f%%\n" "$1" "$2" "$dofs" "$t1" "$t2" \
    "$(awk "BEGIN{print 100*$t2/(2*$t1)}")"
done
