#!/usr/bin/env bash
# Where the PD stencil kernel's time goes: the ceilings of one core measured by
# benchmarks/roofline.cc (compiled with the options of source/pd/lps_stencil_kernel.cc) and
# the kernel's own rate on the 3D benchmark case (97,336 particles, m = 3.015, 40 steps,
# 1 rank x 1 thread, the median of REPEATS=3 runs), set against each other:
#  - memory: the bytes a stored bond moves from memory (its state byte in each pass plus its
#    share of the per-slot arrays, about 90 stored bonds a particle) at the triad bandwidth;
#  - the divide/square-root unit: 2 square roots and 2 divisions per stored bond.
#
#   benchmarks/roofline.sh [build-dir]
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
repeats=${REPEATS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

c++ -std=c++17 -O2 -fopenmp-simd -fno-math-errno -fno-trapping-math -ffp-contract=off \
  -o "$work/roofline" "$top/benchmarks/roofline.cc"
ceilings=$("$work/roofline")
echo "$ceilings"
bandwidth=$(echo "$ceilings" | awk '/triad/{print $3}')
quotients=$(echo "$ceilings" | awk '/sqrt/{print $(NF-1)}')

# The kernel: CONFIGS of pd_throughput.sh cut to the one case, stencil on 1 x 1.
rates=$(CONFIGS="3 46 40" REPEATS=$repeats bash "$top/benchmarks/pd_throughput.sh" "$build" 2>/dev/null |
  awk '/ours stencil, 1 rank x 1 thread/{print $(NF-1)}')
echo "kernel (time loop, 3D, 97,336 particles): $rates bond-updates/s"
# Per particle and step: 2 passes x 89 state bytes, and the per-slot arrays each pass reads
# and writes (displacements 24 B in both, coefficients 24 B, forces 2 x 24 B, deviatoric and
# moment sums 2 x 2 x 8 B, intact volume 8 B): about 336 B, 3.8 B a stored bond.
awk -v b="$bandwidth" -v q="$quotients" -v k="$rates" 'BEGIN {
  bytes = 336 / 89;
  printf "memory ceiling:       %.2e bond-updates/s (%.1f B a stored bond at %.1f GB/s); the kernel uses %.0f %% of the bandwidth\n",
    2 * b * 1e9 / bytes, bytes, b, 100 * (k / 2) * bytes / (b * 1e9);
  printf "divide/sqrt ceiling:  %.2e bond-updates/s; the kernel reaches %.0f %% of it\n", 2 * q, 100 * k / (2 * q);
}'
