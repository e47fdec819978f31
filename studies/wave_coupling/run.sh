#!/bin/bash
# The paper's section 6.1 study of this folder's README: runs the pure-PD reference and the
# bad, strict and weak couplings at dt = 1e-7 s and 1e-8 s (the shipped cases
# parameter_files/pd_wave_2d_reference*.prm and arlequin_wave_2d_{bad,strict,weak}_dt*.prm),
# plus, at dt = 1e-7 s, the weak coupling with the exact (CG) multiplier solve, with damping
# off and under the paper's and the force-based blending, then prints the results table
# (table.sh). Every run is <work directory>/<label>.prm, a file that includes its shipped case
# and sets what the run changes.
#   studies/wave_coupling/run.sh <build directory> <work directory> [jobs (default 2)] [dt list]
# e.g. studies/wave_coupling/run.sh build runs 2 "1e-7"  (the dt = 1e-7 s half, ~5 minutes on 2 cores)
# Runs that finished before (their log ends with the timer table) are not repeated.
set -euo pipefail
build=$(realpath "${1:?usage: wave_study.sh <build dir> <work dir> [jobs] [dt list]}")
mkdir -p "${2:?work directory}"
work=$(realpath "$2")
jobs=${3:-2}
dts=${4:-"1e-7 1e-8"}
here=$(realpath "$(dirname "$0")")
prm_dir=$(realpath "$here/../../parameter_files")

# make_case <label> <shipped case> [<Coupling entry>...]: writes <work>/<label>.prm, the
# shipped case with its own output directory <work>/<label> and the Coupling entries given
make_case() {
  local label=$1 source=$2 entry
  shift 2
  {
    echo "include $prm_dir/$source.prm"
    if [ $# -gt 0 ]; then
      echo "subsection Coupling"
      for entry in "$@"; do echo "  set $entry"; done
      echo "end"
    fi
    echo "subsection Output"
    echo "  set Directory = $work/$label"
    echo "end"
  } > "$work/$label.prm"
  echo "$label"
}

cases=$(
  for dt in $dts; do
    if [ "$dt" = 1e-7 ]; then make_case reference_dt1e-7 pd_wave_2d_reference
    else make_case reference_dt$dt pd_wave_2d_reference_dt$dt; fi
    for method in bad strict weak; do
      make_case ${method}_dt$dt arlequin_wave_2d_${method}_dt$dt
    done
    if [ "$dt" = 1e-7 ]; then
      make_case weak_cg_dt1e-7 arlequin_wave_2d_weak_dt1e-7 "Multiplier solver = cg"
      make_case weak_no_damping_dt1e-7 arlequin_wave_2d_weak_dt1e-7 "Fine-scale damping = false"
      make_case strict_cg_dt1e-7 arlequin_wave_2d_strict_dt1e-7 "Multiplier solver = cg"
      for blending in paper force; do
        make_case weak_${blending}_blending_dt1e-7 arlequin_wave_2d_weak_dt1e-7 "Blending = $blending"
      done
    fi
  done
)

run_case() {
  local label=$1 work=$2 build=$3
  if grep -qs "Total wallclock time elapsed" "$work/$label.log"; then
    echo "$label: done before"
    return
  fi
  local start=$SECONDS
  "$build/periarlequin" "$work/$label.prm" > "$work/$label.log" 2>&1 || { echo "$label: FAILED (see $work/$label.log)"; return 1; }
  echo "$label: $((SECONDS - start)) s"
}
export -f run_case
echo "$cases" | xargs -P "$jobs" -I{} bash -c 'run_case {} "$0" "$1"' "$work" "$build"

for dt in $dts; do
  echo
  echo "dt = $dt s"
  labels=$(echo "$cases" | grep "_dt$dt\$" | grep -v '^reference')
  "$here/table.sh" "$work/reference_dt$dt" $(for l in $labels; do echo "$l=$work/$l"; done)
done
