#!/usr/bin/env bash
# Cost of Peridynamics/Particle contact per time step, contact on against off, alternated in
# the same run REPEATS times (3), 1 rank x 2 threads:
#  - at rest: a 3D block of 46^3 = 97,336 particles (h = 1 mm, m = 3) with small random
#    velocities; no pair ever touches, so contact costs its per-step check (the drift since
#    the last list and the spread of the displacements) and one list;
#  - colliding: two 3D bars 40 x 4 x 4 mm, dx = 0.2 mm (80,000 particles), cut apart by a
#    pre-crack, the left one at 50 m/s (in contact after 0.4 us, for the rest of the 6 us; the
#    400 particles of each face touch). With contact off the bars pass through each other:
#    the same bond work;
#  - impact: the impact-driven mode II plate of studies/adaptive_zone/impact_mode_ii.prm
#    (80,000 particles in 2D, pure PD with fracture, struck at 32 m/s; crack faces touch).
#
#   benchmarks/particle_contact.sh [build-dir]
#
# Prints the median wall time of the time loop per step and the median per-repeat ratio.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"

block_prm() { # contact on|off
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
  subsection Particle contact
    set Enable = $([ "$1" = on ] && echo true || echo false)
  end
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
subsection Time
  set Time step = 5e-8
  set End time = 1e-5
end
PRM
  silent_output
}

bars_prm() { # contact on|off
  cat <<PRM
set Dimension = 3
subsection Geometry
  set Lower corner = 0, 0, 0
  set Upper corner = 0.04, 0.004, 0.004
  set Subdivisions = 40, 4, 4
end
subsection Material
  set Young's modulus = 72e9
  set Poisson's ratio = 0.22
  set Density = 2440
end
subsection Peridynamics
  set Region = 0, 0, 0 : 0.04, 0.004, 0.004
  set Lattice spacing = 2e-4
  set Horizon factor = 3
  set Pre-cracks = 0.02, -0.001, -0.001 : 0, 0.006, 0 : 0, 0, 0.006
  subsection Particle contact
    set Enable = $([ "$1" = on ] && echo true || echo false)
  end
end
subsection Coupling
  set Method = none
end
subsection Initial conditions
  subsection function
    subsection Velocity
      set Function expression = if(x < 0.02, 50, 0); 0; 0
    end
  end
end
subsection Time
  set Time step = 1.2e-8
  set End time = 6e-6
end
PRM
  silent_output
}

impact_prm() { # contact on|off
  sed -e '/^subsection Output/,/^end/d' -e 's/energies, cracks, zone sizes/energies/' \
    "$top/studies/adaptive_zone/impact_mode_ii.prm"
  printf 'subsection Peridynamics\n  subsection Particle contact\n    set Enable = %s\n  end\nend\n' \
    "$([ "$1" = on ] && echo true || echo false)"
  silent_output
}

# Wall time per step of the time loop (its summary line "Time loop: N steps in T s").
time_per_step() {
  "$build/periarlequin" "$1" | awk '/^Time loop:/{print $6 / $3}'
}

for case in block bars impact; do
  "${case}_prm" off > "$work/$case.off.prm"
  "${case}_prm" on > "$work/$case.on.prm"
  : > "$work/$case.times"
  for ((r = 0; r < repeats; r++)); do
    off=$(time_per_step "$work/$case.off.prm")
    on=$(time_per_step "$work/$case.on.prm")
    echo "$off $on $(awk "BEGIN{print $on / $off}")" >> "$work/$case.times"
  done
  printf '%-6s contact off %.4g s/step, on %.4g s/step, on/off %.3f (medians of %d)\n' "$case" \
    "$(cut -d' ' -f1 "$work/$case.times" | median)" "$(cut -d' ' -f2 "$work/$case.times" | median)" \
    "$(cut -d' ' -f3 "$work/$case.times" | median)" "$repeats"
done
