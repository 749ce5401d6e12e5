#!/usr/bin/env bash
# Other tools' files on the command line: one mesh as float PLY, 8-bit PLY, OBJ and glTF COLOR_0
# (tests/import/write_same_mesh.cpp); `radview sample` gives each node's value at the node
# (floats exactly, 8 bits as quantised), `info` keeps the quads, `render --method
# clough-tocher` works headless, and `export` writes a PLY that samples the same.
# usage: import_cli_test.sh RADVIEW WRITE_SAME_MESH OUT_DIR
set -euo pipefail
radview=$1 writer=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$writer" "$out"

for file in two_quads_float.ply two_quads_uchar.ply two_quads.obj two_quads_colour0.gltf; do
  points=$(awk -v f="$file" '$1 == f { printf "%s %s %s;", $2, $3, $4 }' "$out/expected.txt")
  "$radview" sample "$out/$file" --method clough-tocher --points "$points" > "$out/$file.samples"
  # Columns of a sample line: element x y z distance B_r B_g B_b ...
  paste -d' ' <(awk -v f="$file" '$1 == f { print $5, $6, $7 }' "$out/expected.txt") \
              <(grep -v '^#' "$out/$file.samples" | awk '{ print $6, $7, $8 }') |
    awk -v f="$file" '{ for (k = 1; k <= 3; ++k) { d = $k - $(k + 3); if (d < 0) d = -d;
                          if (d > 1e-12) { print f ": node " NR " channel " k ": expected " $k ", sampled " $(k + 3); bad = 1 } } }
                      END { exit bad }'
  "$radview" render "$out/$file" --method clough-tocher --size 160x120 --out "$out/$file.png" > /dev/null
  test -s "$out/$file.png"
done

for file in two_quads_float.ply two_quads_uchar.ply two_quads.obj; do
  "$radview" info "$out/$file" | grep -q '^elements: 2 (quads 2)' || { echo "$file: quads not kept"; exit 1; }
done
"$radview" info "$out/two_quads_uchar.ply" | grep -q '^B from: vertex properties red green blue (uchar), scaled to \[0, 1\] and sRGB-decoded to linear$'
"$radview" info "$out/two_quads_colour0.gltf" | grep -q '^B from: COLOR_0 (float), linear as glTF defines it$'

# Exported and read back: the same samples.
"$radview" export "$out/two_quads_float.ply" "$out/exported.ply" > /dev/null
"$radview" sample "$out/exported.ply" --method clough-tocher --points "0.5 0.5 0; 1.5 0.25 0" | grep -v '^#' > "$out/exported.samples"
"$radview" sample "$out/two_quads_float.ply" --method clough-tocher --points "0.5 0.5 0; 1.5 0.25 0" | grep -v '^#' > "$out/original.samples"
cmp "$out/exported.samples" "$out/original.samples"

# The final gather needs what a PLY does not carry, and says so.
if "$radview" render "$out/two_quads_float.ply" --method final-gather --size 8x8 --out "$out/never.png" 2> "$out/gather.err"; then
  echo "final gather ran on a PLY without reflectance"; exit 1
fi
grep -q 'two_quads_float.ply: the final gather cannot run: this file gives no reflectance and no emitter, which the final gather and the path tracer need (give --rho R,G,B and --emitters-above LUMINANCE)' "$out/gather.err"
# Given them, it runs: the right quad's nodes all reach luminance 0.15, the left's do not.
"$radview" render "$out/two_quads_float.ply" --method final-gather --rho 0.5 --emitters-above 0.15 --spp 1 --size 16x8 \
  --out "$out/gathered.png" > /dev/null
test -s "$out/gathered.png"
"$radview" info "$out/two_quads_float.ply" --rho 0.5 --emitters-above 0.15 | grep -q '^elements: 2 (quads 2); linear 2, quadratic 0; emitting 1$'

echo "import_cli_test: ok"
