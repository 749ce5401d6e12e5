#!/usr/bin/env bash
# Numerical extremes through a file and the real command line: the closed box of
# tests/extreme_scenes.h written as a solution file (float32 positions and radiosities), rendered
# from inside by `radview render` with every method, per pixel and tessellated, and each EXR of
# linear radiosity checked: every pixel finite and covered (a crack would show the background).
#   extremes_cli_test.sh RADVIEW TOOL OUT_DIR PLACEMENT VIEW [every|per-pixel]
# `per-pixel` leaves out the tessellated settings (the sanitizer build, where they are slow).
set -eu
radview=$1 tool=$2 out=$3 placement=$4 view=$5 methods=${6:-every}
mkdir -p "$out"
file="$out/extreme_box_$placement.glb"
"$tool" write "$placement" "$file"
camera=$("$tool" camera "$placement" "$view")
status=0
for method in "flat" "gouraud" "gouraud --screen-space" "scanline-gouraud" "bilinear" \
              "quadratic" "quadratic --tessellation 4" "c1-quadratic" "c1-quadratic --tessellation adaptive" \
              "clough-tocher" "clough-tocher --tessellation 4" "clough-tocher --tessellation adaptive"; do
  if [ "$methods" = per-pixel ] && [[ "$method" == *--tessellation* ]]; then continue; fi
  name=$(tr ' ' '_' <<<"$method")
  exr="$out/extreme_box_${placement}_${view}_${name}.exr"
  # shellcheck disable=SC2086 # the method's options split on purpose
  "$radview" render "$file" --camera "$camera" --size 160x120 --method $method \
    --out "$out/extreme_box_${placement}_${view}_${name}.png" --linear-out "$exr" >/dev/null
  "$tool" check "$exr" || status=1
done
exit $status
