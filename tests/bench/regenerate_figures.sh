#!/usr/bin/env bash
# Runs the benchmarks whose figures README.md shows, each writing its result files, then rewrites
# README's figure blocks from those files (tests/bench/readme_figures.py). Run it from a Release
# build on a quiet machine: its timings are the machine's, and README states the hardware beside
# each table.
#   tests/bench/regenerate_figures.sh [RADVIEW] [PART...]
# PART: fig9_14, cornell, cornell-truth (radview bench, into assets/bench/PART/), noise (the
# solver's noise and time at three sample settings, tests/bench/solution_noise.py, into
# tests/bench/results/solution_noise.md), noisy (noisy solves drawn by the interpolants and
# the thin-plate spline against a converged one, tests/bench/noisy_solutions.py, into
# tests/bench/results/noisy_solutions.md and assets/readme/noisy_penumbra.png), truth (Cycles
# against every way radview shows the Cornell box, tests/truth/agreement_table.py: needs blender;
# its table into tests/bench/results/truth/, its pictures into assets/readme/truth/), or all (the
# default). Minutes each on 2 cores; truth about half an hour.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cd "$here/../.."  # the repository root: the commands below run from there
radview=build/radview
if [ $# -gt 0 ] && [ -x "$1" ] && [ ! -d "$1" ]; then radview=$1; shift; fi
radview=$(readlink -f "$radview")
parts=("$@")
[ ${#parts[@]} -eq 0 ] && parts=(all)

wants() {
  local part
  for part in "${parts[@]}"; do [ "$part" = all ] || [ "$part" = "$1" ] && return 0; done
  return 1
}
for part in "${parts[@]}"; do
  case $part in all | fig9_14 | cornell | cornell-truth | noise | noisy | truth) ;;
    *) echo "regenerate_figures: unknown part '$part' (fig9_14, cornell, cornell-truth, noise, noisy, truth, all)" >&2
       exit 2 ;;
  esac
done

# A bench writes every row's image, linear EXR and error map; what the docs show is kept under
# assets/bench/PART: the tables and plot, each method's picture, the reference and its noise,
# and the per-pixel rows' error maps.
bench() {
  local part=$1 work=build/bench-figures/$1
  shift
  rm -rf "$work" && mkdir -p "$work"
  "$radview" bench "$@" --out-dir "$work"
  rm -rf "assets/bench/$part" && mkdir -p "assets/bench/$part"
  local file name
  for file in "$work"/bench.md "$work"/bench.csv "$work"/*.png; do
    name=$(basename "$file")
    case $name in *-error.png) case $name in *-per-pixel*) ;; *) continue ;; esac ;; esac
    cp "$file" "assets/bench/$part/"
  done
}
if wants fig9_14; then
  bench fig9_14 assets/fig9_14.gltf --camera 0.7,0.5,1.9/0.7,0.5,0/0,1,0 --size 320x320 --spp 1024 --frames 9
fi
if wants cornell; then
  bench cornell assets/cornell_box_solved.glb
fi
if wants cornell-truth; then
  bench cornell-truth assets/cornell_box_solved.glb --reference path-trace --size 256x256 --spp 1024
fi
if wants noise; then
  mkdir -p tests/bench/results
  /usr/bin/python3 tests/bench/solution_noise.py --radview "$radview" --rounds 3 \
    --out tests/bench/results/solution_noise.md \
    --config 'before: 16 samples everywhere | --discontinuity-meshing --samples 16 --max-samples 16' \
    --config 'the defaults: 32, up to 256 where seen in part | --discontinuity-meshing' \
    --config '128 samples everywhere | --discontinuity-meshing --samples 128 --max-samples 128'
fi
if wants noisy; then
  mkdir -p tests/bench/results
  /usr/bin/python3 tests/bench/noisy_solutions.py --radview "$radview" --seeds 3 \
    --out tests/bench/results/noisy_solutions.md --picture assets/readme/noisy_penumbra.png
fi
if wants truth; then
  work=build/truth-figures
  /usr/bin/python3 tests/truth/agreement_table.py --radview "$radview" --scene assets/cornell_box.gltf \
    --size 128x128 --cycles-spp 2048 --out-dir "$work" --reuse-truth
  mkdir -p tests/bench/results/truth assets/readme/truth
  cp "$work/agreement.md" "$work/agreement.csv" tests/bench/results/truth/
  rm -f assets/readme/truth/*.png
  cp "$work"/*.png assets/readme/truth/
fi
/usr/bin/python3 tests/bench/readme_figures.py --write
