#!/usr/bin/env bash
# Runs clang-tidy (.clang-tidy) over the sources of core/, ui/ and app/ with
# the compile commands of a build directory; any finding fails.
# usage: tools/run_clang_tidy.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: tools/run_clang_tidy.sh BUILD_DIR}
if [ ! -f "$build/compile_commands.json" ]; then
  echo "$build/compile_commands.json is missing: configure that build first" >&2
  exit 2
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# The Windows-only files are checked by the Windows build (.ci/windows.sh).
if git ls-files 'core/*.cpp' 'ui/*.cpp' 'app/*.cpp' ':!:*_windows.cpp' |
    xargs -P "$(nproc)" -n 4 clang-tidy -p "$build" --quiet >"$log" 2>&1; then
  echo "clang-tidy: no findings"
else
  grep -v "warnings generated" "$log" >&2
  echo "clang-tidy found problems (see above)" >&2
  exit 1
fi
