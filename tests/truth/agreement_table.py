#!/usr/bin/python3
"""How far each radview image of a view is from the truth (Cycles), per surface: a table and pictures.

  /usr/bin/python3 tests/truth/agreement_table.py --radview build/radview \\
      --scene assets/cornell_box.gltf --size 128x128 --cycles-spp 2048 --out-dir DIR \\
      [--rows rows.txt] [--solution assets/cornell_box_solved.glb] [--blender blender] \\
      [--threads N] [--erode 1] [--reuse-truth]

The truth: Cycles (cycles_reference.py) at --cycles-spp, seeds 1 and 2; its image is their mean,
its noise is estimated from their difference; one extra 1-spp Cycles run writes the surface-id
image (DIR/truth/). --reuse-truth keeps DIR/truth's renders where they were made with the same
scene, size and spp (DIR/truth/truth.json).

Rows: a label and radview command lines producing a linear image of the same view and size.
Built in (ROWS below), or --rows FILE, one row a line, '#' starting a comment:
    label | step ; step ...
each step a radview command line (`solve ...` or `render ...`, a leading `radview` optional).
Placeholders: {scene} (--scene), {solution} (--solution), {dir} (DIR/runs, for solutions),
{seed}: a row with {seed} runs twice, seeds 1 and 2, and its image is their mean with its noise
estimated as Cycles'. Every `render` step gets --size, --out and --linear-out appended; the last
one's linear EXR is the row's image. A `solve` step seen before (the same command line) is not
run again: its time counts in every row that uses it. A row's time is the wall time of all its
steps (both seeds' renders for a {seed} row). --no-discontinuity-meshing is dropped where
`radview solve --help` does not know it (no discontinuity meshing is then the default).

Per row, over interior pixels (surface_means.interior, --erode) in luminance Y:
  * per surface with >= 20 interior pixels (names from the ids' json): radview mean / Cycles
    mean with a 95 % interval from the standard errors (path_tracer_vs_cycles.compare: Cycles'
    from its two seeds, a {seed} row's from its own; a row without {seed} counts as exact, its
    own noise, if any, not estimated: deterministic interpolants and single-seed final gathers);
    the worst surface (largest |r - 1|) and the range of the ratios;
  * relative RMSE: RMS(Y_row - Y_truth) / mean(Y_truth) over all interior pixels. Cycles' mean
    image is noisy: E[RMSE^2] includes its noise variance, estimated per pixel as
    (y1 - y2)^2 / 4; the table shows sqrt(RMSE^2 - that) ("net") and the raw figure. A row's
    own noise stays in: it is part of that image's distance from the truth.
Writes DIR/agreement.md (the table), DIR/agreement.csv (row, surface, ratio, low, high; Y) and
DIR/<slug>.png per row: truth | the row's image | (row - truth) / truth in Y, blue -10 %, white
0, red +10 % (clipped), black where the truth is 0; images tone-mapped as radview's PNGs
(exposure 0, clamp, sRGB), 1-pixel black gaps. Exit 2 naming what failed where blender, radview,
the scene or a file is missing, or a command fails.
"""
import argparse
import csv
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from path_tracer_vs_cycles import compare  # noqa: E402
from surface_means import LUMA, interior, legend, read_ids, read_rgb, surface_estimates  # noqa: E402

PROGRAM = "agreement_table"
MIN_PIXELS = 20
DIFF_SCALE = 0.1
# Converged in shooting (--unshot) and in the mesh (--interpolation-error: solve/interpolation_error.h).
CONVERGED = "--unshot 0.0005 --interpolation-error 0.005 --max-elements 200000"
ROWS = [
    ("path tracer, 1024 spp x 2 seeds", "render {scene} --method path-trace --spp 1024 --seed {seed}"),
    ("final gather over the bundled solution, 256 spp", "render {solution} --method final-gather --spp 256"),
    ("Clough-Tocher, bundled solution", "render {solution} --method clough-tocher"),
    ("Gouraud, bundled solution", "render {solution} --method gouraud"),
    ("Clough-Tocher, the scene as opened (default solve)", "render {scene} --method clough-tocher"),
    ("Clough-Tocher, converged solve with discontinuity meshing",
     "solve {scene} --discontinuity-meshing %s --samples 128 -o {dir}/converged_dm.glb ; "
     "render {dir}/converged_dm.glb --method clough-tocher" % CONVERGED),
    ("Clough-Tocher, converged solve without discontinuity meshing",
     "solve {scene} --no-discontinuity-meshing %s --samples 64 -o {dir}/converged_no_dm.glb ; "
     "render {dir}/converged_no_dm.glb --method clough-tocher" % CONVERGED),
    ("Clough-Tocher, shooting converged, mesh by display steps alone (DM)",
     "solve {scene} --discontinuity-meshing --unshot 0.0005 --samples 128 -o {dir}/shot_dm.glb ; "
     "render {dir}/shot_dm.glb --method clough-tocher"),
    ("final gather over the converged solve (DM), 256 spp",
     "solve {scene} --discontinuity-meshing %s --samples 128 -o {dir}/converged_dm.glb ; "
     "render {dir}/converged_dm.glb --method final-gather --spp 256" % CONVERGED),
    ("direct light only (--direct-only), Clough-Tocher", "render {scene} --direct-only --method clough-tocher"),
]


def fail(message):
    print("%s: error: %s" % (PROGRAM, message), file=sys.stderr)
    sys.exit(2)


def note(message):
    print(message, file=sys.stderr, flush=True)


def run(cmd, what, retry_binary=None):
    """Run cmd; (wall seconds, output). Where retry_binary is given, a run killed by a signal or
    that cannot start (the binary being rebuilt) is tried once more, once the binary is stable."""
    for attempt in (1, 2):
        start = time.time()
        try:
            done = subprocess.run(cmd, capture_output=True, text=True)
            code, output = done.returncode, done.stdout + done.stderr
        except OSError as e:
            code, output = -1, str(e)
        wall = time.time() - start
        if code == 0:
            return wall, output
        if retry_binary and attempt == 1 and code < 0:
            note("  %s: exit %d, retrying once the binary is stable" % (what, code))
            wait_stable(retry_binary)
            continue
        fail("%s failed (exit %d): %s\n%s" % (what, code, " ".join(shlex.quote(c) for c in cmd), output[-3000:]))


def wait_stable(path, quiet=5, limit=300):
    end, last = time.time() + limit, None
    while time.time() < end:
        stamp = os.stat(path).st_mtime if os.path.isfile(path) else None
        if stamp is not None and stamp == last:
            return
        last = stamp
        time.sleep(quiet)


def slugify(label, taken):
    slug = re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")[:60].strip("-") or "row"
    base, i = slug, 2
    while slug in taken:
        slug, i = "%s-%d" % (base, i), i + 1
    taken.add(slug)
    return slug


def read_rows(path):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if "|" not in line:
                fail("%s:%d: expected 'label | radview arguments'" % (path, number))
            label, args = (s.strip() for s in line.split("|", 1))
            if not label or not args:
                fail("%s:%d: empty label or arguments" % (path, number))
            rows.append((label, args))
    if not rows:
        fail("%s: no rows" % path)
    return rows


def parse_steps(label, text, fields, knows_no_dm):
    steps = []
    for part in text.split(";"):
        try:
            words = shlex.split(part)
        except ValueError as e:
            fail("row '%s': %s" % (label, e))
        if words and words[0] == "radview":
            words = words[1:]
        if not words:
            continue
        if words[0] not in ("solve", "render"):
            fail("row '%s': a step must be 'solve ...' or 'render ...', not '%s'" % (label, words[0]))
        if not knows_no_dm:
            words = [w for w in words if w != "--no-discontinuity-meshing"]
        steps.append(words)
    if not steps or steps[-1][0] != "render":
        fail("row '%s': the last step must be a render" % label)
    for words in steps:
        for w in words:
            for name in re.findall(r"\{(\w+)\}", w):
                if name not in fields and name != "seed":
                    fail("row '%s': unknown placeholder {%s}" % (label, name))
    return steps


def tone(rgb):
    """radview's display transform at exposure 0: clamp to [0, 1], sRGB encode."""
    v = np.clip(rgb, 0.0, 1.0)
    return np.where(v < 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)


def difference_colours(row_y, truth_y):
    rel = np.divide(row_y - truth_y, truth_y, out=np.zeros_like(truth_y), where=truth_y > 0)
    t = np.clip(rel / DIFF_SCALE, -1.0, 1.0)[..., None]
    white = np.ones(truth_y.shape + (3,))
    out = np.where(t < 0, white + t * np.array([1.0, 1.0, 0.0]), white - t * np.array([0.0, 1.0, 1.0]))
    return np.where((truth_y > 0)[..., None], out, 0.0)


def write_png(path, panels):
    h, w = panels[0].shape[:2]
    canvas = np.zeros((h, len(panels) * w + len(panels) - 1, 3), dtype=np.float32)
    for i, p in enumerate(panels):
        canvas[:, i * (w + 1):i * (w + 1) + w] = p
    buf = oiio.ImageBuf(oiio.ImageSpec(canvas.shape[1], canvas.shape[0], 3, oiio.UINT8))
    if not buf.set_pixels(oiio.ROI(0, canvas.shape[1], 0, canvas.shape[0]), canvas) or not buf.write(path):
        fail("%s: cannot write the picture (%s)" % (path, buf.geterror()))


def main():
    total_start = time.time()
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--radview", required=True, help="the radview binary")
    p.add_argument("--scene", required=True)
    p.add_argument("--size", default="128x128")
    p.add_argument("--cycles-spp", type=int, default=2048)
    p.add_argument("--out-dir", required=True)
    p.add_argument("--rows", help="rows file, lines 'label | radview arguments' (default: the built-in rows)")
    p.add_argument("--solution", default=os.path.normpath(os.path.join(HERE, "..", "..", "assets",
                                                                       "cornell_box_solved.glb")),
                   help="{solution} in the rows (default: the bundled assets/cornell_box_solved.glb)")
    p.add_argument("--blender", default="blender")
    p.add_argument("--threads", type=int, default=os.cpu_count() or 1, help="Cycles' threads")
    p.add_argument("--erode", type=int, default=1)
    p.add_argument("--reuse-truth", action="store_true", help="keep DIR/truth's Cycles renders where they match")
    args = p.parse_args()

    if not re.fullmatch(r"[1-9]\d*x[1-9]\d*", args.size):
        fail("--size must be WIDTHxHEIGHT, not %s" % args.size)
    if args.cycles_spp < 1:
        fail("--cycles-spp must be >= 1")
    blender = shutil.which(args.blender)
    if not blender:
        fail("blender (%s) not found: install Blender or pass --blender PATH" % args.blender)
    radview = os.path.abspath(args.radview)
    if not (os.path.isfile(radview) and os.access(radview, os.X_OK)):
        fail("radview binary %s not found or not executable (build it, or pass --radview PATH)" % args.radview)
    if not os.path.isfile(args.scene):
        fail("scene %s not found" % args.scene)
    scene = os.path.abspath(args.scene)
    out_dir = os.path.abspath(args.out_dir)
    truth_dir, runs_dir = os.path.join(out_dir, "truth"), os.path.join(out_dir, "runs")
    os.makedirs(truth_dir, exist_ok=True)
    os.makedirs(runs_dir, exist_ok=True)

    rows = read_rows(args.rows) if args.rows else ROWS
    fields = {"scene": scene, "solution": os.path.abspath(args.solution), "dir": runs_dir}
    knows_no_dm = "--no-discontinuity-meshing" in run([radview, "solve", "--help"], "radview solve --help", radview)[1]
    parsed = [(label, parse_steps(label, text, fields, knows_no_dm), "{seed}" in text) for label, text in rows]
    if any("{solution}" in text for _, text in rows) and not os.path.isfile(fields["solution"]):
        fail("solution %s not found (pass --solution)" % args.solution)

    # The truth.
    stamp = {"scene": scene, "size": args.size, "spp": args.cycles_spp}
    stamp_path = os.path.join(truth_dir, "truth.json")
    ids_path = os.path.join(truth_dir, "ids.exr")
    cycles_paths = [os.path.join(truth_dir, "cycles_%d.exr" % s) for s in (1, 2)]
    reuse = False
    if args.reuse_truth and os.path.isfile(stamp_path) and all(map(os.path.isfile, cycles_paths + [ids_path])):
        with open(stamp_path) as f:
            reuse = json.load(f).get("stamp") == stamp
    cycles_render, cycles_wall = [], []
    if reuse:
        with open(stamp_path) as f:
            saved = json.load(f)
        cycles_render, cycles_wall = saved["render_s"], saved["wall_s"]
        note("truth: reusing %s" % truth_dir)
    else:
        def cycles(out, spp, seed, ids=None):
            cmd = [blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "cycles_reference.py"), "--",
                   scene, out, "--size", args.size, "--spp", str(spp), "--seed", str(seed),
                   "--threads", str(args.threads)] + (["--ids", ids] if ids else [])
            wall, output = run(cmd, "Cycles (seed %d, %d spp)" % (seed, spp))
            found = re.search(r"([0-9.]+) s render", output)
            if not found or not os.path.isfile(out):
                fail("Cycles wrote no %s: %s" % (out, output[-2000:]))
            return float(found.group(1)), wall

        note("truth: ids (Cycles, 1 spp)")
        cycles(os.path.join(truth_dir, "ids_rgb.exr"), 1, 0, ids_path)
        for seed, path in zip((1, 2), cycles_paths):
            note("truth: Cycles seed %d, %d spp" % (seed, args.cycles_spp))
            r, w = cycles(path, args.cycles_spp, seed)
            cycles_render.append(r)
            cycles_wall.append(w)
            note("  %.1f s render, %.1f s wall" % (r, w))
        with open(stamp_path, "w") as f:
            json.dump({"stamp": stamp, "render_s": cycles_render, "wall_s": cycles_wall}, f, indent=1)

    labels = interior(read_ids(ids_path), args.erode)
    names = {k: re.sub(r"^node \d+ \((.*?)\).*", r"\1", v) for k, v in legend(ids_path).items()}
    c1, c2 = (read_rgb(path) for path in cycles_paths)
    for path, img in zip(cycles_paths, (c1, c2)):
        if img.shape[:2] != labels.shape:
            fail("%s: %dx%d, the id image %dx%d" % (path, img.shape[1], img.shape[0], *labels.shape[::-1]))
    truth = 0.5 * (c1 + c2)
    est_truth = surface_estimates(labels, [(c1, c2)])
    inside = labels > 0
    truth_y = truth @ LUMA
    mean_truth = truth_y[inside].mean()
    cycles_var = np.mean(((c1 - c2) @ LUMA)[inside] ** 2 / 4)  # the noise variance of the mean image, per pixel
    truth_panel = tone(truth)

    # The rows.
    solved = {}  # solve command line -> (wall seconds, first row using it)
    taken, results = set(), []
    for index, (label, steps, seeded) in enumerate(parsed, 1):
        slug = slugify(label, taken)
        note("row %d: %s" % (index, label))
        images, seconds, shared, counted = [], 0.0, [], set()
        for seed in ((1, 2) if seeded else (None,)):
            for words in steps:
                expanded = [w.format(seed=seed, **fields) for w in words]
                cmd = [radview] + expanded
                key = " ".join(expanded)
                if words[0] == "solve":
                    if key not in solved:
                        wall, _ = run(cmd, "row %d (%s): radview %s" % (index, label, key), radview)
                        solved[key] = (wall, index)
                        note("  solve %.1f s" % wall)
                    wall, first = solved[key]
                    if first != index:
                        shared.append(first)
                    if key not in counted:
                        seconds += wall
                        counted.add(key)
                else:
                    stem = os.path.join(runs_dir, slug + ("_seed%d" % seed if seed else ""))
                    cmd += ["--size", args.size, "--out", stem + ".png", "--linear-out", stem + ".exr"]
                    wall, _ = run(cmd, "row %d (%s): radview %s" % (index, label, key), radview)
                    note("  render%s %.1f s" % (" seed %d" % seed if seed else "", wall))
                    last = stem + ".exr"
                    seconds += wall
            if not os.path.isfile(last):
                fail("row %d (%s): radview wrote no %s" % (index, label, last))
            img = read_rgb(last)
            if img.shape[:2] != labels.shape:
                fail("row %d (%s): %s is %dx%d, the truth %dx%d" % (index, label, last, img.shape[1], img.shape[0],
                                                                   *labels.shape[::-1]))
            images.append(img)
        pair = (images[0], images[1]) if seeded else (images[0], images[0])
        image = 0.5 * (pair[0] + pair[1])
        ratios, _, _ = compare(surface_estimates(labels, [pair]), est_truth)
        per_surface = {k: cols["Y"] for k, (n, cols) in ratios.items() if k != "all" and n >= MIN_PIXELS
                       and "Y" in cols}
        row_y = image @ LUMA
        raw_ms = np.mean((row_y - truth_y)[inside] ** 2)
        own_noise = math.sqrt(np.mean(((pair[0] - pair[1]) @ LUMA)[inside] ** 2 / 4)) / mean_truth if seeded else None
        results.append({"label": label, "slug": slug, "seconds": seconds, "seeded": seeded,
                        "shared": sorted(set(shared)), "surfaces": per_surface, "all": ratios["all"][1]["Y"],
                        "rmse_raw": math.sqrt(raw_ms) / mean_truth,
                        "rmse_net": math.sqrt(max(raw_ms - cycles_var, 0.0)) / mean_truth, "own_noise": own_noise})
        write_png(os.path.join(out_dir, slug + ".png"),
                  [truth_panel, tone(image), difference_colours(row_y, truth_y)])

    # The table.
    with open(os.path.join(out_dir, "agreement.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["row", "surface", "ratio", "low", "high"])
        for r in results:
            for k, (ratio, _, half, _) in list(r["surfaces"].items()) + [("all", r["all"])]:
                w.writerow([r["label"], "all interior pixels" if k == "all" else names.get(int(k), str(k)),
                            "%.5f" % ratio, "%.5f" % (ratio - half), "%.5f" % (ratio + half)])
    n_surfaces = len(results[0]["surfaces"]) if results else 0
    lines = [
        "radview against Cycles (%d spp x 2 seeds), %s, %s, %d surfaces with >= %d interior pixels "
        "(%d interior pixels in all); ratio = radview mean / Cycles mean in luminance, 95 %% interval."
        % (args.cycles_spp, os.path.basename(args.scene), args.size, n_surfaces, MIN_PIXELS, int(inside.sum())),
        "",
        "| row | worst surface (ratio) | every surface within (min..max ratio) | relative RMSE | time |",
        "|---|---|---|---|---|",
    ]
    for i, r in enumerate(results, 1):
        s = r["surfaces"]
        if s:
            worst = max(s, key=lambda k: abs(s[k][0] - 1))
            ratio, _, half, _ = s[worst]
            worst_cell = "%s %.3f [%.3f, %.3f]" % (names.get(int(worst), str(worst)), ratio, ratio - half, ratio + half)
            within = "%.3f..%.3f" % (min(v[0] for v in s.values()), max(v[0] for v in s.values()))
        else:
            worst_cell = within = "-"
        time_cell = "%.1f s" % r["seconds"] + (" (2 renders)" if r["seeded"] else "") + \
            ("" if not r["shared"] else " (solve shared with row %s)" % ", ".join(map(str, r["shared"])))
        lines.append("| %d. %s | %s | %s | %.2f %% (raw %.2f %%) | %s |" % (
            i, r["label"], worst_cell, within, 100 * r["rmse_net"], 100 * r["rmse_raw"], time_cell))
    noise_note = "; ".join("row %d's own pixel noise %.2f %% (in its RMSE)" % (i, 100 * r["own_noise"])
                           for i, r in enumerate(results, 1) if r["seeded"])
    lines += [
        "",
        "Intervals: Cycles' standard error from its two seeds; rows with two seeds (%s) their own too; the "
        "other rows count as exact (deterministic interpolants; final gathers are one seed, their noise not "
        "estimated, so their intervals are too narrow)." % (", ".join(str(i) for i, r in enumerate(results, 1)
                                                                    if r["seeded"]) or "none"),
        "Relative RMSE: RMS(Y_radview - Y_Cycles) / mean Y_Cycles over all interior pixels, Cycles' expected "
        "noise (its mean image's pixel noise, %.2f %% of the mean) subtracted in quadrature; raw in brackets%s."
        % (100 * math.sqrt(cycles_var) / mean_truth, ("; " + noise_note) if noise_note else ""),
        "Time: wall seconds of the row's radview commands (solve + render) on %d CPU threads; Cycles %s s "
        "render (%s s wall) per seed%s." % (os.cpu_count() or 1, " / ".join("%.1f" % x for x in cycles_render),
                                           " / ".join("%.1f" % x for x in cycles_wall),
                                           " (reused)" if reuse else ""),
    ]
    with open(os.path.join(out_dir, "agreement.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    note("%s: %s/agreement.md, agreement.csv and %d pictures; %.0f s in all"
         % (PROGRAM, out_dir, len(results), time.time() - total_start))


if __name__ == "__main__":
    main()
