#!/usr/bin/env bash
# A radiosity solver's OBJ from the shared corpus (../shared/corpus/mesh-colours) on the command
# line: `info` counts its nodes and finds its light, `render` draws it with Clough-Tocher and with
# the final gather. Where the corpus is absent it exits 77, which ctest shows as Skipped, unless
# CI=true, where the corpus is always laid beside the clone (tests/shared_corpus.h).
# usage: import_corpus_cli_test.sh RADVIEW OUT_DIR CORPUS_DIR
set -euo pipefail
radview=$1 out=$2 corpus=$3
obj="$corpus/cornellbox_cornell_radiosity.obj"
if [ ! -f "$obj" ]; then
  echo "no shared corpus file at '$obj' (the third-party corpora are not in the repository: they lie in ../shared beside the checkout)"
  if [ "${CI:-}" = true ]; then echo "with CI=true it must be there"; exit 1; fi
  exit 77
fi
rm -rf "$out" && mkdir -p "$out"
"$radview" info "$obj" | grep -q '^nodes: 7119$'
"$radview" render "$obj" --method clough-tocher --size 320x240 --out "$out/cornell_radiosity_obj.png" > /dev/null
test -s "$out/cornell_radiosity_obj.png"
# Its light is the triangles at exactly 1 1 1.
"$radview" info "$obj" --rho 0.7 --emitters-above 0.999 | grep -q 'emitting [1-9]'
"$radview" render "$obj" --method final-gather --rho 0.7 --emitters-above 0.999 \
  --spp 1 --size 64x48 --out "$out/cornell_radiosity_obj_gather.png" > /dev/null
test -s "$out/cornell_radiosity_obj_gather.png"
echo "import_corpus_cli_test: ok"
