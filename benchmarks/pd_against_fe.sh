#!/usr/bin/env bash
# Cost of Contact/Model = PD against FE per time step, against no contact model, alternated in
# the same run REPEATS times (3), 1 rank x 2 threads. The 3D bar and plate of
# examples/bar_impact refined once (FE bar of 1 mm hexahedra, 36,663 DoFs) with the plate in
# peridynamics (dx = 0.5 mm, m = 1.5: 3,136 particles), the bar striking it at 1 m/s:
#  - none: Contact/Model = none (the bar passes through the plate: the bodies do not interact);
#  - end: PD against FE on the bar's impact end (boundary 10, 121 vertices);
#  - all: PD against FE on every boundary face of the bar (about 4,600 vertices gathered, and
#    their faces binned, every step).
#
#   benchmarks/pd_against_fe.sh [build-dir]
#
# Prints the median wall time of the time loop per step and the median per-repeat ratios.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

case_prm() { # none|end|all
  cat <<PRM
set Dimension = 3
subsection Geometry
  set Mesh file          = $top/examples/bar_impact/bar_and_plate.msh
  set Global refinements = 1
end
subsection Material
  set Young's modulus = 200e9
  set Poisson's ratio = 0.3
  set Density         = 7823
end
subsection Peridynamics
  set Region          = 0.1000005, 0, 0 : 0.102001, 0.014, 0.014
  set Lattice spacing = 5e-4
  set Horizon factor  = 1.5
end
subsection Initial conditions
  subsection function
    subsection Velocity
      set Function expression = x < 0.1000005 ? 1 : 0; 0; 0
    end
  end
end
subsection Contact
  set Model = $([ "$1" = none ] && echo none || echo PD against FE)
  subsection PD against FE
    set Boundary ids = $([ "$1" = end ] && echo 10 || echo)
  end
end
subsection Time
  set Time step = 4e-8
  set End time  = 2e-5
end
PRM
  silent_output
}

# Wall time per step of the time loop (its summary line "Time loop: N steps in T s").
time_per_step() {
  "$build/periarlequin" "$1" | awk '/^Time loop:/{print $6 / $3}'
}

for variant in none end all; do case_prm "$variant" > "$work/$variant.prm"; done
: > "$work/times"
for ((r = 0; r < repeats; r++)); do
  none=$(time_per_step "$work/none.prm")
  end=$(time_per_step "$work/end.prm")
  all=$(time_per_step "$work/all.prm")
  echo "$none $end $all $(awk "BEGIN{print $end / $none, $all / $none}")" >> "$work/times"
done
printf 'none %.4g s/step, end %.4g s/step, all %.4g s/step; end/none %.3f, all/none %.3f (medians of %d)\n' \
  "$(cut -d' ' -f1 "$work/times" | median)" "$(cut -d' ' -f2 "$work/times" | median)" \
  "$(cut -d' ' -f3 "$work/times" | median)" "$(cut -d' ' -f4 "$work/times" | median)" \
  "$(cut -d' ' -f5 "$work/times" | median)" "$repeats"
