#!/usr/bin/python3
"""radview from Python, worked: a row of pixels, and scipy's Clough-Tocher beside radview's.

On the bundled solved Cornell box:
  1. renders Gouraud, Clough-Tocher and the final gather (C&W eq. 9.9, the reference) as linear
     radiosity arrays and plots the luminance along one row of pixels;
  2. samples the floor along a line through the short block's shadow with radview's
     Clough-Tocher and with scipy's CloughTocher2DInterpolator over the same nodes, and times
     both on random points of the floor.
Writes worked_example.png and prints the figures README's Python page quotes.

    app/python/examples/worked_example.py [--out DIR] [--size 320] [--spp 256] [--points 200000]

Needs the module on the path (PYTHONPATH=build/python), numpy, scipy and matplotlib.
"""
import argparse
import pathlib
import time

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np
from scipy.interpolate import CloughTocher2DInterpolator

import radview

REPO = pathlib.Path(__file__).resolve().parents[3]
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])


def pixel_row(solution, size, spp, row_fraction):
    """Luminance along one row of each method's linear image (NaN where no surface is seen)."""
    images = {
        "Gouraud": solution.render(method="gouraud", size=(size, size), linear=True),
        "Clough-Tocher": solution.render(method="clough-tocher", size=(size, size), linear=True),
        f"final gather, {spp} spp": solution.render(method="final-gather", size=(size, size), linear=True,
                                                     spp=spp),
    }
    row = int(row_fraction * size)
    return row, {name: image[row] @ LUMINANCE for name, image in images.items()}


def floor_nodes(solution):
    """The nodes of the floor's elements (scene polygon 0, the plane y = 0)."""
    corners = solution.elements[solution.element_surfaces == 0]
    return np.unique(corners)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    ap.add_argument("--size", type=int, default=320, help="image side, pixels")
    ap.add_argument("--spp", type=int, default=256, help="the final gather's samples per pixel")
    ap.add_argument("--points", type=int, default=200000, help="random floor points timed")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    solution = radview.load(REPO / "assets" / "cornell_box_solved.glb")
    print(solution)

    # 1. A row of pixels through the red wall, the floor, the short block's front and the green wall.
    row, rows = pixel_row(solution, args.size, args.spp, 0.8)
    reference = list(rows.values())[-1]
    seen = np.all([np.isfinite(values) for values in rows.values()], axis=0)
    for name, values in list(rows.items())[:-1]:
        rms = np.sqrt(np.mean((values[seen] - reference[seen]) ** 2))
        print(f"row {row}: {name}: RMS difference from the gather {rms:.4g} (luminance of B)")

    # 2. The floor, radview's Clough-Tocher against scipy's over the same nodes (x, z).
    nodes = floor_nodes(solution)
    xz = solution.positions[nodes][:, [0, 2]]
    B = solution.B[nodes]
    start = time.perf_counter()
    scipy_ct = CloughTocher2DInterpolator(xz, B)
    scipy_setup = time.perf_counter() - start
    # Along x just in front of the short block, through its shadow, from the red wall to the green.
    x = np.linspace(0.001, 0.55, 1500)
    z = np.full_like(x, 0.04)
    line = np.column_stack([x, np.zeros_like(x), z])
    along = {
        "radview Clough-Tocher": solution.sample(line, method="clough-tocher")["B"] @ LUMINANCE,
        "radview Gouraud": solution.sample(line, method="gouraud")["B"] @ LUMINANCE,
        "scipy CloughTocher2DInterpolator": scipy_ct(line[:, [0, 2]]) @ LUMINANCE,
    }
    # Both interpolate: each returns the nodal values at the nodes. radview's, asked at each floor
    # element's first corner; scipy's at the nodes alone at their position (across a C-1
    # discontinuity edge each side has its own node, with its own value, at the same place).
    floor = np.flatnonzero(solution.element_surfaces == 0)
    corner = solution.elements[floor, 0]
    at_corners = solution.sample(element=floor, barycentric=np.tile([1.0, 0.0, 0.0], (floor.size, 1)),
                                 method="clough-tocher")["B"]
    _, first, count = np.unique(xz, axis=0, return_index=True, return_counts=True)
    alone = first[count == 1]
    print(f"floor: {nodes.size} nodes ({nodes.size - alone.size} sharing a position across a value jump); "
          f"at the nodes radview differs from B by {np.abs(at_corners - solution.B[corner]).max():.2e}, "
          f"scipy by {np.nanmax(np.abs(scipy_ct(xz[alone]) - B[alone])):.2e}")

    # Random points over the floor's bounds; those under the blocks (no floor there) go to the
    # nearest surface, and only those on the floor are compared.
    rng = np.random.default_rng(1)
    q = np.column_stack([rng.uniform(0.001, 0.55, args.points), np.zeros(args.points),
                         rng.uniform(0.001, 0.558, args.points)])
    start = time.perf_counter()
    sampled = solution.sample(q, method="clough-tocher", max_distance=1.0)
    radview_time = time.perf_counter() - start
    on_floor = (solution.element_surfaces[sampled["element"]] == 0) & (sampled["distance"] < 1e-9)
    ours = sampled["B"]
    start = time.perf_counter()
    theirs = scipy_ct(q[:, [0, 2]])
    scipy_time = scipy_setup + time.perf_counter() - start
    both = on_floor & np.all(np.isfinite(theirs), axis=1)  # scipy is NaN outside the nodes' convex hull
    difference = np.abs((ours[both] - theirs[both]) @ LUMINANCE)
    print(f"{args.points} floor points: radview {radview_time:.3f} s, scipy {scipy_time:.3f} s (set-up included); "
          f"{both.sum()} on the floor, |difference| in luminance: median {np.median(difference):.3g}, 99th percentile "
          f"{np.percentile(difference, 99):.3g}, largest {difference.max():.3g}")

    fig, axes = plt.subplot_mosaic([["row", "row"], ["line", "map"]], figsize=(10, 8.5), constrained_layout=True)
    top, line_plot, floor_map = axes["row"], axes["line"], axes["map"]
    for name, values in rows.items():
        top.plot(values, label=name, linewidth=1.0 if "gather" in name else 1.4)
    top.set_title(f"Row {row} of a {args.size}x{args.size} render of cornell_box_solved.glb")
    top.set_xlabel("pixel")
    top.set_ylabel("luminance of B")
    top.legend()
    for name, values in along.items():
        line_plot.plot(x, values, label=name, linewidth=1.2)
    line_plot.set_title("The floor along z = 0.04 m")
    line_plot.set_xlabel("x (m)")
    line_plot.set_ylabel("luminance of B")
    line_plot.legend(fontsize="small")
    shown = np.flatnonzero(both)[:40000]
    dots = floor_map.scatter(q[shown, 0], q[shown, 2], c=np.maximum(np.abs((ours[shown] - theirs[shown]) @ LUMINANCE),
                                                                  1e-6),
                             s=1, cmap="magma", norm=matplotlib.colors.LogNorm(1e-4, 1.0))
    fig.colorbar(dots, ax=floor_map, label="|difference|, luminance of B")
    floor_map.set_title("The floor from above: radview - scipy")
    floor_map.set_xlabel("x (m)")
    floor_map.set_ylabel("z (m)")
    floor_map.set_aspect("equal")
    figure = args.out / "worked_example.png"
    fig.savefig(figure, dpi=100)
    print(f"wrote {figure}")


if __name__ == "__main__":
    main()
