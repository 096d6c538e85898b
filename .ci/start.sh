#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds ProbeCycle and opens the window.
# Without a display it renders the window offscreen to probecycle.png and
# says how to get a real window.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  exec build/app/probecycle "$@"
fi
QT_QPA_PLATFORM=offscreen build/app/probecycle --screenshot probecycle.png "$@"
cat <<MSG
No display found, so the window was rendered offscreen to $(pwd)/probecycle.png.
For a real window on this machine, run it under a virtual X server:
    xvfb-run -a -s "-screen 0 1920x1080x24" build/app/probecycle
or from a desktop session: build/app/probecycle
The command line works anywhere: build/app/probecycle-cli --help
MSG
