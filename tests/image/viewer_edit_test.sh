#!/usr/bin/env bash
# Editing continuity in the real viewer window under Xvfb, with synthetic input (xdotool), on
# the T-vertex demo seen from above, centred on the fine quads' edge (0.5, 0.5)-(0.75, 0.5):
# K starts editing; a click tags that edge C0; a drag across it and the edges above and below
# tags those C0 and it C-1; Ctrl+Z undoes the drag; four clicks tag the line x = 0.75 C0 from
# the bottom edge to the top. Ctrl+S writes the solution after each step, and `radview info`
# reads it back. Clough-Tocher (`radview sample`): a lone C0 edge inside the surface changes
# nothing (both sides keep the corner gradients, whose sectors it does not cut); the C0 line
# across the square changes it in a quad at the line and not in one away from it.
set -u
self=$(readlink -f "$0")

# Runs inside the X server: the viewer in the background, driven by xdotool.
drive() {
  "$radview" "$file" --size 1400x800 --camera 0.625,0.5,1.5/0.625,0.5,0/0,1,0 >viewer.log 2>&1 &
  local viewer=$!
  local window
  window=$(timeout 30 xdotool search --sync --onlyvisible --name radview | head -1) || return 1
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
  xdotool mousemove --window "$window" 900 400 mousedown 1; sleep 0.2; xdotool mouseup 1; step
  echo "after the click: $(save)" || return 1
  xdotool mousemove --window "$window" 900 200 mousedown 1; step
  for y in 250 300 350 400 450 500 550 600; do xdotool mousemove --window "$window" 900 $y; sleep 0.05; done
  xdotool mouseup 1; step
  echo "after the drag: $(save)" || return 1
  xdotool key --delay 100 ctrl+z; step
  echo "after undo: $(save)" || return 1
  cp "$written" clicked.glb
  # The square spans about 643 pixels from (498, 721) to (1141, 79): x = 0.75 is at 980, and
  # the line's four edges have their middles at y = 0.125, 0.375, 0.625, 0.875.
  for y in 641 480 320 159; do
    xdotool mousemove --window "$window" 980 $y mousedown 1; sleep 0.2; xdotool mouseup 1; step
  done
  echo "after the line: $(save)" || return 1
  cp "$written" line.glb
  xdotool key Escape
  wait "$viewer"
}
# The script runs itself inside xvfb-run for the driving part.
if [[ "${1:-}" == --drive ]]; then
  radview=$2 file=$3 written=$4
  drive
  exit
fi
radview=$(readlink -f "$1") file=$(readlink -f "$2") out_dir=$3
work="$out_dir/viewer-edit"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
written="$work/$(basename "${file%.*}")-edited.glb"
out=$(xvfb-run -a -s "-screen 0 1400x900x24" "$self" --drive "$radview" "$file" "$written") \
  || { echo "$out"; echo "FAILED: the viewer run failed"; exit 1; }
echo "$out"
expect() {
  grep -q -- "$1" <<<"$out" || { echo "FAILED: expected '$1'"; cat "$work/viewer.log"; exit 1; }
}
expect "after the click: nodes: 18 discontinuity edges: C-1 0, C0 1"
expect "after the drag: nodes: 18 discontinuity edges: C-1 1, C0 2"
expect "after undo: nodes: 18 discontinuity edges: C-1 0, C0 1"
expect "after the line: nodes: 18 discontinuity edges: C-1 0, C0 5"
# Clough-Tocher at (0.7, 0.6), in a quad with corners on the line, and at (0.25, 0.25), in a
# coarse quad away from it.
values() { "$radview" sample "$1" --method clough-tocher --points "0.7 0.6 0; 0.25 0.25 0" | grep -v '^#'; }
original=$(values "$file") clicked=$(values "$work/clicked.glb") line=$(values "$work/line.glb") \
  || { echo "FAILED: radview sample"; exit 1; }
[[ "$clicked" == "$original" ]] || { echo "FAILED: a lone C0 edge changed Clough-Tocher:"; echo "$original"; echo "$clicked"; exit 1; }
[[ "$(sed -n 1p <<<"$line")" != "$(sed -n 1p <<<"$original")" ]] \
  || { echo "FAILED: Clough-Tocher did not change at the C0 line: $line"; exit 1; }
[[ "$(sed -n 2p <<<"$line")" == "$(sed -n 2p <<<"$original")" ]] \
  || { echo "FAILED: Clough-Tocher changed away from the C0 line:"; echo "$original"; echo "$line"; exit 1; }
echo "ok: edges retagged in the window, written and read back, undone; Clough-Tocher changed only at the C0 line"
