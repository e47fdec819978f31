#!/usr/bin/env bash
# Format every C++ file of the project with its .clang-format (Debian bookworm's clang-format
# 14), or, with --check, list the files that differ from it and fail.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$top"
# Other versions lay some constructs out differently: use the one the style was made for.
version=$(clang-format --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p')
if [ "$version" != 14 ]; then
  echo "scripts/format.sh needs clang-format 14 (Debian bookworm's); found: $(clang-format --version)"
  exit 1
fi
mapfile -t files < <(git ls-files -- '*.cc' '*.h' 2>/dev/null || find applications benchmarks examples include source tests -name '*.cc' -o -name '*.h')
if [ "${1:-}" = "--check" ]; then
  unformatted=()
  for f in "${files[@]}"; do
    clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || unformatted+=("$f")
  done
  if [ ${#unformatted[@]} -gt 0 ]; then
    echo "Not formatted as .clang-format says (run scripts/format.sh):"
    printf '  %s\n' "${unformatted[@]}"
    exit 1
  fi
  echo "${#files[@]} files formatted as .clang-format says."
else
  clang-format -i "${files[@]}"
fi
