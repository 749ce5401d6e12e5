#!/usr/bin/env bash
# Continuity-edit latency in the real viewer window, under Xvfb, driven by xdotool: the time from
# the moment a click (or Ctrl+Z) is sent to the end of the first frame that shows its effect with
# the method asked for (the viewer's --frame-log: a frame drawn with the edited mesh, not Gouraud
# standing in while a C1 method's pieces are set up).
#
#   tests/bench/edit_latency.sh RADVIEW PYTHON_MODULE_DIR OUT_DIR [ELEMENT_SIZE [ROUNDS [METHOD]]]
#
# The Cornell box is meshed at ELEMENT_SIZE (0.0016: 1,120,010 elements; 0.005: about 1.1e5) and
# written as a solution; the window (1280 x 800, panel hidden) looks straight down at an edge of
# the floor, about 40 pixels long, and clicks its middle. Each round: a click
# (C1 -> C0, a retag), a click (C0 -> C-1, which splits the edge's nodes), Ctrl+Z (joins them
# again), Ctrl+Z (back to C1). Prints each action's median latency with its range, and the median
# frame time while idle. Exits non-zero when an action is not shown within 120 s.
set -u
self=$(readlink -f "$0")

# Runs inside the X server.
drive() {
  "$radview" "$mesh" --method "$method" --camera "$camera" --frame-log "$log" >viewer.log 2>&1 &
  local viewer=$!
  local window
  window=$(timeout 60 xdotool search --sync --onlyvisible --name radview | head -1) || return 1
  xdotool windowfocus --sync "$window"
  xdotool key Tab  # the panel hidden: the view is the whole window, its centre the edge's middle
  # The last frame's fields: frame end_s cpu_ms wanted drawn mesh_version.
  last() { tail -n 1 "$log"; }
  # Waits for a frame drawn with the method asked for and a mesh version above $1; prints its end.
  shown_after() {
    local deadline=$((SECONDS + 120)) line
    while ((SECONDS < deadline)); do
      line=$(awk -v v="$1" '$1 !~ /^#/ && $4 == $5 && $6 > v { print $2; exit }' "$log")
      [[ -n "$line" ]] && { echo "$line"; return 0; }
      sleep 0.01
    done
    return 1
  }
  shown_after -1 >/dev/null || { echo "FAILED: the window never drew $method"; return 1; }
  xdotool key k
  sleep 1
  # One action: sent at t0, shown at the end of the first frame with a newer mesh.
  act() {
    local name=$1 version t0 t1
    shift
    version=$(last | awk '{ print $6 }')
    t0=$(date +%s.%N)
    "$@"
    t1=$(shown_after "$version") || { echo "FAILED: $name not shown within 120 s"; return 1; }
    echo "$name $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", 1000 * (b - a) }')"
    sleep 0.5
  }
  click() { xdotool mousemove --window "$window" 640 400 click 1; }
  undo() { xdotool key ctrl+z; }
  for _ in $(seq "$rounds"); do
    act retag click || return 1
    act split click || return 1
    act join undo || return 1
    act untag undo || return 1
  done
  xdotool key Escape
  wait "$viewer"
}
if [[ "${1:-}" == --drive ]]; then
  radview=$2 mesh=$3 method=$4 camera=$5 log=$6 rounds=$7
  drive
  exit
fi

# A sanitizer build's test preloads its runtime for the interpreter that imports the module; the
# instrumented executable and the X tools run without it.
python_preload=${LD_PRELOAD:-}
unset LD_PRELOAD
radview=$(readlink -f "$1") module_dir=$(readlink -f "$2") out_dir=$3
element_size=${4:-0.0016} rounds=${5:-3} method=${6:-clough-tocher}
source_dir=$(dirname "$self")/../..
work="$out_dir/edit-latency"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
mesh="$work/mesh.glb"
"$radview" export "$source_dir/assets/cornell_box.gltf" "$mesh" --direct-only --element-size "$element_size" \
  >export.log 2>&1 || { cat export.log; echo "FAILED: radview export"; exit 1; }
# The floor's element nearest (0.8, 0.18) of its width and depth, right of the short block and in
# front of the tall one, and its first edge: the camera looks straight down at that edge's middle
# from the height at which the edge is about 40 of the window's 800 rows.
camera=$(LD_PRELOAD="$python_preload" PYTHONPATH="$module_dir" /usr/bin/python3 - "$mesh" <<'EOF'
import math, sys
import numpy as np
import radview
s = radview.load(sys.argv[1])
p, corners, offsets = s.positions, s.element_corners, s.element_offsets
first = corners[offsets[:-1]]
second = corners[offsets[:-1] + 1]
centroid = np.add.reduceat(p[corners], offsets[:-1], axis=0) / np.diff(offsets)[:, None]
floor = np.abs(np.add.reduceat(np.abs(p[corners, 1]), offsets[:-1])) == 0.0
lo, hi = p.min(axis=0), p.max(axis=0)
target = lo + np.array([0.8, 0.0, 0.18]) * (hi - lo)
d = np.where(floor, np.hypot(centroid[:, 0] - target[0], centroid[:, 2] - target[2]), np.inf)
e = int(np.argmin(d))
a, b = p[first[e]], p[second[e]]
m = (a + b) / 2
size = np.linalg.norm(b - a)
height = (800 / 40 * size / 2) / math.tan(math.radians(45) / 2)
print(f"{m[0]:.9g},{m[1] + height:.9g},{m[2]:.9g}/{m[0]:.9g},{m[1]:.9g},{m[2]:.9g}/0,0,-1")
print(f"{len(offsets) - 1} elements; edge {e}:0, {size:.4g} long", file=sys.stderr)
EOF
) || { echo "FAILED: finding the floor's middle edge"; exit 1; }
echo "$camera" >camera.txt
log="$work/frames.log"
out=$(xvfb-run -a -s "-screen 0 1280x800x24" "$self" --drive "$radview" "$mesh" "$method" "$camera" "$log" "$rounds") \
  || { echo "$out"; cat viewer.log; echo "FAILED: the viewer run failed"; exit 1; }
echo "$out" >latencies.txt
median() { sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.0f [%.0f, %.0f]", m, v[1], v[NR] }'; }
echo "$("$radview" info "$mesh" | grep '^elements:' | cut -d' ' -f2) elements, $method, 1280 x 800, $rounds rounds:"
echo "action   latency ms, median [min, max]"
for action in retag split join untag; do
  printf '%-8s %s\n' "$action" "$(awk -v a="$action" '$1 == a { print $2 }' latencies.txt | median)"
done
# Idle frames: those drawn with the method before the first edit.
echo "idle frame CPU ms, median [min, max]: $(awk '$1 !~ /^#/ && $4 == $5 && $6 == 0 { print $3 }' "$log" | median)"
