#!/bin/bash
# The paper's section 6.1 study: runs the pure-PD reference and the bad, strict and weak
# couplings at dt = 1e-7 s and 1e-8 s from parameter_files/, plus, at dt = 1e-7 s, the weak
# coupling with the exact (CG) multiplier solve, with damping off and under the paper's and the
# force-based blending, then prints the results table (scripts/wave_table.sh).
#   scripts/wave_study.sh <build directory> <work directory> [jobs (default 2)] [dt list]
# e.g. scripts/wave_study.sh build runs 2 "1e-7"      (the dt = 1e-7 s half, ~5 minutes on 2 cores)
# Runs that finished before (their log ends with the timer table) are not repeated.
set -euo pipefail
build=$(realpath "${1:?usage: wave_study.sh <build dir> <work dir> [jobs] [dt list]}")
mkdir -p "${2:?work directory}"
work=$(realpath "$2")
jobs=${3:-2}
dts=${4:-"1e-7 1e-8"}
prm_dir=$(realpath "$(dirname "$0")/../parameter_files")

# make_case <label> <source prm> [sed expressions...]: writes <work>/<label>.prm with its own
# output directory <work>/<label>
make_case() {
  local label=$1 source=$2
  shift 2
  sed -e "s|set Directory .*|set Directory = $work/$label|" "$@" "$prm_dir/$source.prm" > "$work/$label.prm"
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
      make_case weak_cg_dt1e-7 arlequin_wave_2d_weak_dt1e-7 -e "s|Multiplier solver .*|Multiplier solver = cg|"
      make_case weak_no_damping_dt1e-7 arlequin_wave_2d_weak_dt1e-7 -e "s|Fine-scale damping .*|Fine-scale damping = false|"
      make_case strict_cg_dt1e-7 arlequin_wave_2d_strict_dt1e-7 -e "s|Multiplier solver .*|Multiplier solver = cg|"
      for blending in paper force; do
        make_case weak_${blending}_blending_dt1e-7 arlequin_wave_2d_weak_dt1e-7 -e "s|Blending .*|Blending = $blending|"
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
  "$(dirname "$0")/wave_table.sh" "$work/reference_dt$dt" $(for l in $labels; do echo "$l=$work/$l"; done)
done
