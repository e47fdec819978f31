#!/usr/bin/env bash
# Install what is missing (Debian packages only), then configure and build PeriArlequin
# (Release) in ./build. Sourced by run_example.sh and run_tests.sh.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${PERIARLEQUIN_BUILD_DIR:-$top/build}"

packages="libdeal.ii-dev numdiff cmake make g++ openmpi-bin ccache perl gnuplot-nox doxygen clang-format"
missing=""
for p in $packages; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "Installing:$missing"
  apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
fi

cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$(nproc)"
