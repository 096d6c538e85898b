#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each, seeded from the test data (or
# fuzz/seeds/<target>/ where the input has no test file) and the regression
# inputs in fuzz/corpus/<target>/ (inputs that once crashed; each is run
# first). Fails on any finding; the crashing input is left in the build
# directory as crash-* and its path printed.
# usage: tools/run_fuzzers.sh BUILD_DIR [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: tools/run_fuzzers.sh BUILD_DIR [SECONDS]}
seconds=${2:-20}
root=$(pwd)
declare -A seeds=(
  [scenario_json]="tests/data/*.json resources/presets/*.json resources/examples/*.json"
  [ring_csv]="tests/data/lab_ring*.csv"
  [delay_csv]="tests/data/lab_delay*.csv"
  [comparison_points]="tests/data/comparison/*.csv"
  [project_json]="tests/data/golden/project.probecycle"
  [probing_plan]="fuzz/seeds/probing_plan/*.json"
  [machine_log]="fuzz/seeds/machine_log/*"
  [linuxcnc_ini]="tests/data/linuxcnc/*.ini fuzz/seeds/linuxcnc_ini/*.ini"
)
status=0
for target in scenario_json ring_csv delay_csv comparison_points project_json probing_plan \
    machine_log linuxcnc_ini; do
  work=$(mktemp -d)
  # shellcheck disable=SC2086
  cp ${seeds[$target]} "$work"/
  echo "fuzz_$target: ${seconds} s"
  if ! (cd "$build" && "./fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 \
          -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
          -dict="$root/fuzz/$target.dict" "$work" "$root/fuzz/corpus/$target" \
          >"$work/log" 2>&1); then
    tail -60 "$work/log"
    echo "fuzz_$target found a problem; add the crash-* input to fuzz/corpus/$target/ once fixed"
    status=1
  else
    grep -E "stat::number_of_executed_units|Done" "$work/log" | tail -2
  fi
  rm -rf "$work"
done
exit "$status"
