#!/usr/bin/env bash
# Runs the real viewer window under Xvfb for a few frames, takes its screenshot, and checks
# that it shows the scene and the panel (check_screenshot).
#   viewer_screenshot_test.sh RADVIEW CHECKER OUT_DIR FILE NAME [viewer arguments...]
# FILE "-" runs a bare `radview`, which opens the bundled default.
set -u
radview=$1 checker=$2 out_dir=$3 file=$4 name=$5
shift 5
mkdir -p "$out_dir"
out="$out_dir/$name.png"
rm -f "$out"
files=("$file")
[[ "$file" == - ]] && files=()
xvfb-run -a -s "-screen 0 1400x900x24" "$radview" "${files[@]}" --size "${RADVIEW_WINDOW_SIZE:-1400x800}" --screenshot "$out" "$@" \
  || { echo "the viewer failed under Xvfb"; exit 1; }
"$checker" "$out"
