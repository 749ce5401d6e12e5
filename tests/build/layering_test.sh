#!/usr/bin/env bash
# renderer/check_layering.cmake, the build step that keeps renderer/'s directories to their
# arrows: a tree that keeps them passes, and one include against them fails, naming the file
# and the include.
#   layering_test.sh CHECK_LAYERING_CMAKE WORK_DIR
set -u
check=$1 work=$2
rm -rf "$work" && mkdir -p "$work/core" "$work/scene"
printf '#pragma once\n' > "$work/core/types.h"
printf '#pragma once\n#include "core/types.h"\n' > "$work/scene/scene.h"
layers='core:|scene:core'
cmake "-DLAYERS=$layers" -DROOT="$work" -DSTAMP="$work/stamp" -P "$check" || { echo "FAIL: a tree within its arrows was refused"; exit 1; }
[ -f "$work/stamp" ] || { echo "FAIL: no stamp written"; exit 1; }
rm -f "$work/stamp"
printf '#pragma once\n#include "scene/scene.h"\n' > "$work/core/camera.h"
if out=$(cmake "-DLAYERS=$layers" -DROOT="$work" -DSTAMP="$work/stamp" -P "$check" 2>&1); then
  echo "FAIL: core/ including scene/ was let through"; exit 1
fi
grep -q 'core/camera.h: #include "scene/scene.h"' <<<"$out" || { echo "FAIL: the error does not name the include:"; echo "$out"; exit 1; }
[ ! -f "$work/stamp" ] || { echo "FAIL: a stamp was written for a refused tree"; exit 1; }
echo "layering check: passes a tree within its arrows, refuses core/ -> scene/"
