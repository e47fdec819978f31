#!/usr/bin/env bash
# The static solve against the problem size, and against a direct and a Krylov solve of the
# same FE mesh: the clamped cantilever of tests/static/direct_solve under an end shear
# (bending), Q1 on N x N/5 cells, pure FE for N = 40 ... 320, by the library's relaxation and
# conjugate gradients; then coupled (PD on [40, 60] mm, lattice 0.5 / 0.25 mm, strict
# coupling) for N = 40, 80: force blending by relaxation, energy blending by conjugate
# gradients, each deflection against the pure FE one. One run each, 1 rank, 1 thread:
# iteration counts do not depend on the machine, wall times do. About 5 minutes.
#
#   benchmarks/static_solve_cost.sh [build-dir]
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/benchmarks/common.sh"
build=$(cd "${1:-$top/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export DEAL_II_NUM_THREADS=1
echo "# $(date -u +%F), $(nproc) cores, $(git -C "$top" rev-parse --short HEAD)"
for n in 40 80 160 320; do
  "$build/periarlequin-static-solve-cost" "$n" | grep -E '^FE '
done
for case in "40 5e-4" "80 2.5e-4"; do
  # shellcheck disable=SC2086
  "$build/periarlequin-static-solve-cost" $case | grep -E '^coupled '
done
