#!/usr/bin/env bash
# README's first command ends in a bare `build/radview`. Without a display it must render the
# bundled solved Cornell box headless, print the PNG's path, and that PNG must show a global
# solution (check_solved_cornell).
#   first_run_test.sh RADVIEW CHECKER OUT_DIR
set -u
radview=$1 checker=$2 out_dir=$3
work="$out_dir/first-run"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
printed=$(env -u DISPLAY -u WAYLAND_DISPLAY "$radview" 2>"$work/stderr.txt") \
  || { echo "FAILED: radview exited non-zero"; cat "$work/stderr.txt"; exit 1; }
echo "radview printed: $printed"
[[ "$printed" == "$work/radview-cornell_box_solved.png" ]] \
  || { echo "FAILED: expected it to print $work/radview-cornell_box_solved.png"; exit 1; }
[[ -f "$printed" ]] || { echo "FAILED: $printed was not written"; exit 1; }
"$checker" "$printed"
