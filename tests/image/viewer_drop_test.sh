#!/usr/bin/env bash
# Dropping a file on the real viewer window under Xvfb (XDND, as a file manager does: xdnd_drop):
# the viewer opens it, which Ctrl+S then shows by writing it under the dropped file's name.
#   viewer_drop_test.sh RADVIEW XDND_DROP FIRST_FILE DROPPED_FILE OUT_DIR
set -u
self=$(readlink -f "$0")
if [[ "${1:-}" == --drive ]]; then
  radview=$2 dropper=$3 first=$4 dropped=$5
  "$radview" "$first" --size 1000x700 >viewer.log 2>&1 &
  viewer=$!
  window=$(timeout 30 xdotool search --sync --onlyvisible --name radview | head -1) || exit 1
  xdotool windowfocus --sync "$window"
  sleep 1
  "$dropper" "$window" "$dropped" || { kill $viewer; exit 1; }
  written="$(basename "${dropped%.*}")-edited.glb"
  for _ in $(seq 50); do
    xdotool key --delay 100 ctrl+s
    sleep 0.2
    [[ -f "$written" ]] && break
  done
  xdotool key Escape
  wait $viewer
  [[ -f "$written" ]] || { echo "FAILED: the dropped file was not opened (Ctrl+S wrote no $written)"; cat viewer.log; exit 1; }
  echo "ok: the dropped $(basename "$dropped") was opened and written as $written"
  exit
fi
radview=$(readlink -f "$1") dropper=$(readlink -f "$2") first=$(readlink -f "$3") dropped=$(readlink -f "$4")
out_dir=$5
work="$out_dir/viewer-drop"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
xvfb-run -a -s "-screen 0 1400x900x24" "$self" --drive "$radview" "$dropper" "$first" "$dropped"
