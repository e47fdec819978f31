#!/usr/bin/env bash
# PD throughput in bond-updates per second (family sizes summed over particles x steps /
# wall time of the time loop), 2D and 3D, 1 and 2 MPI ranks, and peak memory per particle;
# in 3D side by side, in the same run, with LAMMPS's peri/lps on the same simple cubic
# lattice (h = 1 mm, horizon 3.015 h, E = 69 GPa, nu = 0.3, rho = 2700, dt = 1e-8 s, small
# random velocities, no fracture, same step count) when Debian's `lammps` is installed.
#
#   benchmarks/pd_throughput.sh [build-dir]        (REPEATS=3 by default; CONFIGS below)
#
# Medians of REPEATS runs. Memory per particle is marginal: the growth of the peak resident
# set between the smallest and the largest 3D case divided by the growth in particles, so
# the fixed cost of the libraries is not counted (the same for both codes). Note that the
# two codes count different families: LAMMPS bonds reach |xi| <= delta, ours reach
# delta + h/2 with the partial volumes of eq. 22 (about 45 % more bonds per particle), so
# particle-steps per second are printed too.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"
lammps_input="$top/../shared/bench/lammps-peri-lps/in.lps_block3d"
have_lammps=false
if command -v lmp >/dev/null && [ -f "$lammps_input" ]; then have_lammps=true; fi


write_prm() { # dim, n per edge, steps
  local dim=$1 n=$2 steps=$3 L cells lower upper region velocity
  L=$(awk "BEGIN{print $n*1e-3}")
  cells=$(( n / 4 ))
  if [ "$dim" = 3 ]; then
    lower="0, 0, 0"; upper="$L, $L, $L"; cells="$cells, $cells, $cells"
    velocity="1e-2*sin(1e5*x*y+z); 1e-2*cos(3e5*y*z+x); 1e-2*sin(7e4*z*x+y)"
  else
    lower="0, 0"; upper="$L, $L"; cells="$cells, $cells"
    velocity="1e-2*sin(1e5*x*y); 1e-2*cos(3e5*y+x)"
  fi
  cat > "$work/case.prm" <<PRM
set Dimension = $dim
subsection Geometry
  set Lower corner = $lower
  set Upper corner = $upper
  set Subdivisions = $cells
end
subsection Material
  set Young's modulus = 69e9
  set Poisson's ratio = 0.3
  set Density = 2700
end
subsection Peridynamics
  set Region = $lower : $upper
  set Lattice spacing = 1e-3
  set Horizon factor = 3.015
end
subsection Time
  set Time step = 1e-8
  set End time = $(awk "BEGIN{print $steps*1e-8}")
  set Stability estimate iterations = 10
end
subsection Initial conditions
  subsection function
    subsection Velocity
      set Function expression = $velocity
    end
  end
end
PRM
  silent_output >> "$work/case.prm"
}

# ours: prints "bond-updates/s particle-steps/s peak-RSS-kB particles"
run_ours() { # ranks steps
  local out rss
  out=$( { /usr/bin/time -f "RSS %M" bash -c "$(declare -f launch); launch $1 '$build/periarlequin' '$work/case.prm'"; } 2>&1 )
  rss=$(echo "$out" | awk '/^RSS/{print $2}')
  echo "$out" | awk -v steps="$2" -v rss="$rss" '
    /PD particles/ {for (i = 1; i <= NF; ++i) if ($i == "PD") particles = $(i-1)}
    /Time loop/    {for (i = 1; i <= NF; ++i) if ($i == "in") t = $(i+1);
                    for (i = 1; i <= NF; ++i) if ($i == "PD" && $(i+1) == "bond-updates/s") b = $(i-1)}
    END {printf "%s %s %s %s\n", b, particles*steps/t, rss, particles}'
}

# LAMMPS: the same, from its "total # of bonds" and the second "Loop time"; fails if a
# bond broke (the printed maximum damage must stay 0)
run_lammps() { # ranks n steps
  local out rss
  out=$( { cd "$work" && /usr/bin/time -f "RSS %M" bash -c "$(declare -f launch); launch $1 lmp -in '$lammps_input' -var N $2 -var nsteps $3 -log none"; } 2>&1 )
  rss=$(echo "$out" | awk '/^RSS/{print $2}')
  echo "$out" | awk -v steps="$3" -v rss="$rss" '
    /total # of bonds/ {bonds = $NF}
    /Loop time/ {n++; if (n == 2) {t = $4; atoms = $(NF-1)}}
    $1 == steps && NF == 5 {damage = $5}
    END {if (damage + 0 != 0) {print "LAMMPS damage " damage " != 0" > "/dev/stderr"; exit 1}
         printf "%s %s %s %s\n", bonds*steps/t, atoms*steps/t, rss, atoms}'
}

measure() { # label command... -> median line
  local label=$1; shift
  for r in $(seq "$repeats"); do "$@"; done | sort -g -k1 | awk '{a[NR]=$0} END{print a[int((NR+1)/2)]}'
}

printf "%-6s %-5s %10s %6s %16s %16s\n" code dim particles ranks "bond-upd/s" "particle-st/s"
declare -A rss_ours rss_lammps n_parts
# "dim particles-per-edge steps" cases, ';'-separated (CONFIGS overrides).
IFS=';' read -ra configs <<< "${CONFIGS:-3 22 40;3 46 40;3 67 20;2 100 200;2 316 100;2 1000 20}"
for config in "${configs[@]}"; do
  set -- $config
  dim=$1 n=$2 steps=$3
  write_prm "$dim" "$n" "$steps"
  for ranks in 1 2; do
    line=$(measure ours run_ours "$ranks" "$steps")
    read -r b p rss parts <<< "$line"
    printf "%-6s %-5s %10s %6s %16.3e %16.3e\n" ours "${dim}D" "$parts" "$ranks" "$b" "$p"
    if [ "$dim" = 3 ] && [ "$ranks" = 1 ]; then rss_ours[$n]=$rss; n_parts[$n]=$parts; fi
    if [ "$dim" = 3 ] && $have_lammps; then
      line=$(measure lammps run_lammps "$ranks" "$n" "$steps")
      read -r b p rss parts <<< "$line"
      printf "%-6s %-5s %10s %6s %16.3e %16.3e\n" LAMMPS "${dim}D" "$parts" "$ranks" "$b" "$p"
      if [ "$ranks" = 1 ]; then rss_lammps[$n]=$rss; fi
    fi
  done
done
echo
[ -n "${rss_ours[22]:-}" ] && [ -n "${rss_ours[67]:-}" ] || exit 0
awk -v a="${rss_ours[22]}" -v b="${rss_ours[67]}" -v na="${n_parts[22]}" -v nb="${n_parts[67]}" \
  'BEGIN{printf "ours   3D marginal peak memory per particle: %.2f KB\n", (b-a)*1.024/(nb-na)}'
if $have_lammps; then
  awk -v a="${rss_lammps[22]}" -v b="${rss_lammps[67]}" -v na="${n_parts[22]}" -v nb="${n_parts[67]}" \
    'BEGIN{printf "LAMMPS 3D marginal peak memory per particle: %.2f KB\n", (b-a)*1.024/(nb-na)}'
fi
