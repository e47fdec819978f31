#!/usr/bin/env bash
# Cost of Contact/Model = rigid projectile per time step, against no contact model, alternated
# in the same run REPEATS times (3), 1 rank x 2 threads. A 3D block of 46^3 = 97,336
# particles (dx = 1 mm, m = 3) with small random velocities, and:
#  - none: Contact/Model = none;
#  - far: a flat punch 10 x 10 x 10 mm 20 mm above the block, at rest (never touches: the
#    particles' broad phase against the punch's reach, every step);
#  - pressing: the same punch on the block's top face, driven into it at 5 m/s (a mass of
#    1e6 kg): the 100 particles under it touch from the first steps on.
#
#   benchmarks/rigid_projectile.sh [build-dir]
#
# Prints the median wall time of the time loop per step and the median per-repeat ratios.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

block_prm() { # none|far|pressing
  cat <<PRM
set Dimension = 3
subsection Geometry
  set Lower corner = 0, 0, 0
  set Upper corner = 0.046, 0.046, 0.046
  set Subdivisions = 11, 11, 11
end
subsection Material
  set Young's modulus = 69e9
  set Poisson's ratio = 0.3
  set Density = 2700
end
subsection Peridynamics
  set Region = 0, 0, 0 : 0.046, 0.046, 0.046
  set Lattice spacing = 1e-3
  set Horizon factor = 3
end
subsection Coupling
  set Method = none
end
subsection Initial conditions
  subsection function
    subsection Velocity
      set Function expression = 1e-2*sin(1e5*x*y+z); 1e-2*cos(3e5*y*z+x); 1e-2*sin(7e4*z*x+y)
    end
  end
end
subsection Contact
  set Model = $([ "$1" = none ] && echo none || echo rigid projectile)
  subsection rigid projectile
    set Shape      = flat punch
    set Half sizes = 0.005, 0.005, 0.005
    set Mass       = 1e6
    set Position   = 0.023, 0.023, $([ "$1" = far ] && echo 0.071 || echo 0.051001)
    set Velocity   = 0, 0, $([ "$1" = far ] && echo 0 || echo -5)
  end
end
subsection Time
  set Time step = 5e-8
  set End time = 1e-5
end
PRM
  silent_output
}

# Wall time per step of the time loop (its summary line "Time loop: N steps in T s").
time_per_step() {
  "$build/periarlequin" "$1" | awk '/^Time loop:/{print $6 / $3}'
}

for variant in none far pressing; do block_prm "$variant" > "$work/$variant.prm"; done
: > "$work/times"
for ((r = 0; r < repeats; r++)); do
  none=$(time_per_step "$work/none.prm")
  far=$(time_per_step "$work/far.prm")
  pressing=$(time_per_step "$work/pressing.prm")
  echo "$none $far $pressing $(awk "BEGIN{print $far / $none, $pressing / $none}")" >> "$work/times"
done
printf 'none %.4g s/step, far %.4g s/step, pressing %.4g s/step; far/none %.3f, pressing/none %.3f (medians of %d)\n' \
  "$(cut -d' ' -f1 "$work/times" | median)" "$(cut -d' ' -f2 "$work/times" | median)" \
  "$(cut -d' ' -f3 "$work/times" | median)" "$(cut -d' ' -f4 "$work/times" | median)" \
  "$(cut -d' ' -f5 "$work/times" | median)" "$repeats"
