#!/usr/bin/env bash
# Checks that every C++ file git tracks is formatted by .clang-format;
# with --fix, formats them in place.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
if ! clang-format --dry-run -Werror "${files[@]}"; then
  echo "Some files are not formatted: run tools/check_format.sh --fix" >&2
  exit 1
fi
echo "clang-format: ${#files[@]} files formatted"
