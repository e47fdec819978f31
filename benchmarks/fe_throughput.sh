#!/usr/bin/env bash
# FE zone throughput in DoF-steps per second (DoFs x steps / wall time of the time loop),
# 2D and 3D, sizes up to about 1e6 DoFs, on 1 rank x 1 thread, 1 rank x 2 threads and
# 2 ranks x 1 thread. The three run alternately, REPEATS times; prints the median of each and
# the medians of the per-repeat ratios to 1 x 1.
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


run() { # ranks threads -> prints "DoFs DoF-steps/s" of one run
  local out
  out=$(DEAL_II_NUM_THREADS=$2 launch "$1" "$build/periarlequin" "$work/case.prm")
  echo "$out" | awk '/FE DoFs/{for(i=1;i<=NF;i++) if($i=="FE") d=$(i-1)}
                     /Time loop/{t=$(NF-2)} END{print d, t}'
}

printf "%-4s %-10s %8s %15s %15s %15s %9s %9s\n" dim cells DoFs "1x1 DoF.s/s" "1x2 DoF.s/s" \
  "2x1 DoF.s/s" "1x2/1x1" "2x1/1x1"
for config in "2 70,70 1,1" "2 220,220 1,1" "2 700,700 1,1" \
              "3 15,15,15 1,1,1" "3 32,32,32 1,1,1" "3 68,68,68 1,1,1"; do
  set -- $config
  write_prm "$1" "$2" "$3"
  rm -f "$work"/result.*
  for r in $(seq "$repeats"); do
    for v in 1x1 1x2 2x1; do run "${v%x*}" "${v#*x}" >> "$work/result.$v"; done
  done
  dofs=$(head -1 "$work/result.1x1" | awk '{print $1}')
  # Ratios per repeat (the runs of one repeat were side by side), then their median.
  ratio() { paste -d' ' "$work/result.$1" "$work/result.1x1" | awk '{print $2 / $4}' | median; }
  printf "%-4s %-10s %8s %15.3e %15.3e %15.3e %9.2f %9.2f\n" "$1" "$2" "$dofs" \
    "$(awk '{print $2}' "$work/result.1x1" | median)" "$(awk '{print $2}' "$work/result.1x2" | median)" \
    "$(awk '{print $2}' "$work/result.2x1" | median)" "$(ratio 1x2)" "$(ratio 2x1)"
done
