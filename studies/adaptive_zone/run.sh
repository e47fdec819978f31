#!/bin/bash
# The adaptive PD zone study of this folder's README, in one command: the crack-branching plate
# (pure PD, the best fixed strip and the adaptive runs of ../crack_branching, made by its
# run.sh into <work>/branching), the mixed-mode kinks that the zone follows (the adaptive group
# of ../mixed_mode and the pure-PD and fixed-box runs it is compared with, into
# <work>/mixed_mode), and the zone figures of the shipped case
# parameter_files/adaptive_crack_branching_2d.prm (scripts/plot_zone.sh, into <work>/zone):
#   studies/adaptive_zone/run.sh <build directory> <work directory> [<mpi ranks>] [<parts>]
# <parts> (default: all): branching, kink, figures. About 40 minutes for branching and 50 for
# kink on one core.
set -euo pipefail
usage="usage: studies/adaptive_zone/run.sh <build directory> <work directory> [<mpi ranks>] [<parts>]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
parts=${4:-branching kink figures}
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)

for part in $parts; do
  case $part in
    branching)
      "$here/../crack_branching/run.sh" "$build" "$work/branching" "$ranks" \
        "pd_120 coupled8_120_narrow adaptive8_120 adaptive16_120 adaptive8_120_d3.75 adaptive8_120_d7.5 adaptive8_120_band3" ;;
    kink)
      "$here/../mixed_mode/run.sh" "$build" "$work/mixed_mode" "$ranks" "m6_coupled_angles adaptive" ;;
    figures)
      mkdir -p "$work/zone"
      {
        echo "include $top/parameter_files/adaptive_crack_branching_2d.prm"
        echo "subsection Output"
        echo "  set Directory = $work/zone"
        echo "end"
      } > "$work/zone.prm"
      mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$build/periarlequin" "$work/zone.prm" > "$work/zone.log" 2>&1
      "$top/scripts/plot_zone.sh" "$work/zone" > /dev/null
      echo "wrote the zone figures to $work/zone" ;;
    *) echo "unknown part $part" >&2; exit 1 ;;
  esac
done
