#!/usr/bin/env bash
# Set up, build the library and its API documentation, and run the whole test suite (serial
# and 2-rank MPI tests).
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$top/scripts/setup.sh"
cd "$build"
# The API documentation (Doxygen; its warnings are errors).
cmake --build . --target doc
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest -j"$(nproc)" --output-on-failure --timeout 1200
