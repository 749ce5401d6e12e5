#!/usr/bin/env bash
# One image test: render with the real command line, compare with the golden PNG using
# OpenImageIO's idiff.
#   image_test.sh NAME RADVIEW GOLDEN_DIR OUT_DIR [radview render arguments...]
# Thresholds (per channel, 0..1): a pixel fails past 0.02 (5/255); the test fails when more
# than 0.5% of pixels fail or any pixel is off by more than 0.35 (edges that move by a pixel
# between rasterisers). On failure the difference image (x10) is written and its path printed.
# RADVIEW_UPDATE_GOLDENS=1 writes the new image over the golden instead of comparing.
set -u
name=$1 radview=$2 golden_dir=$3 out_dir=$4
shift 4
mkdir -p "$out_dir"
out="$out_dir/$name.png"
golden="$golden_dir/$name.png"
"$radview" render "$@" --out "$out" >/dev/null || { echo "radview render failed"; exit 1; }
if [ "${RADVIEW_UPDATE_GOLDENS:-0}" = 1 ]; then
  cp "$out" "$golden" && echo "updated $golden" && exit 0
fi
if [ ! -f "$golden" ]; then
  echo "no golden image $golden; the render is at $out (RADVIEW_UPDATE_GOLDENS=1 to accept it)"
  exit 1
fi
diff="$out_dir/$name-diff.png"
idiff -q -fail 0.02 -warn 0.02 -failpercent 0.5 -warnpercent 0.5 -hardfail 0.35 -hardwarn 0.35 \
  -abs -scale 10 -od -o "$diff" "$out" "$golden"
status=$?
if [ $status -ge 2 ]; then
  idiff -fail 0.02 -failpercent 0.5 -hardfail 0.35 "$out" "$golden" | sed 's/^/  /'
  echo "FAILED: $out differs from $golden; difference image (x10): $diff"
  exit 1
fi
echo "ok: $out matches $golden"
