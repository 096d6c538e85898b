#!/usr/bin/env bash
# Builds the Debian package on Debian 12 (README, "Install"): the packages
# the build needs, a Release build of both programs without the tests and
# benchmarks in build-package/, and CPack. Prints the package's path; with
# --install, installs it with apt-get (which resolves its dependencies).
set -euo pipefail
cd "$(dirname "$0")/.."
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
bash .ci/install-deps.sh package
cmake -S . -B build-package -DCMAKE_BUILD_TYPE=Release -DPROBECYCLE_BUILD_TESTS=OFF \
  -DPROBECYCLE_BUILD_BENCH=OFF >/dev/null
cmake --build build-package -j"$(nproc)"
rm -f build-package/probecycle_*.deb
(cd build-package && cpack -G DEB >/dev/null)
deb=$(ls "$PWD"/build-package/probecycle_*.deb)
echo "$deb"
if [ "${1:-}" = "--install" ]; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "$deb"
  echo "Installed: probecycle (the menu's Science section), probecycle-cli, man probecycle-cli."
  echo "Remove it with: ${SUDO:+sudo }apt-get remove probecycle"
fi
