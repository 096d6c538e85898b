#!/usr/bin/env bash
# Runs a benchmark program briefly and fails when it fails or when any
# benchmark reports an error (Google Benchmark's SkipWithError leaves the
# exit code at 0, so a broken benchmark would otherwise pass unnoticed).
# Usage: tools/bench_smoke.sh <benchmark program> [its options...]
set -euo pipefail
program=$1
shift
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$program" --benchmark_min_time=0.01 --benchmark_format=json "$@" >"$out"
errors=$(python3 - "$out" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
bad = [f'{b["name"]}: {b.get("error_message", "")}' for b in runs if b.get("error_occurred")]
print("\n".join(bad))
print(f"{len(runs)} benchmarks ran", file=sys.stderr)
PY
)
if [[ -n "$errors" ]]; then
  echo "$program: benchmarks in error:" >&2
  echo "$errors" >&2
  exit 1
fi
