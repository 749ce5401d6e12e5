#!/usr/bin/env bash
# Editing continuity in the real viewer window under Xvfb, with synthetic input (xdotool): on
# the T-vertex demo seen from above, centred on the fine quads' edge at (0.625, 0.5), K starts
# editing, a drag across three edges tags them C0, a click on the middle one makes it C-1
# (splitting a node), Ctrl+Z undoes that, and Ctrl+S writes the solution after each step,
# which `radview info` reads back.
#   viewer_edit_test.sh RADVIEW FILE OUT_DIR
set -u
self=$(readlink -f "$0")

# Runs inside the X server: the viewer in the background, driven by xdotool.
drive() {
  "$radview" "$file" --size 1400x800 --camera 0.625,0.5,1.5/0.625,0.5,0/0,1,0 >viewer.log 2>&1 &
  local viewer=$!
  local window
  window=$(xdotool search --sync --onlyvisible --name radview | head -1) || return 1
  xdotool windowfocus --sync "$window"
  sleep 1
  # The view is the 1000 x 800 pixels right of the 400-pixel panel; its centre, (900, 400), is on
  # the edge, and the square spans about 320 pixels either side of it.
  save() {
    rm -f "$written"
    xdotool key --delay 100 ctrl+s
    for _ in $(seq 50); do [[ -f "$written" ]] && break; sleep 0.2; done
    [[ -f "$written" ]] || { echo "FAILED: Ctrl+S wrote no $written"; return 1; }
    "$radview" info "$written" | grep -E '^(nodes|discontinuity edges):' | tr '\n' ' '
    echo
  }
  step() { sleep 0.3; }
  xdotool key k; step
  xdotool mousemove --window "$window" 900 200 mousedown 1; step
  for y in 250 300 350 400 450 500 550 600; do xdotool mousemove --window "$window" 900 $y; sleep 0.05; done
  xdotool mouseup 1; step
  echo "after the drag: $(save)" || return 1
  xdotool mousemove --window "$window" 900 400 mousedown 1; sleep 0.2; xdotool mouseup 1; step
  echo "after the click: $(save)" || return 1
  xdotool key --delay 100 ctrl+z; step
  echo "after undo: $(save)" || return 1
  xdotool key Escape
  wait "$viewer"
}
# The script runs itself inside xvfb-run for the driving part.
if [[ "${1:-}" == --drive ]]; then
  radview=$2 file=$3 written=$4
  drive
  exit
fi
radview=$1 file=$2 out_dir=$3
work="$out_dir/viewer-edit"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
written="$work/$(basename "${file%.*}")-edited.glb"
out=$(xvfb-run -a -s "-screen 0 1400x900x24" "$self" --drive "$radview" "$file" "$written") \
  || { echo "$out"; echo "FAILED: the viewer run failed"; exit 1; }
echo "$out"
expect() {
  grep -q -- "$1" <<<"$out" || { echo "FAILED: expected '$1'"; cat "$work/viewer.log"; exit 1; }
}
expect "after the drag: nodes: 18 discontinuity edges: C-1 0, C0 3"
expect "after the click: nodes: 19 discontinuity edges: C-1 1, C0 2"
expect "after undo: nodes: 18 discontinuity edges: C-1 0, C0 3"
echo "ok: edges retagged in the window, written and read back, and undone"
