#!/usr/bin/env bash
# The final gather in the real viewer window under Xvfb (viewer_screenshot_test.sh, 1400x800):
# the last frame of --frames waits for --spp samples per pixel, and the gather's samples are
# keyed by (seed, pixel, pass), so the window must show the very image `radview render --method
# final-gather` makes at that size and spp; only the tone map may round differently (float on
# the GPU, double on the CPU): no pixel may be off by more than 2 8-bit steps. The window frames
# the scene right of its panel (x >= 400), in 1000x800 pixels.
#   viewer_gather_test.sh RADVIEW CHECKER OUT_DIR FILE
set -u
radview=$1 checker=$2 out_dir=$3 file=$4
here=$(dirname "$0")
spp=4
"$here/viewer_screenshot_test.sh" "$radview" "$checker" "$out_dir" "$file" viewer-final-gather \
  --method final-gather --spp $spp --frames 3 || exit 1
window="$out_dir/viewer-final-gather.png"
headless="$out_dir/viewer-final-gather-headless.png"
"$radview" render "$file" --method final-gather --spp $spp --size 1000x800 --out "$headless" >/dev/null \
  || { echo "radview render failed"; exit 1; }
oiiotool "$window" --cut 400,0,1399,799 --origin +0+0 -o "$out_dir/viewer-final-gather-window-part.png" ||
  { echo "oiiotool failed"; exit 1; }
diff="$out_dir/viewer-final-gather-diff.png"
if ! idiff -fail 0.008 -failpercent 0 -abs -scale 50 -od -o "$diff" \
  "$out_dir/viewer-final-gather-window-part.png" "$headless"; then
  echo "FAILED: the window's gather differs from radview render's; difference image (x50): $diff"
  exit 1
fi
echo "ok: the window shows the final gather at $spp spp, as radview render does"
