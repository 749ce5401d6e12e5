#!/usr/bin/env bash
# The final gather or the path tracer in the real viewer window under Xvfb (viewer_screenshot_test.sh, 1400x800):
# the last frame of --frames waits for --spp samples per pixel, and the gather's samples are
# keyed by (seed, pixel, pass), so the window must show the very image `radview render --method
# METHOD` makes at that size and spp; only the tone map may round differently (float on
# the GPU, double on the CPU): no pixel may be off by more than 2 8-bit steps. The window frames
# the scene right of its panel (x >= 400), in 1000x800 pixels.
#   viewer_gather_test.sh RADVIEW CHECKER OUT_DIR FILE METHOD [OPTIONS...]
# METHOD: final-gather or path-trace (the path tracer converges in the window the same way);
# OPTIONS go to both the window and the render.
set -u
radview=$1 checker=$2 out_dir=$3 file=$4 method=$5
shift 5
here=$(dirname "$0")
spp=4
"$here/viewer_screenshot_test.sh" "$radview" "$checker" "$out_dir" "$file" viewer-$method \
  --method $method --spp $spp --frames 3 "$@" || exit 1
window="$out_dir/viewer-$method.png"
headless="$out_dir/viewer-$method-headless.png"
"$radview" render "$file" --method $method --spp $spp --size 1000x800 --out "$headless" "$@" >/dev/null \
  || { echo "radview render failed"; exit 1; }
oiiotool "$window" --cut 400,0,1399,799 --origin +0+0 -o "$out_dir/viewer-$method-window-part.png" ||
  { echo "oiiotool failed"; exit 1; }
diff="$out_dir/viewer-$method-diff.png"
if ! idiff -fail 0.008 -failpercent 0 -abs -scale 50 -od -o "$diff" \
  "$out_dir/viewer-$method-window-part.png" "$headless"; then
  echo "FAILED: the window's $method differs from radview render's; difference image (x50): $diff"
  exit 1
fi
echo "ok: the window shows the $method image at $spp spp, as radview render does"
