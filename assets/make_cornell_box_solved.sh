#!/usr/bin/env bash
# Writes assets/cornell_box_solved.glb, the solution a bare `radview` opens: the measured
# Cornell box (cornell_box.gltf) solved by radview itself, with discontinuity meshing, adaptive
# subdivision (which leaves T-vertices) and interreflection. Rerun it when the solver changes;
# the test assets.solved_cornell_box_is_current fails until then.
#   assets/make_cornell_box_solved.sh [RADVIEW [OUT]]   (defaults: build/radview, the asset)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
radview=${1:-$here/../build/radview}
out=${2:-$here/cornell_box_solved.glb}
"$radview" solve "$here/cornell_box.gltf" -o "$out" --discontinuity-meshing --seed 1
