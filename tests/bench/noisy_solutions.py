#!/usr/bin/python3
"""How far noisy solutions are from a converged one, drawn by each method: interpolants against
the thin-plate smoothing spline (C&W 9.2's last paragraph).

  /usr/bin/python3 tests/bench/noisy_solutions.py --radview build/radview [--scene assets/cornell_box.gltf]
      [--samples 1,4,16] [--seeds 3] [--size 128x128] [--gather-spp 4096] [--out FILE.md]
      [--picture FILE.png] [--work DIR]

The converged solve is `radview solve SCENE --discontinuity-meshing --samples 256 --max-samples
256`; the noisy ones take one batch of N samples per node and shot (`--samples N --max-samples
N`), each with its own seed. Every image is the scene's camera at --size.

Two measures, both `radview bench --truth` (display steps, RMS over the pixels whose four
neighbours see the same plane):
- a noisy solve drawn by method M against the converged solve drawn by the same method: what the
  noise does to the picture each method makes (the converged row is 0 by construction);
- the converged solve drawn by M against the final gather over it (--gather-spp): the
  method's own error on a converged solution, where smoothing must not cost anything.
Rows give the mean over the seeds and their range. --picture writes the floor beside the short
block from one --samples 4 solve: Clough-Tocher | thin-plate, same view and exposure.
Writes the table to standard output (and --out). Exit 2 naming what failed.
"""
import argparse
import csv
import os
import shlex
import statistics
import subprocess
import sys
import tempfile

PROGRAM = "noisy_solutions"
METHODS = ["gouraud", "clough-tocher", "thin-plate"]
PICTURE_CAMERA = "0.1,0.32,-0.02/0.3,0,0.25"


def fail(message):
    print("%s: error: %s" % (PROGRAM, message), file=sys.stderr)
    sys.exit(2)


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        fail("%s failed (exit %d):\n%s" % (" ".join(shlex.quote(c) for c in cmd), done.returncode,
                                           (done.stdout + done.stderr)[-2000:]))
    return done.stdout


def bench_errors(radview, solution, truth, size, out_dir):
    """Display-step RMSE of every per-pixel row of `radview bench` against `truth`."""
    run([radview, "bench", solution, "--truth", truth, "--size", size, "--levels", "1", "--tolerances", "0.5",
         "--frames", "1", "--row-seconds", "0", "--out-dir", out_dir])
    with open(os.path.join(out_dir, "bench.csv")) as f:
        return {row["method"]: float(row["display_rmse_steps"]) for row in csv.DictReader(f)
                if row["setting"] == "per pixel"}


def summary(values):
    return "%.3g [%.3g, %.3g]" % (statistics.mean(values), min(values), max(values))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--radview", required=True)
    p.add_argument("--scene", default=os.path.join(os.path.dirname(__file__), "..", "..", "assets",
                                                   "cornell_box.gltf"))
    p.add_argument("--samples", default="1,4,16")
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--size", default="128x128")
    p.add_argument("--gather-spp", type=int, default=4096)
    p.add_argument("--out")
    p.add_argument("--picture")
    p.add_argument("--work")
    args = p.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="radview-noisy-")
    os.makedirs(work, exist_ok=True)
    solve = [args.radview, "solve", args.scene, "--discontinuity-meshing"]

    converged = os.path.join(work, "converged.glb")
    run(solve + ["--samples", "256", "--max-samples", "256", "--seed", "1000", "-o", converged])
    references = {}
    for m in METHODS:
        references[m] = os.path.join(work, "converged-%s.exr" % m)
        run([args.radview, "render", converged, "--method", m, "--size", args.size,
             "--out", os.path.join(work, "converged-%s.png" % m), "--linear-out", references[m]])
    gather = os.path.join(work, "gather.exr")
    run([args.radview, "render", converged, "--method", "final-gather", "--spp", str(args.gather_spp),
         "--size", args.size, "--out", os.path.join(work, "gather.png"), "--linear-out", gather])
    own = bench_errors(args.radview, converged, gather, args.size, os.path.join(work, "bench-converged"))

    rows = []
    for samples in [int(s) for s in args.samples.split(",")]:
        errors = {m: [] for m in METHODS}
        for seed in range(1, args.seeds + 1):
            noisy = os.path.join(work, "samples%d-seed%d.glb" % (samples, seed))
            run(solve + ["--samples", str(samples), "--max-samples", str(samples), "--seed", str(seed), "-o", noisy])
            for m in METHODS:
                measured = bench_errors(args.radview, noisy, references[m], args.size,
                                        os.path.join(work, "bench-%d-%d-%s" % (samples, seed, m)))
                errors[m].append(measured[m])
            print("samples %d, seed %d: %s" % (samples, seed, ", ".join("%s %.3g" % (m, errors[m][-1])
                                                                        for m in METHODS)),
                  file=sys.stderr, flush=True)
            if args.picture and samples == 4 and seed == 1:
                halves = []
                for m in ["clough-tocher", "thin-plate"]:
                    halves.append(os.path.join(work, "picture-%s.png" % m))
                    run([args.radview, "render", noisy, "--method", m, "--camera", PICTURE_CAMERA, "--size",
                         "320x240", "--out", halves[-1]])
                run(["oiiotool", halves[0], halves[1], "--mosaic", "2x1", "-o", args.picture])
        ratios = [t / c for t, c in zip(errors["thin-plate"], errors["clough-tocher"])]
        rows.append("| `--samples %d --max-samples %d` | %s | %s |" % (
            samples, samples, " | ".join(summary(errors[m]) for m in METHODS), summary(ratios)))

    lines = ["Noisy solves of %s against a converged one (`--samples 256 --max-samples 256`), both "
             "`--discontinuity-meshing`; %s, display steps, mean [range] over %d seeds; 2 CPU threads." % (
                 os.path.basename(args.scene), args.size, args.seeds),
             "",
             "| solve | %s | thin-plate / clough-tocher |" % " | ".join(METHODS),
             "|---|" + "---|" * (len(METHODS) + 1)]
    lines += rows
    lines.append("| converged, against the final gather over it (%d spp) | %s | %.3g |" % (
        args.gather_spp, " | ".join("%.3g" % own[m] for m in METHODS), own["thin-plate"] / own["clough-tocher"]))
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
