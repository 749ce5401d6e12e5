#!/usr/bin/env bash
# Runs the benchmarks whose figures README.md shows, each writing its result files, then rewrites
# README's figure blocks from those files (tests/bench/readme_figures.py). Run it from a Release
# build on a quiet machine: its timings are the machine's, and README states the hardware beside
# each table.
#   tests/bench/regenerate_figures.sh [RADVIEW] [PART...]
# PART: fig9_14, cornell, cornell-truth (radview bench, into assets/bench/PART/), truth (Cycles
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
  case $part in all | fig9_14 | cornell | cornell-truth | truth) ;;
    *) echo "regenerate_figures: unknown part '$part' (fig9_14, cornell, cornell-truth, truth, all)" >&2; exit 2 ;;
  esac
done

if wants fig9_14; then
  "$radview" bench assets/fig9_14.gltf --camera 0.7,0.5,1.9/0.7,0.5,0/0,1,0 --size 320x320 --spp 1024 \
    --frames 9 --out-dir assets/bench/fig9_14
fi
if wants cornell; then
  "$radview" bench assets/cornell_box_solved.glb --out-dir assets/bench/cornell
fi
if wants cornell-truth; then
  "$radview" bench assets/cornell_box_solved.glb --reference path-trace --size 256x256 --spp 1024 \
    --out-dir assets/bench/cornell-truth
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
