#!/usr/bin/env bash
# Installs what ProbeCycle needs to build, test and run on Debian 12; with
# "package", only what building the Debian package needs
# (tools/make_package.sh).
# usage: .ci/install-deps.sh [package]
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# Both programs and the package: the libraries, CMake, Python for the man
# pages, and file for CPack's dependency scan.
packages=(
  build-essential cmake python3 file
  qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools libcli11-dev
  libgl1-mesa-dev libeigen3-dev nlohmann-json3-dev
)
if [ "${1:-}" != "package" ]; then packages+=(
  git libgtest-dev libbenchmark-dev
  xvfb xauth fonts-dejavu-core fonts-noto-cjk
  poppler-utils  # pdftotext and pdfinfo read the PDF report back in its tests
  clang clang-format clang-tidy libclang-rt-14-dev
  linuxcnc-uspace  # rs274, LinuxCNC's stand-alone interpreter, checks the generated programs (about 3 min to install)
  lintian desktop-file-utils appstream  # the Debian package's checks (.ci/package.sh)
  man-db  # the package check reads the man pages with man
  mingw-w64 wine wine64  # the core and the CLI cross-built for Windows, their tests run under Wine (.ci/windows.sh)
); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${missing[@]}"
fi
