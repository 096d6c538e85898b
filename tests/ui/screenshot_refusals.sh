#!/usr/bin/env bash
# The window's --screenshot goes through the checked writer (docs/files.md,
# "Limits on input and output"): a FIFO, a link to a FIFO and a folder are
# refused (exit 2, the path named) and left as they were; --size names its
# range. (A link to a FIFO stands for a link to a device: a writer that
# regressed must not replace a real device.)
set -u
probecycle=${1:?usage: screenshot_refusals.sh PROBECYCLE}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export QT_QPA_PLATFORM=offscreen
failed=0
expect_refusal() {  # TARGET WHAT
  local err rc
  err=$("$probecycle" --screenshot "$1" 2>&1 >/dev/null)
  rc=$?
  if [[ $rc -ne 2 || $err != *"cannot write $1: $2"* ]]; then
    echo "FAIL: --screenshot $1: exit $rc, said: $err"
    failed=1
  fi
}
mkfifo "$dir/fifo.png"
expect_refusal "$dir/fifo.png" "it is not a regular file"
[[ -p $dir/fifo.png ]] || { echo "FAIL: the FIFO was replaced"; failed=1; }
ln -s fifo.png "$dir/link.png"
expect_refusal "$dir/link.png" "it is not a regular file"
[[ -L $dir/link.png && -p $dir/fifo.png ]] || { echo "FAIL: the link or its FIFO was replaced"; failed=1; }
mkdir "$dir/folder.png"
expect_refusal "$dir/folder.png" "it is a directory"
err=$("$probecycle" --screenshot "$dir/x.png" --size 8001x100 2>&1 >/dev/null)
if [[ $? -ne 2 || $err != *"--size: got '8001x100'; allowed: WxH, a width from 400 to 8000"* ]]; then
  echo "FAIL: --size 8001x100 said: $err"
  failed=1
fi
[[ ! -e $dir/x.png ]] || { echo "FAIL: a refused --size wrote the PNG"; failed=1; }
exit $failed
