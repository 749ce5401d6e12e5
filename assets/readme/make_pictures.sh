#!/usr/bin/env bash
# Makes the pictures README.md shows, each with the radview command README names under it.
# The viewer's screenshot needs Xvfb (xvfb-run); everything else renders headless.
#   assets/readme/make_pictures.sh [RADVIEW]   (default: build/radview)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
radview=$(readlink -f "${1:-$here/../../build/radview}")
cd "$here/../.."  # the repository root: README's commands run from there
out=assets/readme

# The viewer as a bare `radview` opens it: the solved Cornell box beside the panel.
xvfb-run -a -s "-screen 0 1400x900x24" "$radview" --size 1400x800 --frames 10 --screenshot $out/viewer.png

# The solved Cornell box, and a close-up of the short block with the mesh's structure.
"$radview" render assets/cornell_box_solved.glb --method clough-tocher --size 512x512 --out $out/cornell_solved.png
closeup="--camera 0.40,0.20,0.03/0.22,0.0,0.17 --size 480x360"
"$radview" render assets/cornell_box_solved.glb --method clough-tocher $closeup --out $out/cornell_closeup.png
"$radview" render assets/cornell_box_solved.glb --method clough-tocher $closeup --edges --discontinuities \
  --t-vertices --out $out/cornell_closeup_mesh.png

# Fig. 9.8: one quad, scanline Gouraud upright, turned 45 and 90 degrees; bilinear turned 45.
"$radview" render assets/fig9_8_quad.gltf --method scanline-gouraud --edges --camera 0,0,2/0,0,0/0,1,0 \
  --size 200x200 --out $out/fig98_scanline_0.png
"$radview" render assets/fig9_8_quad.gltf --method scanline-gouraud --edges \
  --camera 0,0,2/0,0,0/-0.7071068,0.7071068,0 --size 200x200 --out $out/fig98_scanline_45.png
"$radview" render assets/fig9_8_quad.gltf --method scanline-gouraud --edges --camera 0,0,2/0,0,0/-1,0,0 \
  --size 200x200 --out $out/fig98_scanline_90.png
"$radview" render assets/fig9_8_quad.gltf --method bilinear --edges \
  --camera 0,0,2/0,0,0/-0.7071068,0.7071068,0 --size 200x200 --out $out/fig98_bilinear_45.png

# Selected discontinuities: a kink (C0) and a step (C-1), Gouraud against Clough-Tocher.
oblique="--camera 0.5,-0.6,1.1/0.5,0.5,0 --size 256x256"
"$radview" render assets/discontinuities.gltf --method gouraud $oblique --out $out/discontinuities_gouraud.png
"$radview" render assets/discontinuities.gltf --method clough-tocher $oblique --discontinuities \
  --out $out/discontinuities_clough_tocher.png
"$radview" render assets/discontinuities.gltf --method clough-tocher --surface 0.25 \
  --camera 1.6,-0.9,1.1/0.5,0.5,0.1/0,0,1 --size 256x256 --out $out/discontinuities_surface.png

# Meshing for the view (C&W 9.3): 1,000 elements for every view, and for the corner view only.
corner="--camera 0.2,0.3,0.25/0.0,0.05,0.559 --size 384x288"
solved=$(mktemp -d)
trap 'rm -rf "$solved"' EXIT
budget="--max-elements 1000 --tolerance 1 --min-element-size 0.00125"
"$radview" solve assets/cornell_box.gltf -o "$solved/independent.glb" $budget >/dev/null
"$radview" solve assets/cornell_box.gltf -o "$solved/corner.glb" $budget \
  --view 0.2,0.3,0.25/0.0,0.05,0.559 --view-size 384x288 >/dev/null
"$radview" render "$solved/independent.glb" --method gouraud --edges $corner --out $out/view_independent_corner.png
"$radview" render "$solved/corner.glb" --method gouraud --edges $corner --out $out/view_driven_corner.png
"$radview" render "$solved/corner.glb" --method gouraud --edges --size 288x288 --out $out/view_driven_whole.png

# The Python page's worked example (app/python/README.md): a row of pixels, radview against scipy.
PYTHONPATH="$(dirname "$radview")/python" /usr/bin/python3 app/python/examples/worked_example.py --out "$solved"
cp "$solved/worked_example.png" $out/python_worked_example.png

# The truth table's pictures (truth | row | difference) come with its figures:
# tests/bench/regenerate_figures.sh truth.
