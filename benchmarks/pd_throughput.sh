#!/usr/bin/env bash
# PD throughput in bond-updates per second (family sizes summed over particles x steps /
# wall time of the time loop), 2D and 3D, and peak memory per particle. Per case, in the
# same run and alternated REPEATS times (3): ours with the lattice-stencil kernel on
# 1 rank x 1 thread, 1 rank x 2 threads, 2 ranks x 1 thread and two independent 1 x 1 runs
# at once (the machine's ceiling for two cores), with fracture on (critical stretch, a G0 so
# large that no bond breaks: the cost of the stretch test) on 1 rank x 1 and x 2 threads,
# ours with the bond-list kernel on 1 rank x 1 thread; in 3D LAMMPS's peri/lps on 1 and 2 ranks when Debian's
# `lammps` is installed (the same simple cubic lattice: h = 1 mm, horizon 3.015 h,
# E = 69 GPa, nu = 0.3, rho = 2700, dt = 1e-8 s, small random velocities, no fracture, the
# same step count).
#
#   benchmarks/pd_throughput.sh [build-dir]        (REPEATS=3 by default; CONFIGS below)
#
# Medians of REPEATS runs, and medians of the per-repeat ratios. Memory per particle is
# marginal: the growth of the peak resident set between the smallest and the largest 3D case
# divided by the growth in particles, so the fixed cost of the libraries is not counted (the
# same for both codes). The two codes count different families: LAMMPS bonds reach
# |xi| <= delta, ours reach delta + h/2 with the partial volumes of eq. 22 (about 45 % more
# bonds per particle), so particle-steps per second are printed too.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$top/benchmarks/common.sh"
lammps_input="$top/benchmarks/lammps/in.lps_block3d"
have_lammps=false
if command -v lmp >/dev/null && [ -f "$lammps_input" ]; then have_lammps=true; fi


write_prm() { # dim, n per edge, steps, force kernel[, fracture] -> $work/case.<kernel>[.fracture].prm
  local dim=$1 n=$2 steps=$3 kernel=$4 fracture=${5:-} L cells lower upper region velocity file
  file="$work/case.${kernel// /_}${fracture:+.fracture}.prm"
  L=$(awk "BEGIN{print $n*1e-3}")
  cells=$(( n / 4 ))
  if [ "$dim" = 3 ]; then
    lower="0, 0, 0"; upper="$L, $L, $L"; cells="$cells, $cells, $cells"
    velocity="1e-2*sin(1e5*x*y+z); 1e-2*cos(3e5*y*z+x); 1e-2*sin(7e4*z*x+y)"
  else
    lower="0, 0"; upper="$L, $L"; cells="$cells, $cells"
    velocity="1e-2*sin(1e5*x*y); 1e-2*cos(3e5*y+x)"
  fi
  cat > "$file" <<PRM
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
  set Force kernel = $kernel
  set Fracture = ${fracture:-false}
  set Critical energy release rate = 1e12
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
  silent_output >> "$file"
}

# ours: prints "bond-updates/s particle-steps/s peak-RSS-kB particles"
run_ours() { # ranks threads steps prm
  local out rss
  out=$( { DEAL_II_NUM_THREADS=$2 /usr/bin/time -f "RSS %M" bash -c "$(declare -f launch); launch $1 '$build/periarlequin' '$4'"; } 2>&1 )
  rss=$(echo "$out" | awk '/^RSS/{print $2}')
  echo "$out" | awk -v steps="$3" -v rss="$rss" '
    /PD particles/ {for (i = 1; i <= NF; ++i) if ($i == "PD") particles = $(i-1)}
    /Time loop/    {for (i = 1; i <= NF; ++i) if ($i == "in") t = $(i+1);
                    for (i = 1; i <= NF; ++i) if ($i == "PD" && $(i+1) == "bond-updates/s") b = $(i-1)}
    END {printf "%s %s %s %s\n", b, particles*steps/t, rss, particles}'
}

# Two independent 1 x 1 runs at once, their rates summed: what the two cores give work that
# shares nothing (no messages, no threads' synchronisation), the machine's own ceiling for
# 2 ranks or 2 threads (shared caches, memory, the host's scheduling of the virtual cores).
run_pair() { # steps prm
  run_ours 1 1 "$1" "$2" > "$work/pair.a" &
  run_ours 1 1 "$1" "$2" > "$work/pair.b"
  wait
  paste -d' ' "$work/pair.a" "$work/pair.b" | awk '{print $1 + $5, $2 + $6, $3, $4}'
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


printf "%-32s %-4s %10s %14s %14s\n" code dim particles "bond-upd/s" "particle-st/s"
declare -A rss_ours rss_lammps n_parts
# "dim particles-per-edge steps" cases, ';'-separated (CONFIGS overrides).
IFS=';' read -ra configs <<< "${CONFIGS:-3 22 40;3 46 40;3 67 20;2 100 200;2 316 100;2 1000 20}"
variants="stencil-1x1 stencil-1x2 stencil-2x1 stencil-pair fracture-1x1 fracture-1x2 list-1x1"
for config in "${configs[@]}"; do
  set -- $config
  dim=$1 n=$2 steps=$3
  write_prm "$dim" "$n" "$steps" stencil
  write_prm "$dim" "$n" "$steps" stencil true
  write_prm "$dim" "$n" "$steps" "bond list"
  names="$variants"
  if [ "$dim" = 3 ] && $have_lammps; then names="$names lammps-1 lammps-2"; fi
  rm -f "$work"/result.*
  for r in $(seq "$repeats"); do
    for v in $names; do
      case $v in
        stencil-1x1) line=$(run_ours 1 1 "$steps" "$work/case.stencil.prm") ;;
        stencil-1x2) line=$(run_ours 1 2 "$steps" "$work/case.stencil.prm") ;;
        stencil-2x1) line=$(run_ours 2 1 "$steps" "$work/case.stencil.prm") ;;
        stencil-pair) line=$(run_pair "$steps" "$work/case.stencil.prm") ;;
        fracture-1x1) line=$(run_ours 1 1 "$steps" "$work/case.stencil.fracture.prm") ;;
        fracture-1x2) line=$(run_ours 1 2 "$steps" "$work/case.stencil.fracture.prm") ;;
        list-1x1)    line=$(run_ours 1 1 "$steps" "$work/case.bond_list.prm") ;;
        lammps-1)    line=$(run_lammps 1 "$n" "$steps") ;;
        lammps-2)    line=$(run_lammps 2 "$n" "$steps") ;;
      esac
      echo "$line" >> "$work/result.$v"
    done
  done
  for v in $names; do
    b=$(awk '{print $1}' "$work/result.$v" | median)
    p=$(awk '{print $2}' "$work/result.$v" | median)
    parts=$(head -1 "$work/result.$v" | awk '{print $4}')
    label=$(echo "$v" | sed -e 's/^stencil-\(.\)x\(.\)/ours stencil, \1 rank x \2 thread/' \
      -e 's/^stencil-pair/ours stencil, 2 x (1 x 1) at once/' \
      -e 's/^fracture-\(.\)x\(.\)/ours stencil+fracture, \1 x \2/' \
      -e 's/^list-1x1/ours bond list, 1 rank x 1 thread/' -e 's/^lammps-\(.\)/LAMMPS \1 rank/')
    printf "%-32s %-4s %10s %14.3e %14.3e\n" "$label" "${dim}D" "$parts" "$b" "$p"
  done
  # Ratios per repeat (the runs of one repeat were side by side), then their median.
  ratio() { paste -d' ' "$work/result.$1" "$work/result.$2" | awk -v c="$3" '{print $c / $(c + 4)}' | median; }
  printf "  ratios: stencil/bond list %.2f, 2 threads/1 %.2f, 2 ranks/1 %.2f, 2 independent runs/1 %.2f" \
    "$(ratio stencil-1x1 list-1x1 1)" "$(ratio stencil-1x2 stencil-1x1 1)" "$(ratio stencil-2x1 stencil-1x1 1)" \
    "$(ratio stencil-pair stencil-1x1 1)"
  # Rates, so off/on is the step time with fracture on over that with it off.
  printf ", step time fracture on/off: 1 thread %.2f, 2 threads %.2f" \
    "$(ratio stencil-1x1 fracture-1x1 1)" "$(ratio stencil-1x2 fracture-1x2 1)"
  if [ "$dim" = 3 ] && $have_lammps; then
    printf ", ours/LAMMPS per particle-step on 1 rank %.2f" "$(ratio stencil-1x1 lammps-1 2)"
  fi
  echo
  if [ "$dim" = 3 ]; then
    rss_ours[$n]=$(awk '{print $3}' "$work/result.stencil-1x1" | median)
    n_parts[$n]=$(head -1 "$work/result.stencil-1x1" | awk '{print $4}')
    if $have_lammps; then rss_lammps[$n]=$(awk '{print $3}' "$work/result.lammps-1" | median); fi
  fi
done
echo
[ -n "${rss_ours[22]:-}" ] && [ -n "${rss_ours[67]:-}" ] || exit 0
awk -v a="${rss_ours[22]}" -v b="${rss_ours[67]}" -v na="${n_parts[22]}" -v nb="${n_parts[67]}" \
  'BEGIN{printf "ours   3D marginal peak memory per particle (stencil): %.2f KB\n", (b-a)*1.024/(nb-na)}'
if $have_lammps; then
  awk -v a="${rss_lammps[22]}" -v b="${rss_lammps[67]}" -v na="${n_parts[22]}" -v nb="${n_parts[67]}" \
    'BEGIN{printf "LAMMPS 3D marginal peak memory per particle: %.2f KB\n", (b-a)*1.024/(nb-na)}'
fi
