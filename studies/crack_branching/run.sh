#!/bin/bash
# The crack-branching study of this folder's README (section 6.2 of the paper, on the
# peridynamic branching benchmark): the glass plate of plate.prm. Runs pure PD and coupled (PD strip around
# the crack line, overlaps of 5 FE cells above and below, FE beyond, weak coupling, force
# blending, fine-scale damping) at FE/PD size ratios 8 and 16, on the 100 x 40 mm plate and on
# the 100 x 120 mm plate, and with an adaptive PD zone that starts around the notch and grows
# with the crack (../adaptive_zone), then prints the table and draws the figures:
#   studies/crack_branching/run.sh <build directory> <work directory> [<mpi ranks> [<runs>]]
# <runs>: a space-separated list of run names to make (default: all). The adaptive runs
# repartition on several ranks as 'Adaptive PD zone/Load imbalance tolerance' says, 0.1 or
# the environment's LOAD_IMBALANCE_TOLERANCE.
# Every run is <work directory>/<name>.prm, a file that includes plate.prm and sets what the
# run changes. Figures (scripts/plot_cracks.sh) and the table go to <work directory>; takes
# some minutes.
set -euo pipefail
usage="usage: studies/crack_branching/run.sh <build directory> <work directory> [<mpi ranks> [<runs>]]"
build=$(cd "${1:?$usage}" && pwd)
work=${2:?$usage}
ranks=${3:-1}
only=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
scripts=$(cd "$here/../../scripts" && pwd)
mkdir -p "$work"
cd "$work"
source "$scripts/study_lib.sh"

# case_file <name> <height [m]> <PD strip half width [m], 0: pure PD> <FE cell [m]> <overlap cells>
#           [<damage distance [m]>: adaptive PD zone, starting as the strip along the notch]
# writes the run's parameters: plate.prm and what this run changes.
case_file() {
  local name=$1 height=$2 half=$3 cell=$4 layers=$5 distance=${6:-}
  local mid
  mid=$(calc "$height / 2")
  cat << EOF
include $here/plate.prm
subsection Geometry
  set Upper corner = 0.1, $height
  set Subdivisions = $(calc "int(0.1 / $cell + 0.5)"), $(calc "int($height / $cell + 0.5)")
end
subsection Peridynamics
  set Pre-cracks = 0, $mid : 0.05, $mid
EOF
  if [ "$half" = 0 ]; then
    echo "  set Region = 0, 0 : 0.1, $height"
    echo "end"
  elif [ -n "$distance" ]; then
    # The notch and one cell around it; the band of the overlap moves with the zone.
    cat << EOF
  set Region = 0, $(calc "$mid - $half") : $(calc "0.05 + $cell"), $(calc "$mid + $half")
end
subsection Coupling
  set Method        = weak
  set Blending      = force
  set Overlap width = $(calc "$layers * $cell")
end
subsection Adaptive PD zone
  set Conversion criterion = damage distance
  set Check interval       = 20
  set Load imbalance tolerance = ${LOAD_IMBALANCE_TOLERANCE:-0.1}
  subsection damage distance
    set Distance = $distance
  end
end
EOF
  else
    local a b o1 o2
    a=$(calc "$mid - $half"); b=$(calc "$mid + $half")
    o1=$(calc "$a - $layers * $cell"); o2=$(calc "$b + $layers * $cell")
    echo "  set Region = 0, $a : 0.1, $b"
    echo "end"
    cat << EOF
subsection Coupling
  set Method                = weak
  set Blending              = force
  set Overlap region        = 0, $o1 : 0.1, $a ; 0, $b : 0.1, $o2
  set Finite element region = 0, 0 : 0.1, $o1 ; 0, $o2 : 0.1, $height
end
EOF
  fi
  cat << EOF
subsection Output
  set Directory = $name
end
EOF
}

run() {
  [ -z "$only" ] || [[ " $only " == *" $1 "* ]] || return 0
  run_case "$@"
  "$scripts/plot_cracks.sh" "$1" "${reference:-}" > /dev/null || true
}

# 100 x 40 mm: the branches spread to y = 20 +- 13 mm, so the PD strip must nearly fill the
# plate; with overlaps of 5 FE cells nothing is left for FE. Coupled with the widest strip that
# leaves 5 overlap cells and one FE cell: |y - 20| <= 5 mm (ratio 8); the run stops when the
# branches near the overlap.
reference=""
run pd_40 0.04 0 0.0025 5
reference=pd_40
run coupled8_40 0.04 0.005 0.0025 5
# 100 x 120 mm (the paper's aspect ratio): PD strip of a third of the height, |y - 60| <= 20 mm,
# and one chosen from where the cracks go in pure PD (y = 60 +- 4 mm): |y - 60| <= 10 mm.
reference=""
run pd_120 0.12 0 0.0025 5
reference=pd_120
run coupled8_120 0.12 0.02 0.0025 5
run coupled16_120 0.12 0.02 0.005 5
run coupled8_120_narrow 0.12 0.01 0.0025 5
run coupled16_120_narrow 0.12 0.01 0.005 5
# Adaptive: PD around the notch only (|y - 60| <= one cell), overlap band of 2 cells, FE cells
# within 5 mm of damage become PD (checked every 20 steps, 0.5 us).
run adaptive8_120 0.12 0.0025 0.0025 2 0.005
# The same at FE/PD 16 (cells 5 mm, band 10 mm); at FE/PD 8 with damage distances of 3.75 and
# 7.5 mm, and with a wider band (3 cells) at 3.75 mm.
run adaptive16_120 0.12 0.005 0.005 2 0.005
run adaptive8_120_d3.75 0.12 0.0025 0.0025 2 0.00375
run adaptive8_120_d7.5 0.12 0.0025 0.0025 2 0.0075
run adaptive8_120_band3 0.12 0.0025 0.0025 3 0.00375

# The table of the runs made (all, or those asked for).
made=()
for name in pd_40 coupled8_40 pd_120 coupled8_120 coupled16_120 coupled8_120_narrow \
  coupled16_120_narrow adaptive8_120 adaptive16_120 adaptive8_120_d3.75 adaptive8_120_d7.5 \
  adaptive8_120_band3; do
  [ -f "$name.log" ] && made+=("$name")
done
"$here/table.sh" "${made[@]}"
