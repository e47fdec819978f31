# Shared by the benchmark scripts (sourced): MPI settings for root on small machines, the
# median of numbers on stdin, a launcher for 1 or more ranks, and the Output subsection that
# turns off files and progress so that only the time loop is timed.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none

median() { sort -g | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}'; }

launch() { # ranks, command...
  local ranks=$1; shift
  if [ "$ranks" = 1 ]; then "$@"; else mpirun -np "$ranks" "$@"; fi
}

silent_output() {
  cat <<'PRM'
subsection Output
  set Output interval = 0
  set Energy interval = 0
  set Progress interval = 0
  set Print timing summary = false
end
PRM
}

# The build directories of a script's arguments ("[build-dir] [other-build-dir]", the first
# defaulting to $top/build) as absolute paths in the array builds; REPEATS (3) runs of each in
# repeats; a scratch directory in work, removed on exit.
builds_repeats_and_work() {
  builds=("$(cd "${1:-$top/build}" && pwd)")
  if [ -n "${2:-}" ]; then builds+=("$(cd "$2" && pwd)"); fi
  repeats=${REPEATS:-3}
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}
