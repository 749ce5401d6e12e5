#!/usr/bin/python3
"""How noisy a solve is, and what it costs: solves of one scene with two seeds, their difference.

  /usr/bin/python3 tests/bench/solution_noise.py --radview build/radview [--scene assets/cornell_box.gltf]
      [--rounds 3] [--grid 120] [--out FILE.md] --config 'LABEL | SOLVE ARGUMENTS' [--config ...]

Each config is `radview solve SCENE ARGUMENTS` run with two seeds, round k (from 0) with seeds
2k + 1 and 2k + 2, so that each round's noise is an independent estimate (their spread is the figure's own
noise). Both solutions
are sampled with Gouraud (`radview sample`) at a grid x grid of points on the floor (the scene's
lowest horizontal polygon, 2 % in from its bounding box), and the solution's noise is
RMS(Y1 - Y2) / sqrt(2) over them, Y the luminance of B (the two seeds' errors are independent,
so their difference has twice the variance of one). Beside it, what the solver says of its own
noise: the RMS over the same points of its standard errors (`sample --standard-error`, the
luminance of SE_r SE_g SE_b), over both seeds. Configs run interleaved, round after round
(A B C A B C ...), each round starting one config later, so that a machine's slow spell falls
on all of them; a config's time is the median wall time of its solves, its ratio to the first
config the median over rounds of the round's ratio. Writes the table to standard output (and
--out). Exit 2 naming what failed.
"""
import argparse
import math
import os
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

PROGRAM = "solution_noise"
LUMA = np.array([0.2126, 0.7152, 0.0722])


def fail(message):
    print("%s: error: %s" % (PROGRAM, message), file=sys.stderr)
    sys.exit(2)


def run(cmd):
    start = time.time()
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        fail("%s failed (exit %d):\n%s" % (" ".join(shlex.quote(c) for c in cmd), done.returncode,
                                           (done.stdout + done.stderr)[-2000:]))
    return time.time() - start, done.stdout


def floor_points(scene, grid):
    """A grid of points on the lowest horizontal polygon's bounding box, 2 % in from its edges."""
    import json
    with open(scene) as f:
        gltf = json.load(f)
    lowest = None
    for mesh in gltf["meshes"]:
        accessor = gltf["accessors"][mesh["primitives"][0]["attributes"]["POSITION"]]
        lo, hi = accessor["min"], accessor["max"]
        if abs(hi[1] - lo[1]) < 1e-9 and (lowest is None or lo[1] < lowest[0][1]):
            lowest = (lo, hi)
    if lowest is None:
        fail("%s: no horizontal polygon for the floor" % scene)
    lo, hi = lowest
    ts = 0.02 + 0.96 * (np.arange(grid) + 0.5) / grid
    return [(lo[0] + u * (hi[0] - lo[0]), lo[1], lo[2] + v * (hi[2] - lo[2])) for v in ts for u in ts]


def sample(radview, solution, points_file):
    """Luminance of B and of its standard error at the points."""
    _, out = run([radview, "sample", solution, "--method", "gouraud", "--standard-error", "--points", points_file])
    rows = [line.split() for line in out.splitlines() if line and not line.startswith("#")]
    # Columns: element x y z distance B_r B_g B_b, nine gradient components, SE_r SE_g SE_b.
    values = np.array([[float(x) for x in r[5:8] + r[17:20]] for r in rows])
    return values[:, :3] @ LUMA, values[:, 3:] @ LUMA


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--radview", required=True)
    p.add_argument("--scene", default=os.path.join(os.path.dirname(__file__), "..", "..", "assets",
                                                   "cornell_box.gltf"))
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--grid", type=int, default=120)
    p.add_argument("--config", action="append", required=True, help="'LABEL | radview solve arguments'")
    p.add_argument("--out")
    args = p.parse_args()
    configs = []
    for c in args.config:
        if "|" not in c:
            fail("--config '%s': expected 'LABEL | ARGUMENTS'" % c)
        label, arguments = (part.strip() for part in c.split("|", 1))
        configs.append((label, shlex.split(arguments)))
    work = tempfile.mkdtemp(prefix="radview-noise-")
    points_file = os.path.join(work, "floor.txt")
    with open(points_file, "w") as f:
        f.writelines("%.9g %.9g %.9g\n" % p for p in floor_points(args.scene, args.grid))
    seconds = {label: [] for label, _ in configs}
    ratios = {label: [] for label, _ in configs}
    noise = {label: [] for label, _ in configs}
    estimated = {label: [] for label, _ in configs}
    mean_y = {label: [] for label, _ in configs}
    for r in range(args.rounds):
        order = configs[r % len(configs):] + configs[:r % len(configs)]
        this_round = {}
        for label, arguments in order:
            ys, errors, walls = [], [], []
            for seed in (2 * r + 1, 2 * r + 2):
                out = os.path.join(work, "s%d.glb" % seed)
                wall, _ = run([args.radview, "solve", args.scene, "-o", out, "--seed", str(seed)] + arguments)
                walls.append(wall)
                y, error = sample(args.radview, out, points_file)
                ys.append(y)
                errors.append(error)
            seconds[label] += walls
            this_round[label] = sum(walls)
            noise[label].append(float(np.sqrt(np.mean((ys[0] - ys[1]) ** 2) / 2)))
            estimated[label].append(float(np.sqrt(np.mean(errors[0] ** 2 + errors[1] ** 2) / 2)))
            mean_y[label].append(float(np.mean(ys[0] + ys[1]) / 2))
            print("round %d, %s: %.1f s + %.1f s, noise %.3g" % (r + 1, label, walls[0], walls[1], noise[label][-1]),
                  file=sys.stderr, flush=True)
        for label, _ in configs:
            ratios[label].append(this_round[label] / this_round[configs[0][0]])
    lines = ["Solution noise on the floor of %s: %dx%d points, Gouraud, luminance; %d rounds interleaved, "
             "a new pair of seeds each; %d CPU threads." % (os.path.basename(args.scene), args.grid, args.grid, args.rounds,
                                                       os.cpu_count() or 1),
             "",
             "| solve | arguments | time, s (median) | time ratio (median, range) | floor noise, RMS (mean; each round) "
             "| of the floor's mean Y | the solver's estimate (mean) |",
             "|---|---|---|---|---|---|---|"]
    for label, arguments in configs:
        n = statistics.mean(noise[label])
        m = statistics.mean(mean_y[label])
        lines.append("| %s | `%s` | %.2f | %.2fx (%.2f-%.2f) | %.3g (%s) | %.2f %% | %.3g (%.2fx) |" % (
            label, " ".join(arguments) or "(defaults)", statistics.median(seconds[label]),
            statistics.median(ratios[label]), min(ratios[label]), max(ratios[label]), n,
            ", ".join("%.3g" % x for x in noise[label]), 100 * n / m, statistics.mean(estimated[label]),
            statistics.mean(estimated[label]) / n))
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
