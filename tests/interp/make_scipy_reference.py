#!/usr/bin/env python3
"""Writes tests/data/scipy_clough_tocher.txt, the fixture of clough_tocher_test.cpp.

scipy's CloughTocher2DInterpolator on a small Delaunay mesh: its triangles (with their
neighbours), the values, the vertex gradients scipy estimates for them, and the interpolant at
sample points, each with the triangle scipy evaluates it on and the barycentric coordinates it
uses. The C++ test builds radview's affine-invariant Clough-Tocher patches from the same
gradients and must agree to round-off.

Needs python3 with numpy and scipy (Debian 12: apt-get install python3-scipy python3-numpy);
only to regenerate the fixture, never to build or test radview. Run from anywhere:
    python3 tests/interp/make_scipy_reference.py
"""
import pathlib

import numpy as np
import scipy
from scipy.interpolate import CloughTocher2DInterpolator
from scipy.spatial import Delaunay

OUT = pathlib.Path(__file__).resolve().parents[1] / "data" / "scipy_clough_tocher.txt"


def main():
    rng = np.random.default_rng(20240527)
    points = rng.uniform(-1.0, 1.0, size=(30, 2))
    # RGB values: three unrelated smooth-ish fields plus noise, so nothing is degenerate.
    x, y = points[:, 0], points[:, 1]
    values = np.stack([np.sin(2 * x) * np.cos(y) + 0.1 * rng.standard_normal(30),
                       x * x - y + 0.1 * rng.standard_normal(30),
                       rng.uniform(0.0, 1.0, 30)], axis=1)

    tri = Delaunay(points)
    interp = CloughTocher2DInterpolator(tri, values)  # estimates interp.grad (Nielson / Renka-Cline)

    # Sample points inside the hull: random ones, the vertices, and points on edges.
    samples = list(rng.uniform(-1.0, 1.0, size=(400, 2)))
    samples += list(points)
    for s in tri.simplices[:10]:
        samples.append(0.5 * (points[s[0]] + points[s[1]]))
    samples = np.array(samples)
    simplex = tri.find_simplex(samples)
    samples, simplex = samples[simplex >= 0][:240], simplex[simplex >= 0][:240]
    # The barycentric coordinates scipy evaluates with (qhull's affine transform).
    T = tri.transform[simplex]
    c01 = np.einsum("nij,nj->ni", T[:, :2, :], samples - T[:, 2, :])
    lam = np.column_stack([c01, 1.0 - c01.sum(axis=1)])
    reference = interp(samples)

    with open(OUT, "w") as out:
        out.write(f"# scipy {scipy.__version__} CloughTocher2DInterpolator; written by "
                  "tests/interp/make_scipy_reference.py\n")
        out.write("# points: x y | triangles: v0 v1 v2 and the neighbour opposite each vertex (-1: none)\n")
        out.write("# gradients: d/dx d/dy of r, g, b | samples: x y triangle lambda0 lambda1 lambda2 r g b\n")
        out.write(f"points {len(points)}\n")
        for p in points:
            out.write(f"{p[0]!r} {p[1]!r}\n")
        out.write(f"triangles {len(tri.simplices)}\n")
        for s, n in zip(tri.simplices, tri.neighbors):
            out.write(" ".join(str(int(i)) for i in (*s, *n)) + "\n")
        out.write(f"values {len(values)}\n")
        for v in values:
            out.write(" ".join(repr(float(c)) for c in v) + "\n")
        out.write(f"gradients {len(interp.grad)}\n")
        for g in interp.grad:
            out.write(" ".join(repr(float(c)) for c in g.reshape(-1)) + "\n")
        out.write(f"samples {len(samples)}\n")
        for p, t, l, r in zip(samples, simplex, lam, reference):
            out.write(" ".join([repr(float(p[0])), repr(float(p[1])), str(int(t))] +
                               [repr(float(c)) for c in (*l, *r)]) + "\n")


if __name__ == "__main__":
    main()
