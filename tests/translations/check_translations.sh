#!/usr/bin/env bash
# Fails when a user-visible text of the window or the core has no finished
# Chinese or Russian translation, or when the .ts files are not what lupdate
# makes of the sources. Runs lupdate exactly as the update_translations
# target does, but into copies of the .ts files (the real ones are untouched),
# and lists every text that is new or unfinished.
# usage: check_translations.sh LUPDATE GENERATE_PROJECT_SCRIPT PROJECT_CMAKE TS_FILE...
set -euo pipefail
lupdate=$1
generator=$2
project_cmake=$3
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -DIN_FILE="$project_cmake" -DOUT_FILE="$work/project.json" -P "$generator"
status=0
for ts in "$@"; do
  copy="$work/$(basename "$ts")"
  cp "$ts" "$copy"
  "$lupdate" -silent -project "$work/project.json" -no-obsolete -locations none -ts "$copy"
  # The source of each unfinished message (a translator's comment may stand
  # between the two lines).
  missing=$(awk '/<source>/ { source = $0 } /type="unfinished"/ { print source }' "$copy" |
    sed -n 's/^ *<source>\(.*\)<\/source>$/\1/p' || true)
  if [ -n "$missing" ]; then
    echo "$(basename "$ts"): $(printf '%s\n' "$missing" | wc -l) text(s) without a finished translation:"
    printf '  %s\n' "$missing"
    status=1
  elif ! cmp -s "$ts" "$copy"; then
    echo "$(basename "$ts") differs from what lupdate makes of the sources:"
    diff -u "$ts" "$copy" | head -40 || true
    status=1
  fi
done
if [ "$status" -ne 0 ]; then
  echo "Refresh with: cmake --build <build dir> --target update_translations, then translate"
  echo "every entry marked type=\"unfinished\" in resources/translations/*.ts."
else
  echo "translations complete: every text has a finished zh_CN and ru translation"
fi
exit "$status"
