#!/usr/bin/python3
"""Times `radview sample --method clough-tocher` against scipy's CloughTocher2DInterpolator.

Both evaluate the same interpolant on the same planar Delaunay mesh at the same points: the
positions and values are float32 (what a solution file stores) and radview is given scipy's own
estimated vertex gradients, so the two should agree to round-off. radview runs twice per round,
points and samples as text and as .npy arrays (--points FILE.npy --out FILE.npy), the whole
process timed (loading included), and once through the Python module (radview.load, then
Solution.sample on the numpy array, both timed); rounds alternate scipy, text, .npy, module. The
script prints each side's median time, the ratios with their range over rounds, radview's peak
resident set, and the largest difference in B.

Needs Debian's python3 with numpy and scipy (apt-get install python3-scipy python3-numpy);
it is a benchmark, never part of the build or the tests:
    tests/bench/sample_vs_scipy.py [--radview build/radview] [--module build/python]
                                   [--triangles 40000] [--points 1000000] [--rounds 3]
"""
import argparse
import json
import os
import pathlib
import shutil
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy
from scipy.interpolate import CloughTocher2DInterpolator
from scipy.spatial import Delaunay

REPO = pathlib.Path(__file__).resolve().parents[2]

# glTF component types and bufferView targets.
UNSIGNED_BYTE, UNSIGNED_INT, FLOAT = 5121, 5125, 5126
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


def f32(a):
    """Rounds to float32 and back, so scipy sees exactly what the file gives radview."""
    return np.asarray(a, dtype=np.float32).astype(np.float64)


def jittered_grid(triangles, rng):
    """A jittered grid in [0,1]^2 making about `triangles` Delaunay triangles.

    Interior points move by at most a quarter of the spacing; boundary points move only along
    their edge and corners not at all, so the convex hull is exactly the unit square."""
    side = max(2, int(round(np.sqrt(triangles / 2.0))) + 1)  # (side-1)^2 cells, 2 triangles each
    h = 1.0 / (side - 1)
    g = np.linspace(0.0, 1.0, side)
    x, y = (a.ravel() for a in np.meshgrid(g, g, indexing="xy"))
    dx, dy = rng.uniform(-0.25 * h, 0.25 * h, size=(2, x.size))
    on_x_edge = (x == 0.0) | (x == 1.0)
    on_y_edge = (y == 0.0) | (y == 1.0)
    x = x + np.where(on_x_edge, 0.0, dx)
    y = y + np.where(on_y_edge, 0.0, dy)
    return f32(np.stack([x, y], axis=1))


def smooth_values(p):
    """Three positive smooth channels, float32."""
    x, y = p[:, 0], p[:, 1]
    return f32(np.stack([0.5 + 0.4 * np.sin(3 * x) * np.cos(2 * y),
                         0.6 + 0.3 * np.cos(4 * x + y),
                         0.4 + 0.2 * x * x + 0.3 * np.sin(5 * y) * x], axis=1))


def counter_clockwise(points, simplices):
    """The triangles with their vertices counter-clockwise seen from +z."""
    a, b, c = (points[simplices[:, k]] for k in range(3))
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    if np.any(cross == 0.0):
        sys.exit("degenerate triangle in the Delaunay mesh")
    tris = simplices.copy()
    flip = cross < 0.0
    tris[flip, 1], tris[flip, 2] = simplices[flip, 2], simplices[flip, 1]
    return tris.astype(np.uint32)


class Gltf:
    """Accumulates one buffer (the BIN chunk) with its bufferViews and accessors."""

    def __init__(self):
        self.blob = bytearray()
        self.views, self.accessors = [], []

    def add(self, data, component, kind, target=None, bounds=False):
        data = np.ascontiguousarray(data)
        self.blob.extend(b"\0" * (-len(self.blob) % 4))  # every bufferView 4-byte aligned
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": data.nbytes}
        if target is not None:
            view["target"] = target
        self.blob.extend(data.tobytes())
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": component,
               "count": data.shape[0], "type": kind}
        if bounds:
            acc["min"] = [float(v) for v in data.min(axis=0)]
            acc["max"] = [float(v) for v in data.max(axis=0)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def tone_map_scale(b):
    """0.8 / the 99th percentile of luminance over the nodes, as the format defines it."""
    lum = np.sort(b @ np.array([0.2126, 0.7152, 0.0722]))
    y99 = lum[int(np.floor(0.99 * (lum.size - 1)))]
    y99 = y99 if y99 > 0 else lum[-1]
    return 0.8 / y99 if y99 > 0 else 1.0


def write_solution(path, points, tris, values, grad):
    """A radview solution file: one material, one primitive, linear triangles, z = 0."""
    n, m = points.shape[0], tris.shape[0]
    g = Gltf()
    vec3 = lambda a: np.asarray(a, dtype=np.float32)
    pos = vec3(np.column_stack([points, np.zeros(n)]))
    scale = tone_map_scale(values)
    attributes = {
        "POSITION": g.add(pos, FLOAT, "VEC3", ARRAY_BUFFER, bounds=True),
        "NORMAL": g.add(vec3(np.tile([0.0, 0.0, 1.0], (n, 1))), FLOAT, "VEC3", ARRAY_BUFFER),
        "COLOR_0": g.add(vec3(np.clip(values * scale, 0.0, 1.0)), FLOAT, "VEC3", ARRAY_BUFFER),
        "_RADIOSITY": g.add(vec3(values), FLOAT, "VEC3", ARRAY_BUFFER),
    }
    for c, name in enumerate("RGB"):  # surface gradient (d/dx, d/dy, 0) of channel c
        gc = vec3(np.column_stack([grad[:, c, 0], grad[:, c, 1], np.zeros(n)]))
        attributes["_RADIOSITY_GRADIENT_" + name] = g.add(gc, FLOAT, "VEC3", ARRAY_BUFFER)
    corners = tris.ravel()
    u32 = lambda a: np.asarray(a, dtype=np.uint32)
    indices = g.add(corners, UNSIGNED_INT, "SCALAR", ELEMENT_ARRAY_BUFFER)
    ext = {
        "node": g.add(u32(np.arange(n)), UNSIGNED_INT, "SCALAR"),
        "element": g.add(u32(np.arange(m)), UNSIGNED_INT, "SCALAR"),
        "cornerOffsets": g.add(u32(np.arange(m + 1) * 3), UNSIGNED_INT, "SCALAR"),
        "corners": g.add(corners, UNSIGNED_INT, "SCALAR"),
        "order": g.add(np.ones(m, dtype=np.uint8), UNSIGNED_BYTE, "SCALAR"),
        "surface": g.add(u32(np.ones(m)), UNSIGNED_INT, "SCALAR"),
    }
    doc = {
        "asset": {"version": "2.0", "generator": "tests/bench/sample_vs_scipy.py"},
        "extensionsUsed": ["KHR_materials_unlit", "RADVIEW_radiosity_mesh"],
        "extensions": {"RADVIEW_radiosity_mesh": {
            "version": 1, "nodeCount": n, "elementCount": m, "hasGradients": True,
            "toneMapScale": scale}},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "materials": [{"name": "plane",
                       "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0]},
                       "extensions": {"KHR_materials_unlit": {},
                                      "RADVIEW_radiosity_mesh": {"rho": [0.5, 0.5, 0.5],
                                                                 "E": [0.0, 0.0, 0.0]}}}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": indices, "mode": 4,
                                    "material": 0,
                                    "extensions": {"RADVIEW_radiosity_mesh": ext}}]}],
        "accessors": g.accessors, "bufferViews": g.views,
        "buffers": [{"byteLength": len(g.blob)}],
    }
    # Binary glTF: the header, the JSON chunk padded with spaces, the BIN chunk with zeros.
    text = json.dumps(doc).encode("utf-8")
    text += b" " * (-len(text) % 4)
    blob = bytes(g.blob) + b"\0" * (-len(g.blob) % 4)
    chunks = (struct.pack("<II", len(text), 0x4E4F534A) + text +
              struct.pack("<II", len(blob), 0x004E4942) + blob)
    path.write_bytes(struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks)


def run_radview(cmd, stdout):
    """Wall seconds, CPU seconds and peak RSS (KiB) of one radview process."""
    start = time.perf_counter()
    with open(stdout, "wb") as out:
        proc = subprocess.Popen(cmd, stdout=out)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.exit(f"{' '.join(map(str, cmd))}: exit status {proc.returncode}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--radview", type=pathlib.Path, default=REPO / "build" / "radview")
    ap.add_argument("--module", type=pathlib.Path, default=REPO / "build" / "python",
                    help="the folder holding the radview Python module")
    ap.add_argument("--triangles", type=int, default=40000)
    ap.add_argument("--points", type=int, default=1000000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--variant", choices=["affine", "book"], default="affine")
    ap.add_argument("--workdir", type=pathlib.Path, help="default: a temporary directory")
    ap.add_argument("--keep", action="store_true", help="keep the work directory")
    args = ap.parse_args()
    sys.path.insert(0, str(args.module))
    import radview
    rng = np.random.default_rng(args.seed)
    work = args.workdir or pathlib.Path(tempfile.mkdtemp(prefix="sample_vs_scipy."))
    work.mkdir(parents=True, exist_ok=True)
    try:
        points = jittered_grid(args.triangles, rng)
        values = smooth_values(points)

        # scipy: triangulation plus gradient estimation is its set-up; the file gives radview
        # the same triangles and scipy's gradients, so radview's set-up is loading them.
        tri = Delaunay(points)
        # Evaluate with exactly the gradients radview is given, not scipy's float64 ones.
        grad = f32(CloughTocher2DInterpolator(tri, values).grad)

        tris = counter_clockwise(points, tri.simplices)
        solution = work / "plane.glb"
        write_solution(solution, points, tris, values, grad)
        info = subprocess.run([str(args.radview), "info", str(solution)],
                              capture_output=True, text=True)
        if info.returncode != 0:
            sys.exit(f"radview info refused {solution}:\n{info.stderr}{info.stdout}")

        # Query points strictly inside the square; repr gives the exact doubles scipy uses.
        q = rng.uniform(1e-6, 1.0 - 1e-6, size=(args.points, 2))
        pts = work / "pts.txt"
        pts.write_text("".join(f"{x!r} {y!r} 0\n" for x, y in q.tolist()))
        pts_npy = work / "pts.npy"
        np.save(pts_npy, np.concatenate([q, np.zeros((args.points, 1))], axis=1))
        base = [str(args.radview), "sample", str(solution), "--method", "clough-tocher", "--variant", args.variant]
        text_cmd = base + ["--points", str(pts)]
        npy_out = work / "out.npy"
        npy_cmd = base + ["--points", str(pts_npy), "--out", str(npy_out)]
        q3 = np.concatenate([q, np.zeros((args.points, 1))], axis=1)
        # Rounds of scipy (set-up and evaluation), radview with text, with .npy, and the module, in turn.
        times = {"scipy": [], "text": [], "npy": [], "module": []}
        rss = {"text": [], "npy": []}
        for _ in range(args.rounds):
            t0 = time.perf_counter()
            tri = Delaunay(points)
            interp = CloughTocher2DInterpolator(tri, values)
            interp.grad = grad
            b_scipy = interp(q)
            times["scipy"].append(time.perf_counter() - t0)
            for name, cmd in (("text", text_cmd), ("npy", npy_cmd)):
                wall, _, rss_kib = run_radview(cmd, work / f"out_{name}.txt")
                times[name].append(wall)
                rss[name].append(rss_kib)
            t0 = time.perf_counter()
            b_module = radview.load(solution).sample(q3, method="clough-tocher", variant=args.variant)["B"]
            times["module"].append(time.perf_counter() - t0)
        cols = np.loadtxt(work / "out_text.txt", comments="#", usecols=(1, 2, 4, 5, 6, 7), ndmin=2)
        if cols.shape[0] != args.points:
            sys.exit(f"radview printed {cols.shape[0]} points, expected {args.points}")
        table = np.load(npy_out)
        if not np.array_equal(table[:, [1, 2, 4, 5, 6, 7]], cols):
            sys.exit("radview's .npy samples differ from its text")
        if not np.array_equal(b_module, cols[:, 3:6]):
            sys.exit("the module's samples differ from radview sample's")
        d_pos = np.abs(cols[:, 0:2] - q).max()
        d_b = np.abs(cols[:, 3:6] - b_scipy)
        worst = np.unravel_index(np.argmax(d_b), d_b.shape)
    finally:
        if not args.keep and args.workdir is None:
            shutil.rmtree(work, ignore_errors=True)
    median = {k: float(np.median(v)) for k, v in times.items()}
    ratios = {k: np.array(times["scipy"]) / np.array(times[k]) for k in ("text", "npy", "module")}
    print(f"scipy {scipy.__version__}, numpy {np.__version__}; radview {args.radview}"
          f" (--variant {args.variant}); work directory {work}{'' if args.keep else ' (removed)'}")
    print(f"mesh: {points.shape[0]} nodes, {tris.shape[0]} triangles; {args.points} query points; "
          f"{args.rounds} rounds, each scipy, radview text, radview .npy, the module in turn; medians")
    rows = [("scipy (Delaunay, gradients, evaluation) s", f"{median['scipy']:.3f}"),
            ("radview sample, text in and out: wall s", f"{median['text']:.3f}"),
            ("radview sample, .npy in and out: wall s", f"{median['npy']:.3f}"),
            ("radview.load + Solution.sample (module) s", f"{median['module']:.3f}"),
            ("scipy / radview, text [range over rounds]",
             f"{np.median(ratios['text']):.2f} [{ratios['text'].min():.2f}, {ratios['text'].max():.2f}]"),
            ("scipy / radview, .npy [range over rounds]",
             f"{np.median(ratios['npy']):.2f} [{ratios['npy'].min():.2f}, {ratios['npy'].max():.2f}]"),
            ("scipy / module [range over rounds]",
             f"{np.median(ratios['module']):.2f} [{ratios['module'].min():.2f}, {ratios['module'].max():.2f}]"),
            ("radview peak RSS MiB, text / .npy",
             f"{np.median(rss['text']) / 1024:.1f} / {np.median(rss['npy']) / 1024:.1f}"),
            ("max |dB| radview - scipy", f"{d_b.max():.3e}"),
            ("  at point", f"{q[worst[0]].tolist()} channel {'RGB'[worst[1]]}"),
            ("mean |dB|", f"{d_b.mean():.3e}"),
            ("max |d position| (echoed x, y)", f"{d_pos:.3e}"),
            ("max distance to the mesh", f"{cols[:, 2].max():.3e}")]
    width = max(len(r[0]) for r in rows)
    for name, value in rows:
        print(f"  {name:<{width}}  {value}")


if __name__ == "__main__":
    main()
