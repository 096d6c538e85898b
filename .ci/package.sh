#!/usr/bin/env bash
# The Debian package, tested as a user installs it (docs/building.md,
# "Installing"): built with CPack from a finished build folder, checked by
# lintian, desktop-file-validate and appstreamcli, installed with apt-get
# (its dependencies resolved), run from the installed files (the CLI on an
# installed example, the window offscreen in Russian), its desktop entry and
# file type checked, then removed, leaving nothing behind.
#   .ci/package.sh BUILD_FOLDER
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(realpath "${1:?usage: .ci/package.sh BUILD_FOLDER}")
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
fail() { echo ".ci/package.sh: $*" >&2; exit 1; }

rm -f "$build"/probecycle_*.deb
(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls "$build"/probecycle_*.deb)
version=$(dpkg-deb -f "$deb" Version)
echo "package: $deb"

# No lintian error or warning (the info tags that remain: docs/building.md).
lintian --fail-on error,warning "$deb"
desktop-file-validate resources/desktop/org.probecycle.ProbeCycle.desktop
appstreamcli validate --no-net resources/desktop/org.probecycle.ProbeCycle.metainfo.xml

if dpkg-query -W -f='${Status}' probecycle 2>/dev/null | grep -q "install ok installed"; then
  fail "probecycle is already installed here; remove it first (apt-get remove probecycle)"
fi
work=$(mktemp -d)
# However the checks end, the machine is left as it was.
cleanup() {
  cd /
  rm -rf "$work"
  if dpkg-query -W -f='${Status}' probecycle 2>/dev/null | grep -q "install ok installed"; then
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get remove --purge -y probecycle >/dev/null
  fi
}
trap cleanup EXIT
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "$deb" >/dev/null
installed=$(dpkg-query -L probecycle)

# Run from the installed files only, away from the source and build trees.
cd "$work"
[ "$(command -v probecycle-cli)" = /usr/bin/probecycle-cli ] || fail "probecycle-cli is not /usr/bin's"
[ "$(probecycle-cli --version)" = "ProbeCycle $version" ] || fail "probecycle-cli --version is not $version"
[ "$(QT_QPA_PLATFORM=offscreen probecycle --version)" = "ProbeCycle $version" ] ||
  fail "probecycle --version is not $version"
probecycle-cli evaluate /usr/share/probecycle/examples/bore_two_touch.json >evaluate.json
python3 -c 'import json, sys; r = json.load(open("evaluate.json")); sys.exit(0 if r["valid"] and r["cycle_time_s"] > 0 else 1)' ||
  fail "the installed CLI's evaluation of the installed example is not a valid cycle"
# The window offscreen in Russian: the translations are inside the program,
# so its report in Russian proves that they load from the installed file.
QT_QPA_PLATFORM=offscreen probecycle --screenshot window_ru.png --language ru \
  --scenario /usr/share/probecycle/examples/bore_two_touch.json
[ -s window_ru.png ] || fail "no screenshot from the installed window"
QT_QPA_PLATFORM=offscreen probecycle --report-pdf report_ru.pdf --language ru
pdftotext report_ru.pdf report_ru.txt
grep -q "Время цикла" report_ru.txt || fail "the installed window's report is not in Russian"

# The desktop entry starts an installed program and opens the project files
# the installed MIME type names.
desktop=/usr/share/applications/org.probecycle.ProbeCycle.desktop
exec_program=$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")
[ "$(command -v "$exec_program")" = /usr/bin/probecycle ] || fail "Exec=$exec_program is not the installed window"
grep -qx "$(command -v "$exec_program")" <<<"$installed" || fail "Exec names a file the package did not install"
mime_type=$(sed -n 's/^MimeType=\([^;]*\);.*/\1/p' "$desktop")
grep -q "type=\"$mime_type\"" /usr/share/mime/packages/org.probecycle.ProbeCycle.xml ||
  fail "the desktop entry's $mime_type is not the installed MIME type"
if command -v update-mime-database >/dev/null; then
  [ -f "/usr/share/mime/${mime_type}.xml" ] || fail "shared-mime-info did not register $mime_type"
fi
icon=$(sed -n 's/^Icon=//p' "$desktop")
[ -f "/usr/share/icons/hicolor/scalable/apps/$icon.svg" ] || fail "no installed icon $icon"
man -w probecycle-cli >/dev/null && man -w probecycle >/dev/null || fail "man cannot find the pages"
zcat "$(man -w probecycle-cli)" >probecycle-cli.1
grep -q "program delay" probecycle-cli.1 || fail "the CLI's man page lacks its subcommands"
bash -c 'source /usr/share/bash-completion/completions/probecycle-cli &&
  COMP_WORDS=(probecycle-cli import --dialect s) COMP_CWORD=3 && _probecycle_cli &&
  [ "${COMPREPLY[*]}" = siemens ]' || fail "the installed completion does not complete --dialect"

cd /
DEBIAN_FRONTEND=noninteractive $SUDO apt-get remove --purge -y probecycle >/dev/null
left=()
while IFS= read -r path; do
  # Folders other packages share (/usr/share/icons/hicolor/...) may stay.
  if [ -e "$path" ] && [ ! -d "$path" ]; then left+=("$path"); fi
done <<<"$installed"
[ "${#left[@]}" -eq 0 ] || fail "left behind after removal: ${left[*]}"
[ ! -d /usr/share/probecycle ] && [ ! -d /usr/share/doc/probecycle ] || fail "its own folders are left behind"
echo "package: installed, ran and removed cleanly ($version)"
