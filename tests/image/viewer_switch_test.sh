#!/usr/bin/env bash
# Switching to thin-plate and back, live, in the real viewer window under Xvfb (xdotool): keys
# 8, 7 and 8 again, a screenshot (S) after each once the method's pieces are set up. The view,
# the window's 1000x800 pixels right of its 400-pixel panel, must then be the very image
# `radview render --method M` makes at that size (only the tone map may round differently: 2
# 8-bit steps at most), and the two thin-plate shots the same.
#   viewer_switch_test.sh RADVIEW FILE OUT_DIR
set -u
self=$(readlink -f "$0")

# Runs inside the X server: the viewer in the background, driven by xdotool.
drive() {
  "$radview" "$file" --size 1400x800 >viewer.log 2>&1 &
  local viewer=$!
  local window
  window=$(timeout 30 xdotool search --sync --onlyvisible --name radview | head -1) || return 1
  xdotool windowfocus --sync "$window"
  sleep 2
  local n=1
  for key in 8 7 8; do
    xdotool key "$key"
    sleep "$settle"  # the C1 pieces are set up beside the frame loop (Gouraud meanwhile)
    xdotool key s
    for _ in $(seq 100); do [[ -f radview-screenshot-$n.png ]] && break; sleep 0.2; done
    [[ -f radview-screenshot-$n.png ]] || { echo "FAILED: no screenshot after key $key"; return 1; }
    n=$((n + 1))
  done
  xdotool key Escape
  wait "$viewer"
}
if [[ "${1:-}" == --drive ]]; then
  radview=$2 file=$3 settle=$4
  drive
  exit
fi
radview=$(readlink -f "$1") file=$(readlink -f "$2") out_dir=$3
work="$out_dir/viewer-switch"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
settle=${RADVIEW_SWITCH_SETTLE:-6}
out=$(xvfb-run -a -s "-screen 0 1400x900x24" "$self" --drive "$radview" "$file" "$settle") \
  || { echo "$out"; cat viewer.log; echo "FAILED: the viewer run failed"; exit 1; }
compare() {  # screenshot number, method
  oiiotool "radview-screenshot-$1.png" --cut 400,0,1399,799 --origin +0+0 -o "window-$1.png" || return 1
  "$radview" render "$file" --method "$2" --size 1000x800 --out "headless-$2.png" >/dev/null || return 1
  idiff -fail 0.008 -failpercent 0 -abs -scale 50 -od -o "diff-$1.png" "window-$1.png" "headless-$2.png" >/dev/null ||
    { echo "FAILED: after key $3 the window is not radview render's $2 (difference x50: $work/diff-$1.png)"; return 1; }
}
compare 1 thin-plate 8 && compare 2 clough-tocher 7 && compare 3 thin-plate 8 || exit 1
idiff -fail 0.008 -failpercent 0 window-1.png window-3.png >/dev/null ||
  { echo "FAILED: thin-plate differs after switching back"; exit 1; }
echo "ok: the window switched to thin-plate, to clough-tocher and back, each as radview render draws it"
