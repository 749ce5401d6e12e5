#!/usr/bin/python3
"""radview's path tracer against Cycles: a benchmark (time at equal noise) and a test (per-surface means).

  /usr/bin/python3 tests/truth/path_tracer_vs_cycles.py --radview build/radview \\
      --scene assets/cornell_box.gltf --size 64x64 --spp-radview 1024 --spp-cycles 1024 --rounds 2 \\
      [--check] [--out-dir DIR] [--blender blender] [--erode 1] [--bias 1.0]

Each round r renders, interleaved so that drift in the machine's speed falls on both alike:
Cycles seed 2r+1, radview seed 2r+1, Cycles seed 2r+2, radview seed 2r+2 (Cycles through
cycles_reference.py with --threads os.cpu_count(), radview's parallelFor's thread count; one
extra 1-spp Cycles run first writes the surface-id image). Only interior pixels count: pixels
seeing a surface's front whose neighbours within --erode see the same surface (surface_means).

Benchmark: render time per image is Cycles' own "s render" figure (scene sync and render,
Blender's start-up excluded) and radview's printed seconds; wall times, start-up included, are
shown too. Noise of one image: RMS((s1 - s2) / sqrt 2) / mean over interior pixels, in
luminance, per round's seed pair (surface_means --noise), pooled over rounds as an RMS. Time
to reach noise T: time x (noise / T)^2 (noise ~ 1 / sqrt(samples)), T the smaller noise; the
ratio radview / Cycles at equal noise per round, its median and range over rounds.

Test: per surface (and all interior pixels together), radview's mean over Cycles' mean, in
Y, R, G, B, each mean over all 2R images with its standard error from the seed differences
(surface_means.surface_estimates: independent pixel noise, se = RMS((s1-s2)/2) / sqrt(n) for
one pair); the ratio's standard error se_r = sqrt(se_a^2 + r^2 se_b^2) / b. The table shows
the 95 % interval r +- 1.96 se_r (Student t) and whether it holds 1.

--check fails (exit 1, naming the surface and channel) where |r - 1| > max(z se_r, 0.005):
  * z: the two-sided t quantile (Welch-Satterthwaite degrees of freedom) at 0.001 / m, m the
    number of ratios tested (4 channels x (surfaces + the all-pixels row), ~30-60): a
    Bonferroni bound, so that a run whose renderers agree fails by chance at most 1 in 1000
    times over all its surfaces together (3.3 sigma per ratio would fail ~1 in 30 runs with
    ~30 ratios); z is about 4.2 (32 ratios at 64x64, 48 at 128x128). Surfaces with under 20
    interior pixels are not tested (their se is itself too uncertain), nor channels whose
    Cycles mean is 0. The se assumes independent pixels; checked at 64x64, 64 spp: 128 radview
    and 80 Cycles images give neighbour correlations of the seed noise within +-0.01 over
    offsets up to 4 pixels; the variance of the all-pixels mean over seeds is 1.04 (radview) and
    1.05 (Cycles) times the predicted one (per surface 0.7-1.5, chi-square scatter, mean 1.06
    for both), and (r - 1) / se_r over 2016 radview-vs-radview comparisons has sd 1.00. The
    script prints the lag-1 correlation of each run.
  * 0.005: a floor, so that a systematic difference under 0.5 % (the two renderers' own
    conventions: ray offsets, float precision, light sampling) does not fail a long run
    whose se has become tiny. It only lowers the false-alarm rate, and 1 % stays above it.
  * detection: a bias b fails with ~95 % probability where b > max(z se_r, 0.005) + 1.645 se_r;
    the table's "detects" column gives that bias per surface (luminance). At 64x64, 1024 spp
    each, 2 rounds (and 128x128, 256 spp), the all-pixels row detects 0.54 %, the floor,
    ceiling and walls 0.56-0.65 %, the small block faces only 1.9-2.6 %: a global 1 % bias
    fails on ~all 32-48 ratios (radview's saved images x 1.01 or 0.99), a 1 % bias confined to
    one small block face may not.
--bias F multiplies radview's images by F before the comparison (a check of the check: 1.01
must fail). Exit 2 where blender, the radview binary or the scene is missing or a render fails.
"""
import argparse
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from surface_means import interior, legend, read_ids, read_rgb, relative_noise, surface_estimates  # noqa: E402

CHANNELS = ("Y", "R", "G", "B")  # surface_estimates' order is R, G, B, Y
INDEX = {"R": 0, "G": 1, "B": 2, "Y": 3}
MIN_PIXELS = 20
FLOOR = 0.005
FAMILY_ALPHA = 0.001


def fail(message, code=2):
    print("path_tracer_vs_cycles: error: " + message, file=sys.stderr)
    sys.exit(code)


def t_quantile(p, dof):
    """Student t quantile, Cornish-Fisher expansion around the normal one (good for dof >= 20)."""
    z = statistics.NormalDist().inv_cdf(p)
    terms = [(z ** 3 + z) / 4, (5 * z ** 5 + 16 * z ** 3 + 3 * z) / 96,
             (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / 384,
             (79 * z ** 9 + 776 * z ** 7 + 1482 * z ** 5 - 1920 * z ** 3 - 945 * z) / 92160]
    return z + sum(t / dof ** (i + 1) for i, t in enumerate(terms))


def compare(est_a, est_b):
    """Ratios a / b of surface_estimates: ({k: (pixels, {channel: (r, se_r, 95 % half-width,
    allowed |r - 1| or None where not tested)})}, the check's z for large dof, ratios tested)."""
    tested = [(k, c) for k, (n, mean, _, _) in est_b.items() for c in CHANNELS
              if n >= MIN_PIXELS and mean[INDEX[c]] > 0]
    p_check = 1 - FAMILY_ALPHA / (2 * max(len(tested), 1))
    rows = {}
    for k, (n, mean_b, se_b, dof_b) in est_b.items():
        _, mean_a, se_a, dof_a = est_a[k]
        cols = {}
        for c in CHANNELS:
            a, sa, b, sb = mean_a[INDEX[c]], se_a[INDEX[c]], mean_b[INDEX[c]], se_b[INDEX[c]]
            if b <= 0:
                continue
            r = a / b
            se = math.sqrt(sa ** 2 + (r * sb) ** 2) / b
            spread = sa ** 4 / dof_a + sb ** 4 / dof_b  # Welch-Satterthwaite; 0 on a noise-free surface (an emitter)
            dof = (sa ** 2 + sb ** 2) ** 2 / spread if spread > 0 else math.inf
            half = t_quantile(0.975, max(dof, 20)) * se
            cols[c] = (r, se, half, max(t_quantile(p_check, dof) * se, FLOOR) if (k, c) in tested else None)
        rows[k] = (n, cols)
    return rows, statistics.NormalDist().inv_cdf(p_check), len(tested)


def run(cmd, pattern, what):
    start = time.time()
    done = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - start
    found = re.search(pattern, done.stdout + done.stderr)
    if done.returncode != 0 or not found:
        fail("%s failed (exit %d): %s\n%s" % (what, done.returncode, " ".join(cmd),
                                              (done.stdout + done.stderr)[-3000:]))
    return float(found.group(1)), wall


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--radview", required=True, help="the radview binary")
    p.add_argument("--scene", required=True)
    p.add_argument("--size", default="64x64")
    p.add_argument("--spp-radview", type=int, default=1024)
    p.add_argument("--spp-cycles", type=int, default=1024)
    p.add_argument("--rounds", type=int, default=1)
    p.add_argument("--check", action="store_true", help="exit 1 where a surface's means differ (see above)")
    p.add_argument("--out-dir", help="keep the images here (default: a temporary directory, removed)")
    p.add_argument("--blender", default="blender")
    p.add_argument("--erode", type=int, default=1)
    p.add_argument("--bias", type=float, default=1.0, help="multiply radview's images by this (tests the test)")
    args = p.parse_args()
    blender = shutil.which(args.blender)
    if not blender:
        fail("blender (%s) not found: install Blender or pass --blender PATH" % args.blender)
    if not (os.path.isfile(args.radview) and os.access(args.radview, os.X_OK)):
        fail("radview binary %s not found or not executable (build it, or pass --radview PATH)" % args.radview)
    if not os.path.isfile(args.scene):
        fail("scene %s not found" % args.scene)
    if args.rounds < 1 or min(args.spp_radview, args.spp_cycles) < 1:
        fail("--rounds and --spp-* must be >= 1")
    threads = os.cpu_count() or 1
    work = args.out_dir or tempfile.mkdtemp(prefix="pt_vs_cycles_")
    os.makedirs(work, exist_ok=True)
    scene = os.path.abspath(args.scene)

    def cycles(seed, spp, ids=None):
        out = os.path.join(work, "cycles_%d.exr" % seed)
        cmd = [blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "cycles_reference.py"), "--",
               scene, out, "--size", args.size, "--spp", str(spp), "--seed", str(seed), "--threads", str(threads)]
        seconds, wall = run(cmd + (["--ids", ids] if ids else []), r"([0-9.]+) s render", "Cycles")
        return out, seconds, wall

    def radview(seed):
        out = os.path.join(work, "radview_%d.exr" % seed)
        cmd = [args.radview, "render", scene, "--method", "path-trace", "--spp", str(args.spp_radview),
               "--seed", str(seed), "--size", args.size, "--out", out[:-4] + ".png", "--linear-out", out]
        seconds, wall = run(cmd, r"path tracer: .*?: ([0-9.]+) s", "radview")
        return out, seconds, wall

    ids_path = os.path.join(work, "ids.exr")
    cycles(0, 1, ids_path)
    labels = interior(read_ids(ids_path), args.erode)
    names = legend(ids_path)
    print("%s, %s, %d threads, radview %d spp, Cycles %d spp, %d round(s), %d interior pixels; images in %s"
          % (args.scene, args.size, threads, args.spp_radview, args.spp_cycles, args.rounds,
             int((labels > 0).sum()), work))
    renders = {"radview": [], "Cycles": []}  # per round: [(image, seconds, wall), (...)]
    for r in range(args.rounds):
        pair = {"radview": [], "Cycles": []}
        for seed in (2 * r + 1, 2 * r + 2):
            pair["Cycles"].append(cycles(seed, args.spp_cycles))
            pair["radview"].append(radview(seed))
        for name in pair:
            renders[name].append(pair[name])
            print("  round %d %-7s seeds %d, %d: %.2f + %.2f s render, %.2f + %.2f s wall" % (
                r + 1, name, 2 * r + 1, 2 * r + 2, pair[name][0][1], pair[name][1][1],
                pair[name][0][2], pair[name][1][2]))

    images = {name: [tuple(read_rgb(path) * (args.bias if name == "radview" else 1.0) for path, _, _ in rnd)
                     for rnd in rounds] for name, rounds in renders.items()}
    for pairs in images.values():
        for a, b in pairs:
            if a.shape[:2] != labels.shape:
                fail("an image is %dx%d, the id image %dx%d" % (a.shape[1], a.shape[0], *labels.shape[::-1]))

    # Benchmark.
    noise = {n: [relative_noise(labels, a, b)[3] for a, b in images[n]] for n in images}
    seconds = {n: [0.5 * (rnd[0][1] + rnd[1][1]) for rnd in renders[n]] for n in renders}
    pooled = {n: math.sqrt(np.mean(np.square(noise[n]))) for n in noise}
    target = min(pooled.values())
    print("\n%-8s %5s %13s %11s %12s %20s" % ("", "spp", "render s/img", "wall s/img", "noise/img",
                                             "s/img at noise %.4f" % target))
    for n, spp in (("radview", args.spp_radview), ("Cycles", args.spp_cycles)):
        t = statistics.median(seconds[n])
        walls = [w for rnd in renders[n] for _, _, w in rnd]
        print("%-8s %5d %13.2f %11.2f %12.4f %20.2f" % (n, spp, t, statistics.median(walls), pooled[n],
                                                          t * (pooled[n] / target) ** 2))
    ratios = [seconds["radview"][r] * noise["radview"][r] ** 2 / (seconds["Cycles"][r] * noise["Cycles"][r] ** 2)
              for r in range(args.rounds)]
    print("radview / Cycles time at equal noise: %.2f" % statistics.median(ratios)
          + (" (rounds: %s)" % ", ".join("%.2f" % x for x in ratios) if args.rounds > 1 else ""))
    for n in images:  # independent pixel noise is what the standard errors assume
        d = [a - b for a, b in images[n]]
        same = (labels[:, 1:] > 0) & (labels[:, 1:] == labels[:, :-1])
        x = np.concatenate([(e @ [0.2126, 0.7152, 0.0722])[:, :-1][same] for e in d])
        y = np.concatenate([(e @ [0.2126, 0.7152, 0.0722])[:, 1:][same] for e in d])
        print("%s: correlation of horizontal neighbours' seed differences %+.3f (independent: 0 +- %.3f)"
              % (n, np.corrcoef(x, y)[0, 1], 1 / math.sqrt(len(x))))

    # Test.
    rows, z_check, m = compare(surface_estimates(labels, images["radview"]), surface_estimates(labels, images["Cycles"]))
    print("\nradview mean / Cycles mean per surface, 95 %% interval; check: |r-1| <= max(z se, %.3f), "
          "z ~ %.2f (t quantile at %.1e two-sided: %d ratios)" % (FLOOR, z_check, FAMILY_ALPHA / max(m, 1), m))
    print("%4s %5s  %-27s %4s %8s  %-20s %-20s %-20s  %s" % ("id", "px", "Y ratio [95 %]", "has1", "detects",
                                                             "R ratio +-95%", "G", "B", "surface"))
    failures = []
    for k, (n, cols) in rows.items():
        label = re.sub(r"^node \d+ \((.*?)\).*", r"\1", "all interior pixels" if k == "all" else names.get(k, ""))
        cells = {c: "-" for c in CHANNELS}
        has1 = detects = ""
        for c, (r, se, half, allowed) in cols.items():
            cells[c] = ("%.4f [%.4f, %.4f]" % (r, r - half, r + half)) if c == "Y" else "%.4f +- %.4f" % (r, half)
            if c == "Y":
                has1 = "yes" if abs(r - 1) <= half + 1e-6 else "NO"  # 1e-6: float rounding where se is 0
                detects = "%.2f %%" % (100 * (allowed + 1.645 * se)) if allowed else ""
            if allowed and abs(r - 1) > allowed:
                failures.append("%s %s: ratio %.4f, allowed 1 +- %.4f (se %.4f)"
                                % ("all interior pixels" if k == "all" else "surface %s (%s)" % (k, label), c, r, allowed, se))
        tested = any(col[3] for col in cols.values())
        print("%4s %5d  %-27s %4s %8s  %-20s %-20s %-20s  %s" % (k, n, cells["Y"], has1, detects, cells["R"], cells["G"],
                                                                 cells["B"], label + ("" if tested else " (not tested)")))
    if failures:
        print("\nCHECK FAILS: radview's path tracer and Cycles differ beyond noise:\n  " + "\n  ".join(failures))
    else:
        print("\ncheck holds: every tested surface agrees within max(z se, %.3f)" % FLOOR)
    if not args.out_dir:
        shutil.rmtree(work)
    sys.exit(1 if failures and args.check else 0)


if __name__ == "__main__":
    main()
